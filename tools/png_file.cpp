#include "tools/png_file.h"

#include <cstdint>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "cli/error.h"
#include "cli/output_file.h"
#include "cli/text.h"

namespace octopoint {

void writePng(const std::string& path, const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  bool encoded = false;
  try {
    encoded = cv::imencode(".png", image, png);
  } catch (const cv::Exception&) {
    encoded = false;
  }
  if (!encoded) throw cli::Error(cli::displayPath(path) + ": cannot encode the PNG");
  cli::writeFileAtomically(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

}  // namespace octopoint

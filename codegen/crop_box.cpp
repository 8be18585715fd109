// parseCropBox (codegen/prepare.h): apart from prepare.cpp, which links PCL, so that
// octopoint-prepare can read --crop without it (codegen/whole_scan.h).
#include <array>
#include <string_view>

#include "cli/real_numbers.h"
#include "cli/text.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {

CropBox parseCropBox(const std::string& flag, const std::string& text) {
  std::array<double, 6> v{};
  std::size_t at = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t comma = i + 1 < v.size() ? text.find(',', at) : text.size();
    if (comma == std::string::npos ||
        (i + 1 == v.size() && text.find(',', at) != std::string::npos)) {
      throw PrepareError(flag + ": " + cli::inQuotes(text) +
                         " is not six comma-separated numbers X0,Y0,Z0,X1,Y1,Z1");
    }
    v[i] = cli::parseReal(flag, std::string_view(text).substr(at, comma - at), -kMaxCropCoordinate,
                          kMaxCropCoordinate);
    at = comma + 1;
  }
  const CropBox box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!(box.low[axis] < box.high[axis])) {
      throw PrepareError(flag + ": " + cli::inQuotes(text) +
                         " is empty: each lower bound must be below its upper bound");
    }
  }
  return box;
}

}  // namespace octopoint::prepare

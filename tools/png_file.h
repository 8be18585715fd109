#pragma once
// Writing a picture as a PNG file, whole or not at all (cli/output_file.h): octopoint-render's
// frames, contact sheets and camera paths.

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace octopoint {

// The most pixels one PNG of octopoint-render may have, whatever its shape (a frame: 64 MiB of
// framebuffer, 48 MiB of RGB): a single view, a contact sheet's cells and labels together.
inline constexpr std::int64_t kMaxOutputPixels = std::int64_t{4096} * 4096;

// `image` (BGR, as OpenCV keeps it) encoded in memory, then written atomically; cli::Error, one
// line, when it cannot be.
void writePng(const std::string& path, const cv::Mat& image);

}  // namespace octopoint

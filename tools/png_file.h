#pragma once
// Writing a picture as a PNG file, whole or not at all (cli/output_file.h): octopoint-render's
// frames, contact sheets and camera paths.

#include <opencv2/core.hpp>
#include <string>

namespace octopoint {

// `image` (BGR, as OpenCV keeps it) encoded in memory, then written atomically; cli::Error, one
// line, when it cannot be.
void writePng(const std::string& path, const cv::Mat& image);

}  // namespace octopoint

#pragma once
// One measured streaming run for octopoint-stream-measure (docs/streaming.md): octopoint-serve
// started as its own process on a free port, shaped to a link (a rate and a latency per
// connection), and a client streaming one view from it over one connection, drawing the frame and
// scoring it against a reference image every time a table or chunk arrives; then the same link
// used to download the whole file first.

#include <chrono>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "octopoint/camera.h"

namespace octopoint {

struct Link {
  std::string name;                // e.g. "5 kB/s + 500 ms"
  std::uint64_t bytes_per_second;  // per connection
  std::uint32_t latency_ms;        // before each response
};

// A server process: octopoint-serve FOLDER --port 0 --rate R --latency L, stopped by its pid.
class ServeProcess {
 public:
  ServeProcess(const std::string& serve_binary, const std::string& folder, const Link& link);
  ~ServeProcess();  // stops it (SIGTERM) and waits
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;
  int port() const { return port_; }

 private:
  int pid_ = -1;
  int port_ = 0;
};

struct StreamSample {
  double seconds = 0;       // since the first request
  std::uint64_t bytes = 0;  // received so far
  double psnr_db = 0;       // of the frame drawn then, against the reference
  int held_chunks = 0;
};

struct StreamRunResult {
  std::vector<StreamSample> samples;  // the first is the head's picture
  bool complete = false;              // the view's every chunk arrived within the time limit
  double seconds = 0;                 // until complete (or the limit)
  std::uint64_t bytes = 0;
  int deepest_level_depth = 0;  // the finest depth of any chunk fetched
  int wanted_depth = 0;         // the depth the view draws at
  cv::Mat final_frame;          // BGR
};

// Streams `url` for `camera`, scoring each frame (hole-filled when `fill`) against `reference`
// (BGR, the camera's size), until the view is complete or `limit` passes. `keep_frames_at`: byte
// counts after which the frame is also handed to `on_frame` (for figures).
StreamRunResult runStream(
    const std::string& url, const Camera& camera, bool fill, const cv::Mat& reference,
    std::chrono::seconds limit, const std::vector<std::uint64_t>& keep_frames_at,
    const std::function<void(std::uint64_t bytes, const cv::Mat& frame)>& on_frame);

// Downloads the whole file over one connection; seconds until its last byte, or a negative number
// when it did not finish within `limit`.
double downloadWholeFile(const std::string& url, std::uint64_t file_bytes,
                         std::chrono::seconds limit);

}  // namespace octopoint

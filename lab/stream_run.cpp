#include "lab/stream_run.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <thread>

#include "lab/image_quality.h"
#include "octopoint/http.h"
#include "tools/chunked_render.h"

namespace octopoint {
namespace {

using Clock = std::chrono::steady_clock;

constexpr Rgb kBackground{236, 236, 240};
// Frames are scored at most this often (stream time): at 1 MB/s a chunk arrives every few ms.
constexpr auto kMinSampleInterval = std::chrono::milliseconds(25);

}  // namespace

ServeProcess::ServeProcess(const std::string& serve_binary, const std::string& folder,
                           const Link& link) {
  int out[2];
  if (::pipe(out) != 0) throw std::runtime_error("pipe failed");
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    ::close(out[0]);
    ::close(out[1]);
    const std::string rate = std::to_string(link.bytes_per_second);
    const std::string latency = std::to_string(link.latency_ms);
    ::execl(serve_binary.c_str(), serve_binary.c_str(), folder.c_str(), "--port", "0", "--rate",
            rate.c_str(), "--latency", latency.c_str(), static_cast<char*>(nullptr));
    std::perror("exec octopoint-serve");
    ::_exit(127);
  }
  ::close(out[1]);
  std::string line;
  char c = 0;
  while (::read(out[0], &c, 1) == 1 && c != '\n') line += c;
  ::close(out[0]);
  const std::size_t at = line.find("127.0.0.1:");
  if (at == std::string::npos) throw std::runtime_error("octopoint-serve did not start: " + line);
  port_ = std::stoi(line.substr(at + 10));
}

ServeProcess::~ServeProcess() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  int status = 0;
  ::waitpid(pid_, &status, 0);
}

StreamRunResult runStream(const std::string& url_text, const Camera& camera, bool fill,
                          const cv::Mat& reference, std::chrono::seconds limit,
                          const std::vector<std::uint64_t>& keep_frames_at,
                          const std::function<void(std::uint64_t, const cv::Mat&)>& on_frame) {
  const std::optional<net::HttpUrl> url = net::parseHttpUrl(url_text, nullptr);
  if (!url) throw std::runtime_error("bad URL " + url_text);
  net::StreamOptions options;
  options.connections = 1;  // per-connection shaping: one connection is the link
  options.prefetch_invisible = false;
  net::ModelStream stream(*url, options);
  StreamRunResult result;
  std::size_t next_keep = 0;
  Clock::time_point last_sample{};
  const Clock::time_point start = Clock::now();
  const auto score = [&](ProgressiveModel& model, std::uint64_t bytes, bool force) {
    const Clock::time_point now = Clock::now();
    const bool keep = next_keep < keep_frames_at.size() && bytes >= keep_frames_at[next_keep];
    if (!force && !keep && !result.samples.empty() && now - last_sample < kMinSampleInterval)
      return;
    last_sample = now;
    ProgressiveDrawStats stats;
    const cv::Mat frame =
        renderChunkedView(model, camera, defaultVariant(), fill, kBackground, &stats);
    result.samples.push_back({std::chrono::duration<double>(now - start).count(), bytes,
                              tradeoff::psnr(reference, frame),
                              static_cast<int>(model.chunksIn(ChunkState::kHeld))});
    for (; next_keep < keep_frames_at.size() && bytes >= keep_frames_at[next_keep]; ++next_keep) {
      if (on_frame) on_frame(keep_frames_at[next_keep], frame);
    }
    if (model.viewComplete(camera) && !result.complete) {
      result.complete = true;
      result.seconds = std::chrono::duration<double>(now - start).count();
      result.bytes = bytes;
      result.final_frame = frame;
    }
  };
  stream.onAccepted(
      [&](ProgressiveModel& model, std::uint64_t bytes) { score(model, bytes, false); });
  stream.setView(camera);
  stream.start();
  const net::StreamStatus status = stream.waitUntilSettled(limit);
  stream.stop();
  stream.withModel([&](ProgressiveModel* model) {
    if (model == nullptr) return;
    score(*model, status.bytes_received, true);  // the last frame, whatever the interval
    result.wanted_depth = model->wantedDepth(camera).value_or(0);
    for (int level = 1; level < model->levelCount(); ++level) {
      for (std::uint32_t i = 0; i < model->chunkCount(level); ++i) {
        if (model->chunkState(level, i) != ChunkState::kMissing) {
          result.deepest_level_depth =
              std::max(result.deepest_level_depth, model->levelDepth(level));
        }
      }
    }
  });
  if (!result.complete) {
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.bytes = status.bytes_received;
  }
  if (!status.error.empty() && status.failed) throw std::runtime_error(status.error);
  return result;
}

double downloadWholeFile(const std::string& url_text, std::uint64_t file_bytes,
                         std::chrono::seconds limit) {
  const std::optional<net::HttpUrl> url = net::parseHttpUrl(url_text, nullptr);
  net::RangeTimeouts timeouts;
  timeouts.min_bytes_per_second = 1;
  net::RangeClient client(*url, timeouts);
  std::atomic<bool> cancel{false};
  const Clock::time_point start = Clock::now();
  std::thread watchdog([&] {
    while (!cancel && Clock::now() - start < limit)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    cancel = true;
  });
  const net::FetchResult result = client.fetch(
      0, file_bytes, [](std::uint64_t, std::span<const std::uint8_t>) { return true; }, &cancel);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  cancel = true;
  watchdog.join();
  return result.status == net::FetchStatus::kOk ? seconds : -1;
}

}  // namespace octopoint

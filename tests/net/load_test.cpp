// A load test of a running model server (tests/net/load_test.sh starts octopoint-serve): CLIENTS
// clients at once for SECONDS, each streaming the model again and again (octopoint/http.h, one
// connection) for a random view that changes while it streams. Passes when no request failed and
// the server's resident memory (from /proc/PID/status) did not grow after the first
// WARM_UP seconds by more than the stated tolerance.
// usage: net_load_test URL SERVER_PID CLIENTS SECONDS
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "octopoint/http.h"

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr auto kWarmUp = 5s;
// Growth allowed after the warm-up: allocator noise, not a leak (a leak of one request's worth per
// request would be megabytes here).
constexpr long kToleranceKiB = 1024;

long residentKiB(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  }
  return -1;
}

octopoint::Camera randomView(std::mt19937& random) {
  octopoint::Camera camera;
  camera.yaw = octopoint::Angle::fromDegrees(static_cast<int>(random() % 360));
  camera.pitch = octopoint::Angle::fromDegrees(static_cast<int>(random() % 120) - 60);
  camera.zoom = octopoint::Q16::fromRaw(static_cast<std::int32_t>(
      octopoint::Q16::kOneRaw / 2 + random() % (4 * octopoint::Q16::kOneRaw)));
  camera.pan_x_px = static_cast<std::int32_t>(random() % 200) - 100;
  return camera;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: net_load_test URL SERVER_PID CLIENTS SECONDS\n");
    return 2;
  }
  const std::optional<octopoint::net::HttpUrl> url = octopoint::net::parseHttpUrl(argv[1], nullptr);
  const int pid = std::atoi(argv[2]);
  const int clients = std::atoi(argv[3]);
  const auto duration = std::chrono::seconds(std::atoi(argv[4]));
  if (!url || pid <= 0 || clients < 1 || duration < kWarmUp * 2) {
    std::fprintf(stderr, "net_load_test: bad arguments\n");
    return 2;
  }
  std::atomic<bool> done{false};
  std::atomic<long> streams{0}, requests{0}, failed{0}, bytes{0};
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&, c] {
      std::mt19937 random(static_cast<unsigned>(c) * 7919u + 1);
      while (!done) {
        octopoint::net::StreamOptions options;
        options.connections = 1;
        options.timeouts.read_seconds = 10;
        octopoint::net::ModelStream stream(*url, options);
        stream.setView(randomView(random));
        stream.start();
        for (int turn = 0; turn < 3 && !done; ++turn) {  // the user turns twice while it streams
          std::this_thread::sleep_for(std::chrono::milliseconds(50 + random() % 100));
          stream.setView(randomView(random));
        }
        const octopoint::net::StreamStatus status = stream.waitUntilSettled(20s);
        stream.stop();
        ++streams;
        requests += status.requests;
        failed += status.failed_requests + (status.failed ? 1 : 0) + (status.settled ? 0 : 1);
        bytes += static_cast<long>(status.bytes_received);
        if (status.failed_requests > 0 || status.failed) {
          std::fprintf(stderr, "client %d: %s\n", c, status.error.c_str());
        }
      }
    });
  }
  const Clock::time_point start = Clock::now();
  std::this_thread::sleep_for(kWarmUp);
  const long warm_kib = residentKiB(pid);
  long peak_kib = warm_kib;
  while (Clock::now() - start < duration) {
    std::this_thread::sleep_for(1s);
    peak_kib = std::max(peak_kib, residentKiB(pid));
  }
  const long end_kib = residentKiB(pid);
  done = true;
  for (std::thread& thread : threads) thread.join();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf(
      "net_load_test: %d clients, %.1f s: %ld model streams, %ld requests (%.0f/s), %.1f MB, %ld "
      "failed; "
      "server resident memory %ld KiB after %lld s, %ld KiB at the end, %ld KiB at most\n",
      clients, seconds, streams.load(), requests.load(), requests.load() / seconds,
      bytes.load() / 1e6, failed.load(), warm_kib, static_cast<long long>(kWarmUp.count()), end_kib,
      peak_kib);
  if (warm_kib < 0 || end_kib < 0) {
    std::fprintf(stderr, "net_load_test: cannot read the server's memory (pid %d)\n", pid);
    return 1;
  }
  if (failed != 0) {
    std::fprintf(stderr, "net_load_test: %ld requests failed\n", failed.load());
    return 1;
  }
  if (peak_kib > warm_kib + kToleranceKiB) {
    std::fprintf(stderr, "net_load_test: the server grew from %ld to %ld KiB after the warm-up\n",
                 warm_kib, peak_kib);
    return 1;
  }
  return 0;
}

// The manual's third example (octopoint/octopoint.h): a chunked model (octopoint-prepare --chunked)
// streamed over HTTP from any server with Range support (octopoint-serve, nginx), and drawn from
// what has arrived: coarse at first, the file's own picture once the view's chunks are in.
// usage: stream_http http://HOST:PORT/MODEL.oct [OUT.ppm]
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "octopoint/http.h"
#include "octopoint/octopoint.h"

int main(int argc, char** argv) {
  using namespace octopoint;
  if (argc < 2) {
    std::fprintf(stderr, "usage: stream_http URL [OUT.ppm]\n");
    return 2;
  }
  std::string why;
  const std::optional<net::HttpUrl> url = net::parseHttpUrl(argv[1], &why);
  if (!url) {
    std::fprintf(stderr, "stream_http: %s: %s\n", argv[1], why.c_str());
    return 1;
  }

  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  net::StreamOptions options;          // two connections, 256 KiB requests at most
  options.prefetch_invisible = false;  // only what this view needs
  net::ModelStream stream(*url, options);
  stream.setView(camera);  // fetch order: what this view shows, coarse before fine
  stream.start();
  // An app would draw every frame while it waits; this one waits for the view to be complete.
  const net::StreamStatus status = stream.waitUntilSettled(std::chrono::seconds(30));
  if (!status.head_known) {
    std::fprintf(stderr, "stream_http: %s\n", status.error.c_str());
    return 1;
  }

  // Draw what has arrived: a snapshot of the drawable chunks (under the stream's lock, a copy of a
  // byte per chunk), then the frame without the lock, while chunks may still arrive.
  ProgressiveFrame snapshot;
  const ProgressiveModel* model = stream.snapshot(snapshot);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  ProgressiveDrawStats stats;
  if (!model->draw(snapshot, camera, defaultVariant(), frame, &stats)) return 1;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width) * camera.height * 3);
  if (!resolveToRgb(frame, model->baseModel(), Rgb{236, 236, 240}, rgb)) return 1;

  int covered = 0;
  for (const std::uint32_t word : frame.pixels()) covered += word != FrameView::kEmpty;
  std::printf("stream_http: %llu of %llu bytes in %u requests, %s, depth %d drawn, %d pixels\n",
              static_cast<unsigned long long>(status.bytes_received),
              static_cast<unsigned long long>(status.file_bytes), status.requests,
              status.view_complete ? "view complete" : "view incomplete", stats.drawn_depth,
              covered);
  if (argc > 2) {
    std::FILE* out = std::fopen(argv[2], "wb");
    if (out == nullptr) return 1;
    std::fprintf(out, "P6\n%d %d\n255\n", camera.width, camera.height);
    const bool written = std::fwrite(rgb.data(), 1, rgb.size(), out) == rgb.size();
    if (std::fclose(out) != 0 || !written) return 1;
  }
  return status.view_complete && covered > 0 ? 0 : 1;
}

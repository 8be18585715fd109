// libFuzzer harness for the chunked format's reader (octopoint/progressive.h, chunk_records.h,
// chunk_stream.h) and the progressive model that joins and draws what it reads. The first input
// byte chooses how the rest is used:
//  - even: the rest is a file, read front to back as a file or a radio link delivers it;
//  - odd: the rest is spliced into a real chunked model (the default model, depths 5 to 8) at an
//    offset taken from its first 4 bytes, and, when bit 1 is set, every CRC is recomputed
//    afterwards, so that the checks behind the CRCs (head fields, record tables, refinement walks,
//    the joining of chunks) see the damage instead of the CRC refusing it.
// Whatever is read is drawn by two decoders that draw splats (which must agree: fixed_fast and the
// fastest this CPU runs), asked for its fetch priorities and its completeness. ASan and UBSan catch
// a read past a buffer or an overflow.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "tests/support/model_images.h"

namespace {

using namespace octopoint;

void check(bool condition) {
  if (!condition) std::abort();
}

Camera camera(int yaw_degrees, int pitch_degrees, std::int32_t zoom_q16, std::int32_t pan_px,
              std::int32_t width, std::int32_t height) {
  Camera result;
  result.yaw = Angle::fromDegrees(yaw_degrees);
  result.pitch = Angle::fromDegrees(pitch_degrees);
  result.zoom = Q16::fromRaw(zoom_q16);
  result.pan_x_px = pan_px;
  result.width = width;
  result.height = height;
  return result;
}

const std::array kCameras = {camera(0, 0, 1 << 16, 0, 48, 32), camera(30, -20, 4 << 16, 20, 64, 48),
                             camera(200, 60, 1 << 13, -3, 17, 9)};

void readAndDraw(std::span<const std::uint8_t> file) {
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(file, &issue);
  if (!model) return;
  std::array<FetchItem, 16> items{};
  for (const Camera& cam : kCameras) {
    Framebuffer fast(cam.width, cam.height), fastest(cam.width, cam.height);
    fast.clear();
    fastest.clear();
    ProgressiveDrawStats stats;
    check(model->draw(cam, Variant::kFixedFast, fast, &stats));
    check(model->draw(cam, defaultVariant(), fastest));
    check(std::equal(fast.pixels().begin(), fast.pixels().end(), fastest.pixels().begin()));
    const std::size_t count = model->fetchPriority(cam, true, items);
    for (std::size_t i = 0; i < count; ++i) {
      check(items[i].offset + items[i].bytes <= model->head().file_bytes);
      check(model->levelDepth(items[i].level) <= *model->wantedDepth(cam));
    }
    (void)model->viewComplete(cam);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  const std::span<const std::uint8_t> rest(data + 1, size - 1);
  if (mode % 2 == 0) {
    readAndDraw(rest);
    return 0;
  }
  static const std::vector<std::uint8_t> real =
      fuzzing::chunkedImage(*models::defaultModel(), {5, 6, 7, 8}, {512, 1500});
  if (rest.size() < 4) return 0;
  const std::size_t offset =
      (static_cast<std::size_t>(rest[0]) | static_cast<std::size_t>(rest[1]) << 8 |
       static_cast<std::size_t>(rest[2]) << 16 | static_cast<std::size_t>(rest[3]) << 24) %
      real.size();
  std::vector<std::uint8_t> image = real;
  const std::span<const std::uint8_t> splice = rest.subspan(4);
  std::copy_n(splice.begin(), std::min(splice.size(), image.size() - offset),
              image.begin() + static_cast<std::ptrdiff_t>(offset));
  if (mode & 2) fuzzing::resealChunked(image);
  readAndDraw(image);
  return 0;
}

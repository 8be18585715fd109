// The manual's second example (octopoint/octopoint.h): a frame drawn band by band into a small
// static buffer and sent to an RGB565 display, as a microcontroller with a 240x320 SPI panel does
// (ILI9341, ST7789). Nothing here allocates: the buffers are static, the model's arrays are const.
// On a host the "panel" is an array, and the program checks that the bands it received are the
// whole frame drawn at once, pixel for pixel.
// usage: bands_rgb565
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <span>

#include "octopoint/octopoint.h"

namespace {

constexpr std::int32_t kWidth = 240;
constexpr std::int32_t kHeight = 320;
constexpr std::int32_t kBandRows = 16;

// One band of 16 rows: 15 KiB instead of a 300 KiB frame. Two, so that the next band is drawn
// while the previous one is still on its way to the panel (a DMA transfer).
alignas(4) std::uint32_t band_a[kBandRows * kWidth];
alignas(4) std::uint32_t band_b[kBandRows * kWidth];
// The band index: where each subtree of one tree level ends, so that a band walks only the
// subtrees that meet it (4 bytes per node of that level; built once per model).
std::array<octopoint::SubtreeSize, 512> index_storage;
// Stands for the panel's memory: what a flush would send over SPI.
std::uint16_t panel[kWidth * kHeight];

// The display driver's flush: rows [y0, y0 + rows) as RGB565 halfwords in the CPU's byte order.
void flush(void* /*user*/, std::int32_t y0, std::int32_t rows,
           std::span<const std::uint8_t> rgb565) {
  std::memcpy(panel + y0 * kWidth, rgb565.data(), static_cast<std::size_t>(rows) * kWidth * 2);
}

}  // namespace

int main() {
  using namespace octopoint;
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!model) {
    std::printf("bands_rgb565: %s\n", describe(issue.error));
    return 1;
  }
  const LevelView& level = model->finestLevel();

  Camera camera;
  camera.width = kWidth;
  camera.height = kHeight;
  camera.yaw = Angle::fromDegrees(-20);
  FrameSetup setup;
  if (const CameraError error = buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup);
      error != CameraError::kNone) {
    std::printf("bands_rgb565: %s\n", describe(error));
    return 1;
  }

  BandConfig config;  // fixed_fast, no hole filling
  config.band_rows = kBandRows;
  config.background = Rgb{0, 0, 0};
  const Rgb565Palette palette = makeRgb565Palette(*model, config.background);
  const int index_level = deepestIndexLevel(level, index_storage.size());
  const BandIndex index = buildBandIndex(level, index_level, index_storage);
  if (bandBufferWords(kWidth, config) > std::size(band_a)) return 1;  // needs margins: fill is on
  const BandBuffers buffers{band_a, band_b, {}};
  const BandSink sink{nullptr, flush, nullptr};  // flush finishes before it returns: no wait
  if (const BandError error = renderBands(level, setup, config, index, palette, buffers, sink);
      error != BandError::kNone) {
    std::printf("bands_rgb565: %s\n", describe(error));
    return 1;
  }

  // The host's check: the whole frame at once, turned into RGB565 the same way.
  Framebuffer frame(setup);
  frame.clear();
  if (!renderLevel(config.variant, level, setup, frame)) return 1;
  static std::uint16_t whole[kWidth * kHeight];
  packedToRgb565(frame.pixels().data(), frame.pixels().size(), palette,
                 reinterpret_cast<std::uint8_t*>(whole));
  int covered = 0, differ = 0;
  for (std::size_t i = 0; i < std::size(panel); ++i) {
    covered += frame.pixels()[i] != FrameView::kEmpty;
    differ += panel[i] != whole[i];
  }
  std::printf("bands_rgb565: %d bands of %d rows, index level %d, %d pixels covered, %d differ\n",
              (kHeight + kBandRows - 1) / kBandRows, kBandRows, index.level, covered, differ);
  return covered > 0 && differ == 0 ? 0 : 1;
}

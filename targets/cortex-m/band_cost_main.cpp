// Host tool for docs/device.md: one frame of the default model (depth 8, 320x240 or 240x320,
// fixed_fast), drawn either whole (one walk of the tree into a whole-frame buffer, then RGB565) or
// in bands (renderBands, with or without the subtree index), inside drawFrame, so that callgrind
// counts exactly one frame's instructions:
//   valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*drawFrame*'
//            mcu_band_cost ROWS INDEX_LEVEL [portrait]     (ROWS 0: the whole frame in one walk)
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "octopoint/bands.h"
#include "octopoint/models.h"
#include "targets/cortex-m/band_cases.h"

using namespace octopoint;

namespace {

std::uint32_t checksum_sink = 0;

void flush(void*, std::int32_t, std::int32_t, std::span<const std::uint8_t> rgb565) {
  checksum_sink += rgb565[0];  // touch the band, as a driver would
}

[[gnu::noinline]] bool drawFrame(const LevelView& level, const FrameSetup& setup, std::int32_t rows,
                                 const BandIndex& index, const Rgb565Palette& palette,
                                 std::vector<std::uint32_t>& buffer) {
  if (rows == 0) {
    FrameView frame(buffer.data(), setup.width, setup.height);
    frame.clear();
    const bool drawn = renderLevel(Variant::kFixedFast, level, setup, frame);
    packedToRgb565(buffer.data(), buffer.size(), palette,
                   reinterpret_cast<std::uint8_t*>(buffer.data()));
    return drawn;
  }
  BandSink sink;
  sink.flush = flush;
  const BandConfig config{Variant::kFixedFast, rows, false, mcu::kBackground};
  return renderBands(level, setup, config, index, palette, {buffer, {}, {}}, sink) ==
         BandError::kNone;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: mcu_band_cost ROWS INDEX_LEVEL [portrait]\n");
    return 2;
  }
  const std::int32_t rows = std::atoi(argv[1]);
  const int index_level = std::atoi(argv[2]);
  const bool portrait = argc > 3 && std::strcmp(argv[3], "portrait") == 0;
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  const LevelView& level = *model->levelOfDepth(8);
  FrameSetup setup;
  if (buildFrameSetup(mcu::kCameras[portrait ? 2 : 0], 8, kDefaultFractionBits, &setup) !=
      CameraError::kNone)
    return 1;
  std::vector<SubtreeSize> storage(4096);
  const BandIndex index =
      index_level > 0 ? buildBandIndex(level, index_level, storage) : BandIndex{};
  if (index.level != index_level) {
    std::fprintf(stderr, "mcu_band_cost: no index at level %d\n", index_level);
    return 1;
  }
  const Rgb565Palette palette = makeRgb565Palette(*model, mcu::kBackground);
  std::vector<std::uint32_t> buffer(static_cast<std::size_t>(setup.width) *
                                    static_cast<std::size_t>(rows == 0 ? setup.height : rows));
  if (!drawFrame(level, setup, rows, index, palette, buffer)) {
    std::fprintf(stderr, "mcu_band_cost: the frame was refused\n");
    return 1;
  }
  std::printf("drawn: %d leaves\n", static_cast<int>(level.leaves.size()));
  return static_cast<int>(checksum_sink & 0);
}

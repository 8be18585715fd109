// Host tool for docs/device.md: one frame of the default model (depth 8, 320x240 or 240x320,
// fixed_fast), drawn either whole (one walk of the tree into a whole-frame buffer, then RGB565) or
// in bands (renderBands, with or without the subtree index), inside drawFrame, so that callgrind
// counts exactly one frame's instructions:
//   valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*drawFrame*'
//            mcu_band_cost ROWS INDEX_LEVEL [portrait]     (ROWS 0: the whole frame in one walk)
// or a perspective case of band_cases.h drawn in bands (renderPerspectiveBands, detail by distance,
// the upper tree indexes built before), to see where the device's instructions go by function:
//            mcu_band_cost perspective CASE [cull]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "octopoint/bands.h"
#include "octopoint/models.h"
#include "renderer/perspective_bands.h"
#include "renderer/perspective_layers.h"
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

[[gnu::noinline]] bool drawPerspectiveFrame(const mcu::PerspectiveCase& c, const ModelView& model,
                                            std::span<const UpperTreeIndex> indexes,
                                            std::span<PerspectiveWalkTables> tables,
                                            const Rgb565Palette& palette,
                                            std::vector<std::uint32_t>& buffer,
                                            std::span<OcclusionTile> tiles,
                                            PerspectiveDrawStats* stats) {
  PerspectiveView view;
  if (buildPerspectiveView(c.camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
    return false;
  const PerspectiveLayers layers = perspectiveLayers(model, view, 0, indexes, tables);
  if (layers.count == 0) return false;
  const PerspectiveBandFrame frame{layers.layers(), &layers.detail, &view, tiles, 3};
  BandSink sink;
  sink.flush = flush;
  return renderPerspectiveBands(frame, c.band_rows, palette, {buffer, {}, {}}, sink, stats) ==
         BandError::kNone;
}

int perspectiveMain(int index, bool cull) {
  if (index < 0 || index >= mcu::kPerspectiveCaseCount) return 2;
  const mcu::PerspectiveCase& c = mcu::kPerspectiveCases[static_cast<std::size_t>(index)];
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!model) return 1;
  std::vector<UpperTreeIndex> indexes(format::kMaxLevels);
  std::vector<std::vector<UpperTreeNode>> nodes(format::kMaxLevels);
  for (int i = 0; i < model->levelCount() && model->level(i).depth <= kMaxRenderDepth; ++i) {
    const auto l = static_cast<std::size_t>(i);
    nodes[l].resize(upperTreeEntries(model->level(i)));
    indexes[l] = buildUpperTreeIndex(model->level(i), nodes[l]);
  }
  std::vector<PerspectiveWalkTables> tables(format::kMaxLevels);
  const Rgb565Palette palette = makeRgb565Palette(*model, mcu::kBackground);
  std::vector<std::uint32_t> buffer(static_cast<std::size_t>(c.camera.width) *
                                    static_cast<std::size_t>(c.band_rows));
  std::vector<OcclusionTile> tiles(occlusionTileCount(c.camera.width, c.band_rows, 3));
  PerspectiveDrawStats stats;
  if (!drawPerspectiveFrame(c, *model, indexes, tables, palette, buffer,
                            cull ? std::span(tiles) : std::span<OcclusionTile>(), &stats)) {
    std::fprintf(stderr, "mcu_band_cost: the perspective frame was refused\n");
    return 1;
  }
  std::printf("points handed over: %llu, hidden subtrees: %llu\n",
              static_cast<unsigned long long>(stats.leaves),
              static_cast<unsigned long long>(stats.hidden_subtrees));
  return static_cast<int>(checksum_sink & 0);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "perspective") == 0)
    return perspectiveMain(std::atoi(argv[2]), argc > 3 && std::strcmp(argv[3], "cull") == 0);
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

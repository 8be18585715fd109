// Band rendering (octopoint/bands.h): the concatenated bands are the whole frame, bit for
// bit, for every fixed variant at every band height, with and without the subtree index, with and
// without hole filling (which needs the bands' neighbour rows), in landscape and portrait frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

#include "octopoint/bands.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

// RGB565 "colours" that are the palette indices themselves: the bands' RGB565 then shows each
// pixel's palette index exactly, and background (0xFFFF) is no index.
Rgb565Palette identityPalette() {
  Rgb565Palette palette;
  for (std::size_t i = 0; i < palette.colour.size(); ++i)
    palette.colour[i] = static_cast<std::uint16_t>(i);
  palette.background = 0xFFFF;
  return palette;
}

// The whole frame as the desktop draws it (renderLevel, then HoleFiller when filling), in RGB565.
std::vector<std::uint16_t> wholeFrame(Variant variant, const LevelView& level,
                                      const FrameSetup& setup, bool fill,
                                      const Rgb565Palette& palette) {
  Framebuffer frame(setup.width, setup.height);
  EXPECT_TRUE(renderLevel(variant, level, setup, frame));
  if (fill) {
    EXPECT_FALSE(HoleFiller(setup.width).fill(frame, bridgeDepthLimit(setup)).refused);
  }
  std::vector<std::uint16_t> rgb(frame.pixels().size());
  packedToRgb565(frame.pixels().data(), rgb.size(), palette,
                 reinterpret_cast<std::uint8_t*>(rgb.data()));
  return rgb;
}

// Collects the bands a renderBands call flushes, checking that they come top to bottom.
struct Collected {
  std::vector<std::uint16_t> rgb;
  std::int32_t next_y0 = 0;
  std::int32_t width = 0;
  int flushes = 0;
  bool in_order = true;
  std::vector<const std::uint8_t*> waited;  // buffers the renderer waited for, in order
  std::vector<const std::uint8_t*> flushed;

  BandSink sink() {
    BandSink sink;
    sink.user = this;
    sink.flush = [](void* user, std::int32_t y0, std::int32_t rows,
                    std::span<const std::uint8_t> bytes) {
      auto& self = *static_cast<Collected*>(user);
      self.in_order =
          self.in_order && y0 == self.next_y0 &&
          bytes.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(self.width) * 2;
      self.next_y0 = y0 + rows;
      const std::size_t at = self.rgb.size();
      self.rgb.resize(at + bytes.size() / 2);
      std::memcpy(self.rgb.data() + at, bytes.data(), bytes.size());
      self.flushed.push_back(bytes.data());
      ++self.flushes;
    };
    sink.wait = [](void* user, std::span<const std::uint8_t> buffer) {
      static_cast<Collected*>(user)->waited.push_back(buffer.data());
    };
    return sink;
  }
};

class BandRenderer : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
  }

  static FrameSetup setupFor(const Camera& camera, int depth) {
    FrameSetup setup;
    EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
    return setup;
  }

  // Every band height 1..height of one frame: the bands equal `expected`.
  static void expectEveryBandHeight(const LevelView& level, const FrameSetup& setup,
                                    Variant variant, bool fill, const BandIndex& index,
                                    const std::vector<std::uint16_t>& expected, const char* what) {
    const Rgb565Palette palette = identityPalette();
    std::vector<std::uint32_t> history(holeFillHistoryWords(setup.width));
    for (std::int32_t rows = 1; rows <= setup.height; ++rows) {
      const BandConfig config{variant, rows, fill, Rgb{}};
      std::vector<std::uint32_t> buffer(bandBufferWords(setup.width, config));
      Collected collected;
      collected.width = setup.width;
      ASSERT_EQ(renderBands(level, setup, config, index, palette, {buffer, {}, history},
                            collected.sink()),
                BandError::kNone);
      ASSERT_TRUE(collected.in_order) << what;
      ASSERT_EQ(collected.next_y0, setup.height) << what;
      ASSERT_TRUE(collected.rgb == expected)
          << what << ": band rows " << rows << ", fill " << fill << ", index level " << index.level;
    }
  }

  std::optional<ModelView> model_;
};

Camera camera(int width, int height, int yaw, int pitch, int zoom_percent, int pan_x, int pan_y) {
  Camera c;
  c.width = width;
  c.height = height;
  c.yaw = Angle::fromDegrees(yaw);
  c.pitch = Angle::fromDegrees(pitch);
  c.zoom = Q16::fromRaw(zoom_percent * Q16::kOneRaw / 100);
  c.pan_x_px = pan_x;
  c.pan_y_px = pan_y;
  return c;
}

// Small frames, so that every variant can be tried at every band height: straight on, turned and
// zoomed past the frame's edges (straddling subtrees and splats), portrait. The finer level is
// covered below.
TEST_F(BandRenderer, EveryFixedVariantAtEveryBandHeightIsTheWholeFrame) {
  const Rgb565Palette palette = identityPalette();
  // The last two zoom far enough for footprint splats (a voxel covers 2.5 to 4 pixels), which
  // fixed_fast and fixed_simd draw and the paper's variants do not: each is compared with its own
  // whole frame.
  const Camera cameras[] = {camera(64, 48, 0, 0, 100, 0, 0), camera(48, 64, 30, -20, 180, 7, -9),
                            camera(57, 41, -45, 15, 800, -13, 11),
                            camera(64, 48, 20, 10, 1000, 9, -30)};
  {  // depth 7, not 8: every variant at every height of four cameras is many frames
    const LevelView& level = *model_->levelOfDepth(7);
    std::array<SubtreeSize, 600> storage_2{}, storage_4{};
    const BandIndex indexes[] = {BandIndex{}, buildBandIndex(level, 2, storage_2),
                                 buildBandIndex(level, 4, storage_4)};
    ASSERT_EQ(indexes[1].level, 2);  // depth 7: levels 2 to 5 can be indexed
    ASSERT_EQ(indexes[2].level, 4);
    for (const Camera& cam : cameras) {
      const FrameSetup setup = setupFor(cam, level.depth);
      if (cam.zoom.raw() >= 8 * Q16::kOneRaw) {
        EXPECT_TRUE(setup.splat.active());
      }
      for (const VariantInfo& info : allVariants()) {
        if (!supportsBands(info.variant)) continue;
        for (const bool fill : {false, true}) {
          const std::vector<std::uint16_t> expected =
              wholeFrame(info.variant, level, setup, fill, palette);
          for (const BandIndex& index : indexes) {
            expectEveryBandHeight(level, setup, info.variant, fill, index, expected,
                                  info.name.data());
          }
        }
      }
    }
  }
}

// The device's frame sizes at the finest depth, every band height, with the index the device uses.
TEST_F(BandRenderer, FastestVariantsAtEveryBandHeightOfFullSizeFrames) {
  const Rgb565Palette palette = identityPalette();
  const LevelView& level = model_->finestLevel();
  std::array<SubtreeSize, 600> storage{};
  const BandIndex index = buildBandIndex(level, 4, storage);
  ASSERT_EQ(index.level, 4);
  for (const Camera& cam :
       {camera(320, 240, 0, 0, 100, 0, 0), camera(240, 320, 30, -20, 150, 20, 0)}) {
    const FrameSetup setup = setupFor(cam, level.depth);
    for (const Variant variant : {Variant::kFixedFast, Variant::kFixedSimd}) {
      for (const bool fill : {false, true}) {
        // fixed_fast's whole frame, footprint splats included where a voxel covers more than a
        // pixel (the portrait camera's): fixed_simd's bands must be it too.
        const std::vector<std::uint16_t> expected =
            wholeFrame(Variant::kFixedFast, level, setup, fill, palette);
        expectEveryBandHeight(level, setup, variant, fill, index, expected, "full size");
      }
    }
  }
}

// The primitive itself: a band's shifted set-up drawn into a band-sized frame holds exactly the
// whole frame's packed words (depth keys too) of those rows.
TEST_F(BandRenderer, ShiftedSetupDrawsTheWholeFramesPackedWordsOfItsRows) {
  const LevelView& level = model_->finestLevel();
  const FrameSetup setup = setupFor(camera(96, 72, 20, 10, 200, 5, -3), level.depth);
  for (const VariantInfo& info : allVariants()) {
    if (!supportsBands(info.variant)) continue;
    Framebuffer whole(setup.width, setup.height);
    ASSERT_TRUE(renderLevel(info.variant, level, setup, whole));
    for (const std::int32_t rows : {1, 5, 24, 72}) {
      for (std::int32_t y0 = 0; y0 < setup.height; y0 += rows) {
        const std::int32_t band_rows = std::min(rows, setup.height - y0);
        FrameSetup band;
        ASSERT_EQ(bandFrameSetup(setup, y0, band_rows, &band), CameraError::kNone);
        Framebuffer part(setup.width, band_rows);
        ASSERT_TRUE(renderLevel(info.variant, level, band, part));
        const auto first = whole.pixels().begin() + static_cast<std::ptrdiff_t>(y0) * setup.width;
        ASSERT_TRUE(std::ranges::equal(part.pixels(), std::span(first, part.pixels().size())))
            << info.name << " rows " << y0 << ".." << y0 + band_rows;
      }
    }
  }
}

TEST_F(BandRenderer, TwoBuffersAlternateAndEachIsWaitedForBeforeItIsDrawnAgain) {
  const LevelView& level = model_->finestLevel();
  const FrameSetup setup = setupFor(camera(320, 240, 0, 0, 100, 0, 0), level.depth);
  const BandConfig config{Variant::kFixedFast, 24, true, Rgb{}};
  std::vector<std::uint32_t> a(bandBufferWords(320, config)), b(a.size()),
      history(holeFillHistoryWords(320));
  Collected collected;
  collected.width = 320;
  ASSERT_EQ(
      renderBands(level, setup, config, {}, identityPalette(), {a, b, history}, collected.sink()),
      BandError::kNone);
  ASSERT_EQ(collected.flushes, 10);
  const auto* first = reinterpret_cast<const std::uint8_t*>(a.data());
  const auto* second = reinterpret_cast<const std::uint8_t*>(b.data());
  for (int band = 0; band < 10; ++band)
    EXPECT_EQ(collected.flushed[band], band % 2 == 0 ? first : second);
  ASSERT_EQ(collected.waited.size(), 8u);  // bands 2..9 reuse a buffer
  for (int i = 0; i < 8; ++i) EXPECT_EQ(collected.waited[i], i % 2 == 0 ? first : second);
  EXPECT_TRUE(collected.rgb ==
              wholeFrame(Variant::kFixedFast, level, setup, true, identityPalette()));
}

TEST_F(BandRenderer, RefusesWhatItCannotDraw) {
  const LevelView& level = model_->finestLevel();
  const FrameSetup setup = setupFor(camera(64, 48, 0, 0, 100, 0, 0), level.depth);
  const Rgb565Palette palette = identityPalette();
  std::vector<std::uint32_t> buffer(64 * 12), history(holeFillHistoryWords(64));
  Collected collected;
  collected.width = 64;
  const auto bands = [&](BandConfig config, BandBuffers buffers, BandSink sink) {
    return renderBands(level, setup, config, {}, palette, buffers, sink);
  };
  EXPECT_EQ(bands({Variant::kFloatBaseline, 8, false, {}}, {buffer, {}, {}}, collected.sink()),
            BandError::kUnsupportedVariant);
  EXPECT_EQ(bands({Variant::kFixedFast, 0, false, {}}, {buffer, {}, {}}, collected.sink()),
            BandError::kBadBandRows);
  EXPECT_EQ(bands({Variant::kFixedFast, 13, false, {}}, {buffer, {}, {}}, collected.sink()),
            BandError::kBufferTooSmall);
  EXPECT_EQ(
      bands({Variant::kFixedFast, 8, true, {}}, {buffer, {}, {}}, collected.sink()),  // no history
      BandError::kBufferTooSmall);
  EXPECT_EQ(bands({Variant::kFixedFast, 8, true, {}}, {buffer, {}, history}, BandSink{}),
            BandError::kNoSink);
  // A level of another depth than the set-up's, a set-up buildFrameSetup would not make, an index
  // level the level cannot have, an index that does not fit the level: refused before a band is
  // flushed (API misuse, as tests/core/api_misuse_test.cpp), by every variant that draws bands.
  std::vector<SubtreeSize> storage(4096);
  const BandIndex index = buildBandIndex(level, 4, storage);
  ASSERT_EQ(index.level, 4);
  const BandIndex one_short{index.level, index.sizes.first(index.sizes.size() - 1)};
  std::vector<SubtreeSize> lying(index.sizes.begin(), index.sizes.end());
  lying.front().nodes = static_cast<std::uint16_t>(lying.front().nodes + 1);
  for (const VariantInfo& info : allVariants()) {
    if (!supportsBands(info.variant)) continue;
    SCOPED_TRACE(info.name);
    const BandConfig config{info.variant, 8, false, {}};
    const BandBuffers one{buffer, {}, {}};
    ASSERT_EQ(renderBands(level, setup, config, index, palette, one, collected.sink()),
              BandError::kNone);
    collected.flushes = 0;
    const LevelView& coarsest = model_->level(0);
    EXPECT_EQ(renderBands(coarsest, setup, config, {}, palette, one, collected.sink()),
              BandError::kRefused);
    FrameSetup huge_root = setup;
    huge_root.root.x = std::numeric_limits<std::int32_t>::max() - 1;
    EXPECT_EQ(renderBands(level, huge_root, config, {}, palette, one, collected.sink()),
              BandError::kRefused);
    const BandIndex leaf_index{level.depth, {}};  // an index level at the leaves: never allowed
    EXPECT_EQ(renderBands(level, setup, config, leaf_index, palette, one, collected.sink()),
              BandError::kRefused);
    EXPECT_EQ(renderBands(level, setup, config, one_short, palette, one, collected.sink()),
              BandError::kRefused);
    EXPECT_EQ(
        renderBands(level, setup, config, {index.level, lying}, palette, one, collected.sink()),
        BandError::kRefused);
    EXPECT_EQ(collected.flushes, 0);
  }
  FrameSetup band;
  EXPECT_EQ(bandFrameSetup(setup, 40, 9, &band), CameraError::kBadViewport);
  EXPECT_EQ(bandFrameSetup(setup, -1, 2, &band), CameraError::kBadViewport);
  // A frame whose coordinates only just fit: shifting its root up by 10 rows would overflow.
  std::int64_t reach_y = 0;
  for (int l = 0; l < setup.depth; ++l) {
    std::int64_t widest = 0;
    for (const Vec3& d : setup.child_offset[static_cast<std::size_t>(l)])
      widest = std::max<std::int64_t>(widest, std::abs(d.y));
    reach_y += widest;
  }
  FrameSetup tight = setup;
  tight.root.y = static_cast<std::int32_t>(
      -(std::int64_t{INT32_MAX} - 1 - reach_y - (std::int64_t{5} << setup.fraction_bits)));
  EXPECT_EQ(bandFrameSetup(tight, 5, 1, &band), CameraError::kNone);
  EXPECT_EQ(bandFrameSetup(tight, 10, 1, &band), CameraError::kOverflow);
}

TEST_F(BandRenderer, IndexRecordsTheSizeOfEverySubtreeOfItsLevel) {
  const LevelView& level = model_->finestLevel();
  std::array<std::uint32_t, format::kMaxDepth> counts{};
  countNodesPerLevel(level, counts);
  EXPECT_EQ(counts[0], 1u);
  EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), std::uint32_t{0}), level.nodes.size());
  std::vector<SubtreeSize> storage(counts[4]);
  for (const int index_level : {3, 4}) {
    const BandIndex index = buildBandIndex(level, index_level, storage);
    ASSERT_EQ(index.level, index_level);
    ASSERT_EQ(index.sizes.size(), counts[static_cast<std::size_t>(index_level)]);
    // The subtrees' nodes are every node at their levels and below; their leaves are all leaves.
    std::uint32_t nodes = 0, leaves = 0;
    for (const SubtreeSize& size : index.sizes) {
      EXPECT_GT(size.nodes, 0u);
      EXPECT_GT(size.leaves, 0u);
      nodes += size.nodes;
      leaves += size.leaves;
    }
    EXPECT_EQ(nodes, std::accumulate(counts.begin() + index_level, counts.end(), std::uint32_t{0}));
    EXPECT_EQ(leaves, level.leaves.size());
  }
  // Too little room, or a level whose subtrees are too deep for 16-bit sizes: no index.
  EXPECT_EQ(buildBandIndex(level, 3, std::span(storage).first(counts[3] - 1)).level, 0);
  EXPECT_EQ(buildBandIndex(level, 2, storage).level, 0);  // depth 8: 6 levels below level 2
  EXPECT_EQ(buildBandIndex(level, 7, storage).level, 0);  // leaf parents: nothing to index
  EXPECT_EQ(deepestIndexLevel(level, counts[4]), 4);
  EXPECT_EQ(deepestIndexLevel(level, counts[4] - 1), 3);
  EXPECT_EQ(deepestIndexLevel(level, counts[3] - 1), 0);
}

}  // namespace
}  // namespace octopoint

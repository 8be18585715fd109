// Smooth splats band by band (octopoint/bands.h, renderSmoothBands): the concatenated RGB565 bands
// are the whole frame's blend bit for bit, in bands of 1, 7, 8 and 24 rows, with and without the
// subtree index, and the box bands where voxels are at most a pixel; what does not apply is
// refused.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "octopoint/bands.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"

namespace octopoint {
namespace {

const ModelView& smoothBandsModel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

FrameSetup smoothBandsSetup(int width, int height, int zoom_percent, int yaw, int pitch) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.zoom = Q16::fromRaw(zoom_percent * Q16::kOneRaw / 100);
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
  return setup;
}

// The whole frame blended (renderSmooth), in RGB565.
std::vector<std::uint16_t> wholeSmoothFrame(Variant variant, const FrameSetup& setup,
                                            const Rgb565Palette& palette) {
  const ModelView& model = smoothBandsModel();
  Framebuffer frame(setup);
  frame.clear();
  SmoothSplats smooth(setup);
  EXPECT_TRUE(
      renderSmooth(variant, *model.levelOfDepth(8), setup, frame, smooth, paletteOf(model)));
  std::vector<std::uint16_t> rgb(frame.pixels().size());
  EXPECT_TRUE(smooth.resolveToRgb565(frame, palette, reinterpret_cast<std::uint8_t*>(rgb.data())));
  return rgb;
}

// The bands renderSmoothBands flushes, concatenated (they come top to bottom: renderBands' tests).
struct SmoothBandsOut {
  std::vector<std::uint16_t> rgb;

  BandSink sink() {
    BandSink sink;
    sink.user = this;
    sink.flush = [](void* user, std::int32_t, std::int32_t, std::span<const std::uint8_t> bytes) {
      auto& self = *static_cast<SmoothBandsOut*>(user);
      const std::size_t at = self.rgb.size();
      self.rgb.resize(at + bytes.size() / 2);
      std::memcpy(self.rgb.data() + at, bytes.data(), bytes.size());
    };
    return sink;
  }
};

BandError drawSmoothBands(Variant variant, const FrameSetup& setup, std::int32_t rows,
                          const BandIndex& index, const Rgb565Palette& palette,
                          SmoothBandsOut& out) {
  const ModelView& model = smoothBandsModel();
  const BandConfig config{variant, rows, false, Rgb{}};
  std::vector<std::uint32_t> buffer(bandBufferWords(setup.width, config));
  SmoothSplats smooth(setup.width, rows);
  return renderSmoothBands(*model.levelOfDepth(8), setup, config, index, palette, paletteOf(model),
                           {buffer, {}, {}}, smooth, out.sink());
}

std::vector<Variant> smoothBandVariants() {
  std::vector<Variant> variants{Variant::kFixedFast};
  if (simdDecoderAvailable()) variants.push_back(Variant::kFixedSimd);
  return variants;
}

TEST(SmoothBands, BandsAreTheWholeFramesBlend) {
  const ModelView& model = smoothBandsModel();
  const Rgb565Palette palette = makeRgb565Palette(model, Rgb{236, 236, 240});
  const LevelView& level = *model.levelOfDepth(8);
  std::array<SubtreeSize, 4096> storage{};
  const BandIndex indexes[] = {BandIndex{}, buildBandIndex(level, 4, storage)};
  ASSERT_EQ(indexes[1].level, 4);
  for (const FrameSetup& setup :
       {smoothBandsSetup(320, 240, 300, 30, 10), smoothBandsSetup(200, 150, 500, -40, 25)}) {
    ASSERT_GT(voxelEdgeOnScreen(setup), std::uint64_t{2} << setup.fraction_bits);
    for (const Variant variant : smoothBandVariants()) {
      const std::vector<std::uint16_t> whole = wholeSmoothFrame(variant, setup, palette);
      for (const BandIndex& index : indexes) {
        for (const std::int32_t rows : {1, 7, 8, 24}) {
          SmoothBandsOut out;
          ASSERT_EQ(drawSmoothBands(variant, setup, rows, index, palette, out), BandError::kNone);
          EXPECT_TRUE(out.rgb == whole) << "rows " << rows << ", index " << index.level;
        }
      }
    }
  }
}

TEST(SmoothBands, BandsAreTheBoxBandsWhereVoxelsAreAtMostAPixel) {
  const ModelView& model = smoothBandsModel();
  const Rgb565Palette palette = makeRgb565Palette(model, Rgb{236, 236, 240});
  const FrameSetup setup = smoothBandsSetup(320, 240, 100, 30, 10);
  ASSERT_LE(voxelEdgeOnScreen(setup), std::uint64_t{1} << setup.fraction_bits);
  const BandConfig config{Variant::kFixedFast, 24, false, Rgb{}};
  std::vector<std::uint32_t> buffer(bandBufferWords(setup.width, config));
  SmoothBandsOut box;
  ASSERT_EQ(renderBands(*model.levelOfDepth(8), setup, config, BandIndex{}, palette,
                        {buffer, {}, {}}, box.sink()),
            BandError::kNone);
  SmoothBandsOut smooth;
  ASSERT_EQ(drawSmoothBands(Variant::kFixedFast, setup, 24, BandIndex{}, palette, smooth),
            BandError::kNone);
  EXPECT_TRUE(smooth.rgb == box.rgb);
}

TEST(SmoothBands, WhatDoesNotApplyIsRefused) {
  const ModelView& model = smoothBandsModel();
  const Rgb565Palette palette = makeRgb565Palette(model, Rgb{});
  const FrameSetup setup = smoothBandsSetup(64, 48, 1200, 0, 0);  // voxels 2.25 pixels wide
  ASSERT_TRUE(setup.splat.active());
  const LevelView& level = *model.levelOfDepth(8);
  std::vector<std::uint32_t> history(holeFillHistoryWords(setup.width));
  SmoothBandsOut out;
  const auto refuse = [&](Variant variant, bool fill, std::int32_t smooth_width,
                          std::int32_t smooth_rows) {
    const BandConfig config{variant, 8, fill, Rgb{}};
    std::vector<std::uint32_t> buffer(bandBufferWords(setup.width, config));
    SmoothSplats smooth(smooth_width, smooth_rows);
    return renderSmoothBands(level, setup, config, BandIndex{}, palette, paletteOf(model),
                             {buffer, {}, history}, smooth, out.sink());
  };
  EXPECT_EQ(refuse(Variant::kFixedFast, true, 64, 8), BandError::kRefused);    // hole filling
  EXPECT_EQ(refuse(Variant::kFixedDelta, false, 64, 8), BandError::kRefused);  // no splats
  EXPECT_EQ(refuse(Variant::kFixedFast, false, 64, 7), BandError::kRefused);   // a band too high
  EXPECT_EQ(refuse(Variant::kFixedFast, false, 63, 8), BandError::kRefused);   // another width
  EXPECT_EQ(refuse(Variant::kFixedFast, false, 64, 8), BandError::kNone);
  EXPECT_EQ(out.rgb.size(), std::size_t{64 * 48});  // the last call only
}

// In the caller's memory (SmoothSplats::Memory, a device without a heap): the 3-row bands of the
// Cortex-M smooth budget image are the whole frame's blend; memory too small for the band is
// refused like a band too high.
TEST(SmoothBands, CallerMemoryDrawsTheSameBandsAndTooLittleIsRefused) {
  const ModelView& model = smoothBandsModel();
  const Rgb565Palette palette = makeRgb565Palette(model, Rgb{236, 236, 240});
  const FrameSetup setup = smoothBandsSetup(320, 240, 300, 30, 10);
  constexpr std::int32_t kRows = 3;
  const std::vector<std::uint16_t> whole = wholeSmoothFrame(Variant::kFixedFast, setup, palette);
  const BandConfig config{Variant::kFixedFast, kRows, false, Rgb{}};
  std::vector<std::uint32_t> buffer(bandBufferWords(setup.width, config));
  std::vector<SmoothSplats::Sums> sums(static_cast<std::size_t>(setup.width) * kRows);
  std::vector<std::uint16_t> column_weights(static_cast<std::size_t>(setup.width));
  std::vector<std::uint16_t> row_weights(kRows);
  const auto draw = [&](const SmoothSplats::Memory& memory, SmoothBandsOut& out) {
    SmoothSplats smooth(setup.width, kRows, memory);
    return renderSmoothBands(*model.levelOfDepth(8), setup, config, BandIndex{}, palette,
                             paletteOf(model), {buffer, {}, {}}, smooth, out.sink());
  };
  SmoothBandsOut out;
  ASSERT_EQ(draw({sums, column_weights, row_weights}, out), BandError::kNone);
  EXPECT_TRUE(out.rgb == whole);
  const std::span<SmoothSplats::Sums> all_sums(sums);
  const std::span<std::uint16_t> columns(column_weights), rows(row_weights);
  for (const SmoothSplats::Memory& short_memory :
       {SmoothSplats::Memory{all_sums.first(sums.size() - 1), columns, rows},
        SmoothSplats::Memory{all_sums, columns.first(columns.size() - 1), rows},
        SmoothSplats::Memory{all_sums, columns, rows.first(kRows - 1)}}) {
    SmoothBandsOut refused;
    EXPECT_EQ(draw(short_memory, refused), BandError::kRefused);
    EXPECT_TRUE(refused.rgb.empty());
  }
}

}  // namespace
}  // namespace octopoint

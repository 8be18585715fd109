// A perspective frame in bands (renderer/perspective_bands.h, docs/device.md): the concatenated
// bands are the whole frame PerspectiveRenderer draws, pixel for pixel (each pixel's palette
// index, through a palette that maps index i to the RGB565 word i), at every band height of small
// frames and at the device's heights of 320x240, with and without occlusion culling, with one or
// two band buffers; and each band walks only the subtrees that may reach it.

#include "renderer/perspective_bands.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/perspective_layers.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace perspective_bands_test {

const ModelView& bandsTestModel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

// Index i is the RGB565 word i, the background 0xFFFF: the bands' words name the palette index.
Rgb565Palette identityPalette() {
  Rgb565Palette palette;
  for (std::size_t i = 0; i < palette.colour.size(); ++i)
    palette.colour[i] = static_cast<std::uint16_t>(i);
  palette.background = 0xFFFF;
  palette.colour[255] = 0xFFFF;  // an empty pixel's word names index 255
  return palette;
}

// The whole frame as the desktop draws it, one RGB565 word per pixel.
std::vector<std::uint16_t> wholeFrame(const PerspectiveView& view, const Rgb565Palette& palette) {
  PerspectiveRenderer renderer(bandsTestModel());
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  EXPECT_TRUE(renderer.draw(view, {}, frame));
  std::vector<std::uint16_t> rgb(frame.pixels().size());
  packedToRgb565(frame.pixels().data(), frame.pixels().size(), palette,
                 reinterpret_cast<std::uint8_t*>(rgb.data()));
  return rgb;
}

// Collects the flushed bands into a frame.
struct BandCollector {
  std::vector<std::uint16_t> frame;
  std::int32_t width = 0;
  std::int32_t next_y0 = 0;
  bool in_order = true;

  static void flush(void* user, std::int32_t y0, std::int32_t rows,
                    std::span<const std::uint8_t> rgb565) {
    auto& self = *static_cast<BandCollector*>(user);
    self.in_order = self.in_order && y0 == self.next_y0;
    self.next_y0 = y0 + rows;
    const std::size_t at = static_cast<std::size_t>(y0) * static_cast<std::size_t>(self.width);
    std::memcpy(self.frame.data() + at, rgb565.data(),
                static_cast<std::size_t>(rows) * static_cast<std::size_t>(self.width) * 2);
  }
};

// The frame drawn in bands of `rows`, the indexes and tiles as a device keeps them.
std::vector<std::uint16_t> bandedFrame(const PerspectiveView& view, std::int32_t rows, bool cull,
                                       bool two_buffers, const Rgb565Palette& palette,
                                       PerspectiveDrawStats* stats) {
  const ModelView& model = bandsTestModel();
  std::vector<std::vector<UpperTreeNode>> storage(static_cast<std::size_t>(model.levelCount()));
  std::vector<UpperTreeIndex> indexes(storage.size());
  for (std::size_t i = 0; i < storage.size(); ++i) {
    const LevelView& level = model.level(static_cast<int>(i));
    storage[i].resize(upperTreeEntries(level));
    indexes[i] = buildUpperTreeIndex(level, storage[i]);
  }
  std::vector<PerspectiveWalkTables> tables(storage.size());
  const PerspectiveLayers layers = perspectiveLayers(model, view, 0, indexes, tables);
  const std::int32_t width = view.camera.width;
  std::vector<OcclusionTile> tiles(occlusionTileCount(width, rows, 3));
  PerspectiveBandFrame frame{layers.layers(), &layers.detail, &view, {}, 3};
  if (cull) frame.tiles = tiles;
  const std::size_t words = static_cast<std::size_t>(width) * static_cast<std::size_t>(rows);
  std::vector<std::uint32_t> first(words), second(words);
  BandBuffers buffers{first, {}, {}};
  if (two_buffers) buffers.second = second;
  BandCollector collector;
  collector.width = width;
  collector.frame.assign(static_cast<std::size_t>(width) * view.camera.height, 0x1234);
  BandSink sink;
  sink.user = &collector;
  sink.flush = BandCollector::flush;
  EXPECT_EQ(renderPerspectiveBands(frame, rows, palette, buffers, sink, stats), BandError::kNone);
  EXPECT_TRUE(collector.in_order);
  EXPECT_EQ(collector.next_y0, view.camera.height);
  return collector.frame;
}

struct BandView {
  std::string name;
  PerspectiveCamera camera;
};

std::vector<BandView> bandViews(int width, int height) {
  const std::int64_t u = kPerspectiveUnit;
  return {
      {"outside", perspectiveCameraOf({0, 0, -2 * u}, 0, 0, 60, width, height)},
      {"outside, turned", perspectiveCameraOf({u, -u / 2, -u}, -45, -20, 90, width, height)},
      {"at the table's edge",
       perspectiveCameraOf({0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, width, height)},
      {"deep inside", perspectiveCameraOf({u / 16, u / 8, 0}, 170, 30, 120, width, height)},
  };
}

std::int64_t differences(const std::vector<std::uint16_t>& a, const std::vector<std::uint16_t>& b) {
  std::int64_t different = 0;
  for (std::size_t i = 0; i < a.size(); ++i) different += a[i] != b[i];
  return different;
}

TEST(PerspectiveBands, EveryBandHeightOfASmallFrameIsTheWholeFrame) {
  const Rgb565Palette palette = identityPalette();
  for (const BandView& v : bandViews(64, 48)) {
    PerspectiveView view;
    ASSERT_EQ(buildPerspectiveView(v.camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
    const std::vector<std::uint16_t> whole = wholeFrame(view, palette);
    std::int64_t covered = 0;
    for (const std::uint16_t word : whole) covered += word != 0xFFFF;
    EXPECT_GT(covered, 150) << v.name;
    for (std::int32_t rows = 1; rows <= 48; ++rows) {
      for (const bool cull : {false, true}) {
        SCOPED_TRACE(v.name + ", bands of " + std::to_string(rows) + (cull ? ", culled" : ""));
        EXPECT_EQ(
            differences(bandedFrame(view, rows, cull, rows % 2 == 0, palette, nullptr), whole), 0);
      }
    }
  }
}

TEST(PerspectiveBands, DeviceBandsOf320x240AreTheWholeFrame) {
  const Rgb565Palette palette = identityPalette();
  for (const BandView& v : bandViews(320, 240)) {
    PerspectiveView view;
    ASSERT_EQ(buildPerspectiveView(v.camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
    const std::vector<std::uint16_t> whole = wholeFrame(view, palette);
    for (const std::int32_t rows : {1, 7, 8, 24, 240}) {
      SCOPED_TRACE(v.name + ", bands of " + std::to_string(rows));
      EXPECT_EQ(differences(bandedFrame(view, rows, true, true, palette, nullptr), whole), 0);
    }
  }
}

// A band passes over what lies wholly above or below it: 24-row bands hand over about as many
// points as one walk of the whole frame (1.3 times: subtrees that straddle a band are handed to
// both), not ten times as many.
TEST(PerspectiveBands, BandsWalkOnlyWhatMayReachThem) {
  const Rgb565Palette palette = identityPalette();
  const BandView v = bandViews(320, 240)[2];
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(v.camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  PerspectiveDrawStats whole, banded;
  static_cast<void>(bandedFrame(view, 240, true, false, palette, &whole));
  static_cast<void>(bandedFrame(view, 24, true, false, palette, &banded));
  EXPECT_GT(banded.leaves, whole.leaves);  // leaves near a band's edge are handed to both
  EXPECT_LT(banded.leaves * 10, whole.leaves * 14) << banded.leaves << " against " << whole.leaves;
}

// Without culling too: a subtree drawn from one affine map that straddles a band's edge hands the
// band only its nodes that may reach it, and a leaf parent near the eye that straddles it only
// the leaves that may (each band walking and clipping all of them handed over 1.60 times the
// points of one walk with 24-row bands, 2.69 times with 8-row bands; now 1.34 and 1.95).
TEST(PerspectiveBands, StraddlingSubtreesHandOverOnlyTheirRows) {
  const Rgb565Palette palette = identityPalette();
  const BandView v = bandViews(320, 240)[2];
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(v.camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  PerspectiveDrawStats whole, bands_24, bands_8;
  static_cast<void>(bandedFrame(view, 240, false, false, palette, &whole));
  static_cast<void>(bandedFrame(view, 24, false, false, palette, &bands_24));
  static_cast<void>(bandedFrame(view, 8, false, false, palette, &bands_8));
  EXPECT_LT(bands_24.leaves * 100, whole.leaves * 140)
      << bands_24.leaves << " against " << whole.leaves;
  EXPECT_LT(bands_8.leaves * 100, whole.leaves * 210)
      << bands_8.leaves << " against " << whole.leaves;
}

TEST(PerspectiveBands, Refusals) {
  const Rgb565Palette palette = identityPalette();
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(bandViews(64, 48)[0].camera, kDefaultFractionBits, &view),
            PerspectiveError::kNone);
  std::vector<PerspectiveWalkTables> tables(4);
  const PerspectiveLayers layers = perspectiveLayers(bandsTestModel(), view, 8, {}, tables);
  ASSERT_EQ(layers.count, 1u);
  std::vector<std::uint32_t> buffer(64 * 8);
  std::vector<OcclusionTile> tiles(2);
  BandSink sink;
  sink.flush = [](void*, std::int32_t, std::int32_t, std::span<const std::uint8_t>) {};
  const PerspectiveBandFrame frame{layers.layers(), &layers.detail, &view, {}, 3};
  EXPECT_EQ(renderPerspectiveBands(frame, 0, palette, {buffer, {}, {}}, sink),
            BandError::kBadBandRows);
  EXPECT_EQ(renderPerspectiveBands(frame, 9, palette, {buffer, {}, {}}, sink),
            BandError::kBufferTooSmall);
  EXPECT_EQ(renderPerspectiveBands(frame, 8, palette, {buffer, {}, {}}, {}), BandError::kNoSink);
  PerspectiveBandFrame few_tiles = frame;
  few_tiles.tiles = tiles;  // 8 x 1 tiles needed
  EXPECT_EQ(renderPerspectiveBands(few_tiles, 8, palette, {buffer, {}, {}}, sink),
            BandError::kRefused);
  PerspectiveBandFrame no_view = frame;
  no_view.view = nullptr;
  EXPECT_EQ(renderPerspectiveBands(no_view, 8, palette, {buffer, {}, {}}, sink),
            BandError::kRefused);
  EXPECT_EQ(renderPerspectiveBands(frame, 8, palette, {buffer, {}, {}}, sink), BandError::kNone);
}

}  // namespace perspective_bands_test
}  // namespace octopoint

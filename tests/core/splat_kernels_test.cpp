// Each footprint shape has its own code in fixed_simd (a splat's pixels as single-pixel entries
// up to 2 x 2, renderer/avx2_emit.h; an unrolled box kernel up to 2 x 4, one four-pixel vector per
// row for 3 or 4 columns up to 4 rows, one eight-pixel vector per row up to 8 columns, several
// beyond, renderer/splat_batch.h) and is drawn by fixed_fast's rectangle loop. For every shape from
// 1 x 2 to 5 x 5 and some wider and taller ones, with points that cover the whole box and points
// one column or row short, both must draw the splat's definition (tests/support/splat_reference.h)
// bit for bit, also where the frame's edges (its last pixel included) cut the splats.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"
#include "tests/support/splat_reference.h"

namespace octopoint {
namespace {

constexpr int kF = kDefaultFractionBits;

// How the leaves of a footprint cover its box: kExact, every leaf the whole box (padded extent P
// exactly that many pixels); kShort, P half a pixel less, so leaves cover the box or one column
// (row) fewer, depending on where they fall; kJustOver, P 1/16 pixel over one column (row) fewer,
// so few leaves reach the box's last column or row (fixed_simd skips a 2 x 2 box's last row for
// leaf parents none of whose children reach it).
enum class Cover { kShort, kExact, kJustOver };

const char* describe(Cover cover) {
  return cover == Cover::kExact   ? " exact"
         : cover == Cover::kShort ? " with short leaves"
                                  : " just over";
}

// A footprint whose box is `columns` x `rows` pixels, covered as `cover` says.
SplatFootprint footprintOf(int columns, int rows, int depth, Cover cover) {
  const auto extent = [&](int pixels) -> std::int64_t {
    if (pixels == 1) return (std::int64_t{7} << kF) / 10;  // under a pixel: no splat on this axis
    const std::int64_t padded =
        cover == Cover::kExact   ? std::int64_t{pixels} << kF
        : cover == Cover::kShort ? (std::int64_t{pixels} << kF) - (std::int64_t{1} << (kF - 1))
                                 : (std::int64_t{pixels - 1} << kF) + (std::int64_t{1} << (kF - 4));
    return padded - 2 * (depth + 1);  // W, so that W + 2(depth + 1) = P
  };
  return splatFootprint(extent(columns) / 2, extent(rows) / 2, depth, kF);
}

std::vector<std::pair<int, int>> shapes() {
  std::vector<std::pair<int, int>> list;
  for (int rows = 1; rows <= 5; ++rows) {
    for (int columns = 1; columns <= 5; ++columns) {
      if (columns > 1 || rows > 1) list.emplace_back(columns, rows);
    }
  }
  for (const auto& shape : {std::pair{8, 3}, std::pair{6, 7}, std::pair{7, 2}, std::pair{4, 9},
                            std::pair{9, 9}, std::pair{12, 5}, std::pair{2, 17}})
    list.push_back(shape);
  return list;
}

std::vector<VariantInfo> splattingVariantInfos() {
  std::vector<VariantInfo> variants;
  for (const VariantInfo& info : allVariants()) {
    if (drawsSplats(info.variant)) variants.push_back(info);
  }
  return variants;
}

TEST(SplatKernels, EveryFootprintShapeDrawsItsDefinition) {
  ModelIssue issue;
  const auto model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value());
  const LevelView& level = model->finestLevel();
  struct View {
    int width, height, yaw, pan_x, pan_y;
  };
  // Centred; pushed right and down so splats cross the last row and column (and the last pixel);
  // pushed left and up across the first ones.
#if defined(__arm__)  // under qemu: the frame's edges on two sides, splats with short leaves only
  const View views[] = {{96, 72, 55, 40, 30}, {83, 61, -20, -35, -25}};
  const bool exact_too = false;
#else
  const View views[] = {{96, 72, 30, 0, 0}, {96, 72, 55, 40, 30}, {83, 61, -20, -35, -25}};
  const bool exact_too = true;
#endif
  int shapes_checked = 0;
  for (const auto& [columns, rows] : shapes()) {
    for (const Cover cover : {Cover::kShort, Cover::kExact, Cover::kJustOver}) {
      if (cover != Cover::kShort && !exact_too) continue;
      const SplatFootprint footprint = footprintOf(columns, rows, level.depth, cover);
      ASSERT_EQ(footprint.columns, columns);
      ASSERT_EQ(footprint.rows, rows);
      for (const View view : views) {
        Camera camera;
        camera.width = view.width;
        camera.height = view.height;
        camera.yaw = Angle::fromDegrees(view.yaw);
        camera.pitch = Angle::fromDegrees(20);
        camera.pan_x_px = view.pan_x;
        camera.pan_y_px = view.pan_y;
        FrameSetup setup;
        ASSERT_EQ(buildFrameSetup(camera, level.depth, kF, &setup), CameraError::kNone);
        setup.splat = footprint;  // the leaves' spacing does not matter to the definition
        Framebuffer reference(view.width, view.height), candidate(view.width, view.height);
        reference.clear();
        testing_support::ReferenceSplat::draw(level, setup, reference);
        for (const VariantInfo& info : splattingVariantInfos()) {
          candidate.clear();
          ASSERT_TRUE(renderLevel(info.variant, level, setup, candidate));
          ASSERT_TRUE(std::ranges::equal(candidate.pixels(), reference.pixels()))
              << info.name << " footprint " << columns << "x" << rows << describe(cover) << " view "
              << view.width << "x" << view.height << " yaw " << view.yaw << " pan " << view.pan_x
              << "," << view.pan_y;
        }
      }
      ++shapes_checked;
    }
  }
  EXPECT_EQ(shapes_checked, (exact_too ? 3 : 1) * static_cast<int>(shapes().size()));
}

}  // namespace
}  // namespace octopoint

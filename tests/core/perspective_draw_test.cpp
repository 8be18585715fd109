// drawPerspective's frames: the same pixels as the splat rule of docs/perspective.md applied to
// every leaf the walk hands over (the plot's shortcuts for on-screen subtrees and small splats
// change nothing), subtrees widened enough for their nearest voxels, and frames whose checksums
// are fixed, so that x86-64 and armel (scripts/test-armel) draw the same ones.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/crc32.h"
#include "renderer/perspective_walk.h"
#include "tests/support/perspective_reference.h"

namespace octopoint {
namespace {

constexpr int kDrawFractionBits = kDefaultFractionBits;
constexpr std::int64_t kDrawQuarterPixel = std::int64_t{1} << (kDrawFractionBits - 2);

const LevelView& drawnLevel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model.finestLevel();
}

// The rule, plainly: a leaf at p with half extent h (its own plus the padding) covers the pixels
// whose centres lie within [p - h, p + h] on both axes, or the pixel holding p where no centre
// does; clipped to the frame; the nearer word wins.
void plotByTheRule(const LevelView& level, const PerspectiveLeaf& leaf, std::int64_t padding,
                   Framebuffer& frame) {
  const std::int64_t one = std::int64_t{1} << kDrawFractionBits;
  const auto span = [&](std::int64_t p, std::int64_t half) {
    std::vector<std::int64_t> pixels;
    for (std::int64_t i = ((p - half) >> kDrawFractionBits) - 1;
         i <= ((p + half) >> kDrawFractionBits) + 1; ++i) {
      const std::int64_t centre = i * one + one / 2;
      if (centre >= p - half && centre <= p + half) pixels.push_back(i);
    }
    if (pixels.empty()) pixels.push_back(p >> kDrawFractionBits);
    return pixels;
  };
  const std::uint32_t key = static_cast<std::uint32_t>(
      std::min<std::int64_t>(leaf.z >> kPerspectiveDepthShift, FrameView::kMaxDepthKey));
  const std::uint32_t word = FrameView::pack(key, level.leaves[leaf.index]);
  for (std::int64_t y : span(leaf.y, leaf.half_y + padding)) {
    for (std::int64_t x : span(leaf.x, leaf.half_x + padding)) {
      if (x < 0 || y < 0 || x >= frame.width() || y >= frame.height()) continue;
      std::uint32_t& kept = frame.pixelData()[y * frame.width() + x];
      kept = std::min(kept, word);
    }
  }
}

struct DrawCase {
  std::string name;
  PerspectiveCamera camera;
};

std::vector<DrawCase> drawCases() {
  const std::int64_t u = kPerspectiveUnit;
  std::vector<DrawCase> all;
  const auto add = [&](std::string name, ModelPoint eye, int yaw, int pitch, int fov, int width,
                       int height) {
    all.push_back({std::move(name), perspectiveCameraOf(eye, yaw, pitch, fov, width, height)});
  };
  // Whole model on screen, half of it off the left edge, eye at the face, eye inside: on-screen,
  // straddling and off-screen subtrees; small splats far away and large ones near the eye.
  add("outside, 60 degrees", {0, 0, -2 * u}, 0, 0, 60, 320, 240);
  add("outside, 10 degrees", {0, 0, -6 * u}, 5, 3, 10, 320, 240);
  add("off the left edge", {0, 0, -u}, 25, 0, 60, 200, 150);
  add("at the cube's face", {0, 0, -u / 2}, 10, -5, 90, 320, 240);
  add("deep inside", {u / 16, u / 8, 0}, 170, 30, 120, 320, 240);
  add("large frame", {u / 4, -u / 4, -3 * u / 2}, -10, -10, 30, 1280, 960);
  return all;
}

TEST(PerspectiveDraw, FrameIsTheSplatRuleAppliedToEveryLeafHandedOver) {
  const LevelView& level = drawnLevel();
  for (const DrawCase& c : drawCases()) {
    SCOPED_TRACE(c.name);
    PerspectiveView view;
    ASSERT_EQ(buildPerspectiveView(c.camera, kDrawFractionBits, &view), PerspectiveError::kNone);
    const PerspectiveWalkTables tables =
        perspectiveWalkTables(view, level.depth, kDrawQuarterPixel);
    Framebuffer drawn(c.camera.width, c.camera.height), expected(c.camera.width, c.camera.height);
    drawn.clear();
    expected.clear();
    ASSERT_TRUE(drawPerspective(level, view, tables, drawn));
    const std::int64_t padding = tables.max_error + tables.depth + 1;
    std::size_t leaves = 0;
    auto reference = [&](const PerspectiveLeaf& leaf) {
      plotByTheRule(level, leaf, padding, expected);
      ++leaves;
    };
    PerspectiveWalk<decltype(reference)> walk(level, view, tables, reference);
    ASSERT_TRUE(walk.run());
    EXPECT_GT(leaves, 100u);
    std::size_t different = 0, covered = 0;
    for (std::int32_t y = 0; y < c.camera.height; ++y) {
      for (std::int32_t x = 0; x < c.camera.width; ++x) {
        different += drawn.pixelAt(x, y) != expected.pixelAt(x, y);
        covered += expected.covered(x, y);
      }
    }
    EXPECT_EQ(different, 0u);
    EXPECT_GT(covered, 500u);
  }
}

// Calls check(fov, view, tables of depth 12, max_error) for a 640x480 view at 10 to 120 degrees
// and error budgets of 1/16 to 1 pixel.
template <typename Check>
void forEachTablesCase(const Check& check) {
  for (int fov : {10, 30, 60, 90, 120}) {
    for (const std::int64_t max_error :
         {kDrawQuarterPixel / 4, kDrawQuarterPixel, 4 * kDrawQuarterPixel}) {
      PerspectiveCamera camera;
      camera.fov = Angle::fromDegrees(fov);
      camera.width = 640;
      camera.height = 480;
      PerspectiveView view;
      ASSERT_EQ(buildPerspectiveView(camera, kDrawFractionBits, &view), PerspectiveError::kNone);
      check(fov, view, perspectiveWalkTables(view, 12, max_error), max_error);
    }
  }
}

// A subtree drawn from the affine map at its centre has voxels nearer the eye, larger on screen
// by up to z / (z - reach): the per-level growth bounds that wherever a subtree may be drawn so.
TEST(PerspectiveDraw, GrowthBoundsTheNearestVoxelOfEverySubtreeDrawnFromItsMap) {
  int checked = 0;
  forEachTablesCase([&](int fov, const PerspectiveView& view, const PerspectiveWalkTables& tables,
                        std::int64_t /*max_error*/) {
    for (std::size_t bucket = 0; bucket < PerspectiveWalkTables::kAffineBuckets; ++bucket) {
      for (int level = 0; level <= 12; ++level) {
        const auto l = static_cast<std::size_t>(level);
        const std::int64_t nearest = tables.affine_depth[bucket][l], reach = tables.reach[l];
        if (nearest > (std::int64_t{1} << 40)) continue;  // no depth the eye sees
        for (const std::int64_t z :
             {nearest, nearest + 1, nearest + nearest / 3, 2 * nearest, 10 * nearest}) {
          if (z - reach < view.camera.near) continue;  // the walk projects such a node anew
          SCOPED_TRACE(std::to_string(fov) + " degrees, level " + std::to_string(level) +
                       ", bucket " + std::to_string(bucket));
          // growth >= z / (z - reach), in integers.
          EXPECT_GE(tables.growth_q16[bucket][l] * (z - reach), z << 16);
          ++checked;
        }
      }
    }
  });
  EXPECT_GT(checked, 1500);
}

// A node nearer the view's axis qualifies for its affine map nearer the eye (bucket b >= 1 of
// affine_depth: max(|c.x|, |c.y|) <= c.z / 2^(b - 1)): wherever a bucket lets a node be drawn so,
// at its threshold depth and beyond, as far off the axis as the bucket and the frustum allow, the
// error bound of its box (f (r^2 m + (|d|^2 / 2) z) / (z^2 (z - r)), |d| <= sqrt(3) (h + depth)
// the farthest a leaf's centre lies from its node's, in double precision) is within max_error. And
// the buckets nearer the axis do let nodes qualify nearer the eye than the frustum's worst case
// (bucket 0) does.
TEST(PerspectiveDraw, EveryAffineBucketKeepsItsNodesWithinTheErrorBudget) {
  int checked = 0, nearer = 0;
  forEachTablesCase([&](int fov, const PerspectiveView& view, const PerspectiveWalkTables& tables,
                        std::int64_t max_error) {
    const double f = static_cast<double>(view.focal_q16) / 65536.0;
    const double budget = static_cast<double>(max_error) / (1 << kDrawFractionBits);
    const double slope = static_cast<double>(std::max(tables.slope_x_q30, tables.slope_y_q30)) /
                         static_cast<double>(std::int64_t{1} << 30);
    for (std::size_t bucket = 1; bucket < PerspectiveWalkTables::kAffineBuckets; ++bucket) {
      for (int level = 0; level <= 12; ++level) {
        const auto l = static_cast<std::size_t>(level);
        const std::int64_t nearest = tables.affine_depth[bucket][l];
        if (nearest > (std::int64_t{1} << 34)) continue;  // beyond what the camera holds
        nearer += nearest < tables.affine_depth[0][l];
        const auto r = static_cast<double>(tables.reach[l]);
        // Half the node's edge plus a unit of rounding per level, on each axis.
        const double h = static_cast<double>(std::int64_t{1} << (23 - level)) + 12;
        const double d_squared = 3 * h * h;
        for (const std::int64_t depth : {nearest, nearest + nearest / 3, 4 * nearest}) {
          const auto z = static_cast<double>(depth);
          if (z - r < static_cast<double>(view.camera.near)) continue;  // projected anew
          // Off the axis as far as the bucket admits, and no farther than a box that meets
          // the frustum may lie.
          const double m =
              std::min(static_cast<double>(depth >> (bucket - 1)), slope * (z + r) + r);
          SCOPED_TRACE(std::to_string(fov) + " degrees, level " + std::to_string(level) +
                       ", bucket " + std::to_string(bucket));
          EXPECT_LE(f * (r * r * m + d_squared / 2 * z) / (z * z * (z - r)), budget);
          ++checked;
        }
      }
    }
  });
  EXPECT_GT(checked, 500);
  EXPECT_GT(nearer, 300);
}

// The walk's affine thresholds take a leaf's centre within sqrt(9/8) reach of its node's: 3 (h +
// depth)^2 <= (9/8) reach^2 at every level of every depth (h half the node's edge).
TEST(PerspectiveDraw, ALeafLiesWithinTheReachTheAffineThresholdsAssume) {
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(PerspectiveCamera{}, kDrawFractionBits, &view),
            PerspectiveError::kNone);
  for (int depth = 1; depth <= kMaxRenderDepth; ++depth) {
    const PerspectiveWalkTables tables = perspectiveWalkTables(view, depth, kDrawQuarterPixel);
    for (int level = 0; level <= depth; ++level) {
      const std::int64_t h = std::int64_t{1} << (kPerspectiveUnitBits - 1 - level);
      const std::int64_t reach = tables.reach[static_cast<std::size_t>(level)];
      EXPECT_LE(24 * (h + depth) * (h + depth), 9 * reach * reach) << depth << ", " << level;
    }
  }
}

// The frames' checksums (CRC-32 of the pixel words, little-endian): the same on every build, so
// that scripts/test-armel checks an ARMv5 draws the same frames. A change of the walk or the
// splat rule that moves a pixel changes them (then check the new frames and update them).
TEST(PerspectiveDraw, FramesHaveTheirFixedChecksums) {
  const LevelView& level = drawnLevel();
  const std::uint32_t expected[] = {0x651ff628, 0x216801a9, 0x4aa94779,
                                    0x352db9c7, 0x3109f9af, 0x0abf0648};
  const std::vector<DrawCase> all = drawCases();
  ASSERT_EQ(all.size(), std::size(expected));
  for (std::size_t i = 0; i < all.size(); ++i) {
    const DrawCase& c = all[i];
    PerspectiveView view;
    ASSERT_EQ(buildPerspectiveView(c.camera, kDrawFractionBits, &view), PerspectiveError::kNone);
    Framebuffer frame(c.camera.width, c.camera.height);
    frame.clear();
    ASSERT_TRUE(drawPerspective(
        level, view, perspectiveWalkTables(view, level.depth, kDrawQuarterPixel), frame));
    std::vector<std::uint8_t> bytes;
    for (std::int32_t y = 0; y < c.camera.height; ++y) {
      for (std::int32_t x = 0; x < c.camera.width; ++x) {
        const std::uint32_t word = frame.pixelAt(x, y);
        for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<std::uint8_t>(word >> (8 * b)));
      }
    }
    EXPECT_EQ(crc32(std::span<const std::uint8_t>(bytes)), expected[i])
        << c.name << std::hex << ": 0x" << crc32(std::span<const std::uint8_t>(bytes));
  }
}

}  // namespace
}  // namespace octopoint

// Numerical stability of the integer decoder at the extremes: every decoded leaf stays
// within the proven bound of exact rational arithmetic, for every degree, for the raw angles next
// to each quarter turn, at the smallest and largest zoom, at depth 1 and the deepest depth, on 1x1
// and 4096x4096 framebuffers, and for a model touching every face of its cube. The asan preset runs
// this under UBSan, so a signed overflow anywhere on these paths fails it too.
//
// The bound: each level adds one displacement vector rounded to nearest once (octopoint/camera.h),
// so a leaf at depth d is off the exact sum by at most d/2 units in the last place per axis. The
// exact sum uses the same rotation matrix (its own error against true trigonometry is bounded in
// tests/core/rotation_test.cpp), so this checks the decoder's accumulation, not the sine table.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "renderer/decode_baseline.h"
#include "tests/support/exact_int128.h"

namespace octopoint {
namespace {

using octopoint::test::Int128;

// Walks a level's stream as the decoder does, but sums the exact (unrounded) child vectors, scaled
// by 2^(48 + depth - 1 - F) so that every term is an integer (see renderer/camera.cpp).
class ExactWalk {
 public:
  ExactWalk(const LevelView& level, const Camera& camera, int fraction_bits)
      : level_(level), depth_(level.depth), fraction_bits_(fraction_bits) {
    rotation_ = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
    edge_q16_ = static_cast<Int128>(camera.zoom.raw()) * std::min(camera.width, camera.height);
    const int scale_bits = 48 + depth_ - 1 - fraction_bits;
    root_[0] = (((static_cast<Int128>(camera.width) << fraction_bits) / 2) +
                (static_cast<Int128>(camera.pan_x_px) << fraction_bits))
               << scale_bits;
    root_[1] = (((static_cast<Int128>(camera.height) << fraction_bits) / 2) +
                (static_cast<Int128>(camera.pan_y_px) << fraction_bits))
               << scale_bits;
    root_[2] = 0;
  }

  // Exact leaf positions (scaled), in stream order.
  std::vector<std::array<Int128, 3>> leaves() {
    node_ = level_.nodes.data();
    result_.clear();
    visit(0, root_);
    return result_;
  }

  int scaleBits() const { return 48 + depth_ - 1 - fraction_bits_; }

 private:
  void visit(int level, std::array<Int128, 3> centre) {
    if (level == depth_) {
      result_.push_back(centre);
      return;
    }
    const std::uint8_t mask = *node_++;
    for (int k = 0; k < 8; ++k) {
      if (!(mask & (1 << k))) continue;
      const int sign[3] = {k & 4 ? 1 : -1, k & 2 ? 1 : -1, k & 1 ? 1 : -1};
      std::array<Int128, 3> child = centre;
      for (std::size_t axis = 0; axis < 3; ++axis) {
        Int128 row_dot_sign = 0;
        for (std::size_t j = 0; j < 3; ++j)
          row_dot_sign += sign[j] * static_cast<Int128>(rotation_.m_q30[axis][j]);
        child[axis] += row_dot_sign * edge_q16_ * (static_cast<Int128>(1) << (depth_ - 1 - level));
      }
      visit(level + 1, child);
    }
  }

  const LevelView& level_;
  int depth_;
  int fraction_bits_;
  Rotation rotation_{};
  Int128 edge_q16_ = 0;
  std::array<Int128, 3> root_{};
  const std::uint8_t* node_ = nullptr;
  std::vector<std::array<Int128, 3>> result_;
};

// Checks every leaf of `level` seen through `camera` against the exact sum; returns the number of
// leaves checked.
std::size_t expectWithinProvenBound(const LevelView& level, const Camera& camera,
                                    int fraction_bits) {
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, level.depth, fraction_bits, &setup), CameraError::kNone);
  std::vector<Vec3> decoded;
  auto sink = [&](std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    decoded.push_back({x, y, z});
  };
  BaselineWalk<decltype(sink)>(level, setup, sink).run();

  ExactWalk exact_walk(level, camera, fraction_bits);
  const auto exact = exact_walk.leaves();
  EXPECT_EQ(decoded.size(), exact.size());
  const int s = exact_walk.scaleBits();
  const Int128 bound = static_cast<Int128>(level.depth) << (s - 1);  // depth/2 ulp, scaled by 2^s
  for (std::size_t i = 0; i < std::min(decoded.size(), exact.size()); ++i) {
    const std::int32_t got[3] = {decoded[i].x, decoded[i].y, decoded[i].z};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const Int128 error = (static_cast<Int128>(got[axis]) << s) - exact[i][axis];
      if (error > bound || -error > bound) {
        ADD_FAILURE() << "leaf " << i << " axis " << axis << " off by more than " << level.depth
                      << "/2 ulp; yaw " << camera.yaw.turns16() << " pitch "
                      << camera.pitch.turns16();
        return i;
      }
    }
  }
  return decoded.size();
}

const LevelView& defaultLevel(int depth) {
  static const std::optional<ModelView> model = [] {
    ModelIssue issue;
    return ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return *model->levelOfDepth(depth);
}

TEST(RenderStability, EveryDegreeOfYawPitchAndRollStaysWithinTheProvenBound) {
  for (int degrees = -180; degrees < 360; ++degrees) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(degrees);
    camera.pitch = Angle::fromDegrees(degrees / 3);
    camera.roll = Angle::fromDegrees(-degrees / 2);
    expectWithinProvenBound(defaultLevel(7), camera, kDefaultFractionBits);
  }
}

TEST(RenderStability, TheSixteenRawAnglesNearestEachQuarterTurnStayWithinTheBound) {
  for (int quarter = 0; quarter < 4; ++quarter) {
    for (int step = -8; step < 8; ++step) {
      Camera camera;
      camera.yaw = Angle::fromTurns16(quarter * 16384 + step);
      camera.pitch = Angle::fromTurns16(quarter * 16384 - step);
      expectWithinProvenBound(defaultLevel(8), camera, kDefaultFractionBits);
    }
  }
}

TEST(RenderStability, FractionBitsAtBothEndsStayWithinTheBound) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(37);
  // The most fraction bits a 320x240 frame allows: one more and the screen coordinates would not
  // fit 32 bits, which the camera must refuse.
  int most = kMaxFractionBits;
  FrameSetup setup;
  while (buildFrameSetup(camera, 8, most, &setup) == CameraError::kOverflow) --most;
  ASSERT_GE(most, 20);
  if (most < kMaxFractionBits) {
    EXPECT_EQ(buildFrameSetup(camera, 8, most + 1, &setup), CameraError::kOverflow);
  }
  for (int bits : {kMinFractionBits, 8, 12, 15, most})
    expectWithinProvenBound(defaultLevel(8), camera, bits);
}

// The largest zoom the camera accepts for this view, by bisection over the raw Q16.16 value.
std::int32_t largestAcceptedZoomRaw(Camera camera, int depth) {
  std::int64_t low = 1, high = std::numeric_limits<std::int32_t>::max();
  FrameSetup setup;
  while (low < high) {
    const std::int64_t middle = (low + high + 1) / 2;
    camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(middle));
    if (buildFrameSetup(camera, depth, kDefaultFractionBits, &setup) == CameraError::kNone)
      low = middle;
    else
      high = middle - 1;
  }
  return static_cast<std::int32_t>(low);
}

TEST(RenderStability,
     TheSmallestAndLargestAcceptedZoomDrawWithinTheBoundAndOneStepBeyondIsRefused) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(45);
  camera.pitch = Angle::fromDegrees(35);
  FrameSetup setup;

  camera.zoom = Q16::fromRaw(0);
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kBadZoom);
  camera.zoom = Q16::fromRaw(1);
  expectWithinProvenBound(defaultLevel(8), camera, kDefaultFractionBits);

  const std::int32_t largest = largestAcceptedZoomRaw(camera, 8);
  ASSERT_LT(largest, std::numeric_limits<std::int32_t>::max()) << "no zoom was refused";
  camera.zoom = Q16::fromRaw(largest + 1);
  EXPECT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kOverflow);
  camera.zoom = Q16::fromRaw(largest);
  expectWithinProvenBound(defaultLevel(8), camera, kDefaultFractionBits);
  ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  for (const VariantInfo& info : allVariants()) {  // under UBSan: no variant overflows here
    frame.clear();
    EXPECT_TRUE(renderLevel(info.variant, defaultLevel(8), setup, frame)) << info.name;
  }
}

// Every leaf's depth key (the z-buffer's 24 bits, FrameSetup::depthKey) is exactly
// floor((z + bias) / 2^shift), in range, and the shift is the least that fits: at the default
// frame, the largest accepted zoom and the most fraction bits.
TEST(RenderStability, DepthKeysAreExactFitTwentyFourBitsAndLoseNoMoreThanTheyMust) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(45);
  camera.pitch = Angle::fromDegrees(35);
  struct Case {
    std::int32_t zoom_raw;
    int fraction_bits;
  };
  const std::int32_t largest = largestAcceptedZoomRaw(camera, 8);
  for (const Case& c :
       {Case{Q16::kOneRaw, kDefaultFractionBits}, Case{largest, kDefaultFractionBits},
        Case{Q16::kOneRaw, 20}, Case{1, kDefaultFractionBits}}) {
    camera.zoom = Q16::fromRaw(c.zoom_raw);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, 8, c.fraction_bits, &setup), CameraError::kNone);
    const std::uint64_t range = 2 * std::uint64_t{setup.depth_bias};
    EXPECT_LE(range >> setup.depth_shift, Framebuffer::kMaxDepthKey);
    if (setup.depth_shift > 0) {
      EXPECT_GT(range >> (setup.depth_shift - 1), Framebuffer::kMaxDepthKey);
    }
    std::size_t wrong = 0;
    auto check = [&](std::int32_t, std::int32_t, std::int32_t z, std::uint8_t) {
      const std::int64_t exact = (std::int64_t{z} + setup.depth_bias) >> setup.depth_shift;
      wrong += exact < 0 || exact > Framebuffer::kMaxDepthKey || setup.depthKey(z) != exact;
    };
    ASSERT_TRUE(BaselineWalk(defaultLevel(8), setup, check).run());
    EXPECT_EQ(wrong, 0u) << "zoom raw " << c.zoom_raw << " fraction bits " << c.fraction_bits;
    if (c.zoom_raw == Q16::kOneRaw && c.fraction_bits == kDefaultFractionBits) {
      EXPECT_LE(setup.depth_shift, 1) << "at zoom 1 a key step is at most 2^-14 pixels";
    }
  }
}

// A model of one level built by hand, for the depths no scan gives us.
struct HandModel {
  std::vector<std::uint8_t> nodes;
  std::vector<std::uint8_t> leaves;
  LevelView level(int depth) const { return {depth, nodes, leaves}; }
};

// Depth 16: a single chain of nodes down to the two opposite leaves of one leaf parent.
HandModel deepestChain() {
  HandModel model;
  model.nodes.assign(format::kMaxDepth - 1, 0x01);  // always child 0: the cube's low corner
  model.nodes.push_back(0x81);                      // leaf parent: children 0 and 7
  model.leaves = {0, 0};
  return model;
}

// Depth 4: every voxel on the surface of the cube, so leaves touch all six faces.
HandModel everyFaceOfTheCube() {
  HandModel model;
  const int n = 16;
  std::function<void(int, int, int, int)> node = [&](int level, int x, int y, int z) {
    const int size = n >> level;  // this node's edge in voxels
    std::uint8_t mask = 0;
    for (int k = 0; k < 8; ++k) {
      const int cx = x + (k & 4 ? size / 2 : 0), cy = y + (k & 2 ? size / 2 : 0),
                cz = z + (k & 1 ? size / 2 : 0);
      const int half = size / 2;
      const bool touches_face =
          cx == 0 || cy == 0 || cz == 0 || cx + half == n || cy + half == n || cz + half == n;
      if (touches_face) mask = static_cast<std::uint8_t>(mask | 1 << k);
    }
    model.nodes.push_back(mask);
    for (int k = 0; k < 8; ++k) {
      if (!(mask & (1 << k))) continue;
      const int cx = x + (k & 4 ? size / 2 : 0), cy = y + (k & 2 ? size / 2 : 0),
                cz = z + (k & 1 ? size / 2 : 0);
      if (level + 1 == 4)
        model.leaves.push_back(0);
      else
        node(level + 1, cx, cy, cz);
    }
  };
  node(0, 0, 0, 0);
  return model;
}

TEST(RenderStability, DepthOneAndTheDeepestDepthDrawWithinTheBound) {
  const HandModel depth_one{{0xff}, std::vector<std::uint8_t>(8, 0)};
  const HandModel deepest = deepestChain();
  ASSERT_EQ(validateLevelStream(depth_one.level(1), 1).error, ModelError::kNone);
  ASSERT_EQ(validateLevelStream(deepest.level(format::kMaxDepth), 1).error, ModelError::kNone);
  for (int degrees = 0; degrees < 360; degrees += 15) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(degrees);
    camera.roll = Angle::fromDegrees(degrees / 2);
    EXPECT_EQ(expectWithinProvenBound(depth_one.level(1), camera, kDefaultFractionBits), 8u);
    EXPECT_EQ(
        expectWithinProvenBound(deepest.level(format::kMaxDepth), camera, kDefaultFractionBits),
        2u);
  }
}

TEST(RenderStability, AModelTouchingEveryFaceOfItsCubeStaysWithinTheBoundAndInsideTheFrame) {
  const HandModel faces = everyFaceOfTheCube();
  const LevelView level = faces.level(4);
  ASSERT_EQ(validateLevelStream(level, 1).error, ModelError::kNone);
  ASSERT_EQ(level.leaves.size(), 16u * 16 * 16 - 14u * 14 * 14);
  for (int degrees = 0; degrees < 360; degrees += 7) {
    Camera camera;
    camera.yaw = Angle::fromDegrees(degrees);
    camera.pitch = Angle::fromDegrees(degrees);
    camera.zoom = Q16::fromRaw(Q16::kOneRaw / 2);  // half: the turned cube's corners stay on screen
    expectWithinProvenBound(level, camera, kDefaultFractionBits);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, 4, kDefaultFractionBits, &setup), CameraError::kNone);
    std::size_t off_screen = 0;
    auto sink = [&](std::int32_t x, std::int32_t y, std::int32_t, std::uint8_t) {
      const std::int32_t px = x >> setup.fraction_bits, py = y >> setup.fraction_bits;
      off_screen += px < 0 || py < 0 || px >= camera.width || py >= camera.height;
    };
    BaselineWalk<decltype(sink)>(level, setup, sink).run();
    EXPECT_EQ(off_screen, 0u) << "yaw and pitch " << degrees;
  }
}

TEST(RenderStability, OneByOneAndLargestCommonFramebuffersDrawTheSameWithEveryFixedVariant) {
  for (const auto& [width, height] : {std::pair{1, 1}, std::pair{4096, 4096}}) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.yaw = Angle::fromDegrees(20);
    FrameSetup setup;
    ASSERT_EQ(buildFrameSetup(camera, 8, kDefaultFractionBits, &setup), CameraError::kNone);
    setup.splat = SplatFootprint{};  // one pixel per leaf; splats: tests/core/splat_test.cpp
    expectWithinProvenBound(defaultLevel(8), camera, kDefaultFractionBits);
    Framebuffer reference(width, height), frame(width, height);
    reference.clear();
    ASSERT_TRUE(renderLevel(Variant::kFixedBaseline, defaultLevel(8), setup, reference));
    EXPECT_GT(std::ranges::count_if(reference.pixels(),
                                    [](std::uint32_t word) { return word != Framebuffer::kEmpty; }),
              0);  // the model is there
    for (const VariantInfo& info : allVariants()) {
      if (!isFixedPoint(info.variant)) continue;
      frame.clear();
      ASSERT_TRUE(renderLevel(info.variant, defaultLevel(8), setup, frame));
      EXPECT_TRUE(std::ranges::equal(frame.pixels(), reference.pixels()))
          << info.name << " " << width;
    }
  }
}

}  // namespace
}  // namespace octopoint

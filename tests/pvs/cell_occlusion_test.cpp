// The eroded occlusion map's sets (tools/cell_occlusion.h): an instance hidden from a sample but
// seen from an eye within eps of it is in the sample's set, by the erosion (past a wall's edge) and
// by the crack rule (through the gap between two walls that touch as seen from the sample).
#include "tools/cell_occlusion.h"

#include <gtest/gtest.h>

#include <array>
#include <initializer_list>
#include <utility>
#include <vector>

#include "renderer/scene_renderer.h"
#include "tests/support/perspective_reference.h"
#include "tests/support/synthetic_levels.h"

namespace octopoint {
namespace {

using testing_support::encodeLevel;
using testing_support::mortonKey;
using testing_support::SyntheticLevel;

constexpr std::int64_t kEdge = kPerspectiveUnit;  // one scene edge, Q.24

// A wall a quarter of the model cube wide (centred) and its whole height, facing z, two voxels of
// depth 6 thick at z = 0.
const ModelView& wallModel() {
  static const SyntheticLevel level = [] {
    std::vector<std::uint64_t> keys;
    for (std::uint32_t i = 24; i < 40; ++i)
      for (std::uint32_t j = 0; j < 64; ++j)
        for (std::uint32_t k = 31; k <= 32; ++k) keys.push_back(mortonKey(i, j, k, 6));
    return encodeLevel(std::move(keys), 6, [](std::uint64_t) { return std::uint8_t{1}; });
  }();
  static const std::array<std::uint8_t, 768> palette{};
  static const EmbeddedLevel embedded{6,
                                      level.nodes.data(),
                                      static_cast<std::uint32_t>(level.nodes.size()),
                                      level.leaves.data(),
                                      static_cast<std::uint32_t>(level.leaves.size()),
                                      nullptr};
  static const EmbeddedModel model{"wall", format::kVersion2, 0, 0,        2, palette.data(),
                                   0,      nullptr,           1, &embedded};
  static const ModelView view = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(model, &issue);
  }();
  return view;
}

// Seen from the eye at the origin looking along +z: wall A (an edge wide, 4 tall, 2 edges away,
// its right edge at x/z = 1/8); far F (an eighth of an edge wide, 16 edges away, at x/z = 3/32:
// behind A); wall B (2 edges wide, 8 tall, 4 edges away, its left edge at x/z = 0.12: just behind
// A's right edge). Around F the walls reach farther than the erosion's window (12 pixels of a
// 64-pixel face: 3/8 in x/z): what lets F in is the erosion past A's edge, or with B the crack.
const SceneInstance kWallA{0, {{-kEdge / 4, 0, 2 * kEdge}, Angle{}, 2}};
const SceneInstance kFar{0, {{3 * kEdge / 2, 0, 16 * kEdge}, Angle{}, -1}};
const SceneInstance kWallB{0, {{kEdge * 37 / 25, 0, 4 * kEdge}, Angle{}, 3}};

// Whether `far` changes a 128-pixel frame seen from `eye` (looking along +z, 90 degrees).
bool farSeen(std::vector<SceneInstance> instances, const Point3<std::int64_t>& eye) {
  const SceneInstance far = instances.back();
  const ModelView* models[] = {&wallModel()};
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(perspectiveCameraOf(eye, 0, 0, 90, 128, 128), kDefaultFractionBits,
                                 &view),
            PerspectiveError::kNone);
  std::vector<std::uint32_t> words[2];
  for (int with = 0; with < 2; ++with) {
    if (with == 0) instances.pop_back();  // the far instance is last
    SceneError error;
    SceneRenderer renderer(models, instances, &error);
    Framebuffer frame(128, 128);
    frame.clear();
    EXPECT_TRUE(renderer.draw(view, frame));
    words[with].assign(frame.pixels().begin(), frame.pixels().end());
    if (with == 0) instances.push_back(far);
  }
  return words[0] != words[1];
}

// The erosion's window: the face corner's radius everywhere, each pixel's own for the near
// distance (OcclusionSampling::radii), or sized by the depths in it (depth_windows).
enum class Window { kCorner, kRadii, kDepth };

// Whether the sample at the origin puts the far instance (the last) in its set.
bool farInSet(const std::vector<SceneInstance>& instances, std::int64_t eps,
              Window window = Window::kCorner) {
  const ModelView* models[] = {&wallModel()};
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  EXPECT_EQ(error, SceneError::kNone);
  OcclusionSampling sampling{eps, kEdge, 64};
  sampling.radii = window == Window::kRadii;
  sampling.depth_windows = window == Window::kDepth;
  OcclusionSampler sampler(renderer, sampling);
  std::uint64_t frames = 0;
  sampler.look({0, 0, 0}, &frames);
  EXPECT_EQ(frames, 12u);
  EXPECT_EQ(sampler.marks()[0], 1);  // wall A is seen whatever the erosion
  return sampler.marks().back() != 0;
}

TEST(CellOcclusion, AnInstancePastAWallsEdgeFromAnEyeWithinEpsIsInTheSet) {
  const std::vector<SceneInstance> scene = {kWallA, kFar};
  // The geometry: hidden from the sample, seen from an eye a tenth of an edge to the right.
  EXPECT_FALSE(farSeen(scene, {0, 0, 0}));
  EXPECT_TRUE(farSeen(scene, {kEdge / 10, 0, 0}));
  EXPECT_TRUE(farInSet(scene, kEdge / 10));
  EXPECT_TRUE(farInSet(scene, kEdge / 10, Window::kRadii));  // each pixel's own radius
  EXPECT_TRUE(farInSet(scene, kEdge / 10, Window::kDepth));  // sized by wall A's depth
  EXPECT_FALSE(farInSet(scene, 0));  // without erosion: the sample's own view, which misses it
}

TEST(CellOcclusion, AnInstanceThroughTheGapBetweenTouchingWallsIsInTheSet) {
  // Walls A and B touch as the sample sees them, but B is twice as far: from an eye a tenth of
  // an edge to the right a gap opens between them, through which F shows. The erosion alone
  // (the farthest of A's and B's depths around F's pixels) would call F hidden; the crack between
  // them is what lets it in.
  const std::vector<SceneInstance> scene = {kWallA, kWallB, kFar};
  EXPECT_FALSE(farSeen(scene, {0, 0, 0}));
  EXPECT_TRUE(farSeen(scene, {kEdge / 10, 0, 0}));
  EXPECT_TRUE(farInSet(scene, kEdge / 10));
  EXPECT_TRUE(farInSet(scene, kEdge / 10, Window::kRadii));
  EXPECT_TRUE(farInSet(scene, kEdge / 10, Window::kDepth));
}

// A far wall W (2 edges wide, 8 tall, 8 edges ahead: 4 pixels either side of the axis on a
// 64-pixel face) and a small instance behind its middle, 12 edges ahead, hidden from every eye
// within eps (1/10 edge). The window for the near distance (1 edge) is 5 pixels at the face's
// centre (12 at its corner): it reaches past W into the sky, and lets the instance in. Sized by
// W's own depth, asin(eps / 7.9 edges), it is 2 pixels: all W, and the instance is out.
const SceneInstance kFarWall{0, {{0, 0, 8 * kEdge}, Angle{}, 3}};
const SceneInstance kBehind{0, {{0, 0, 12 * kEdge}, Angle{}, -1}};

TEST(CellOcclusion, AFarWallHidesWhatIsBehindItOnlyWithDepthWindows) {
  const std::vector<SceneInstance> scene = {kFarWall, kBehind};
  constexpr std::int64_t kEps = kEdge / 10;
  for (const Point3<std::int64_t>& eye :
       {Point3<std::int64_t>{0, 0, 0}, {kEps, 0, 0}, {-kEps, 0, 0}, {0, kEps, 0}, {0, -kEps, 0}}) {
    EXPECT_FALSE(farSeen(scene, eye));
  }
  EXPECT_TRUE(farInSet(scene, kEps, Window::kCorner));
  EXPECT_TRUE(farInSet(scene, kEps, Window::kRadii));
  EXPECT_FALSE(farInSet(scene, kEps, Window::kDepth));
  EXPECT_FALSE(farInSet(scene, 0));  // the sample's own view
}

TEST(CellOcclusion, DepthWindowsNarrowWithDepth) {
  // At the near distance a depth window is the pixel's radius for it where that is below the
  // corner's rho (which caps the radii, not the depth windows); at 8 times that distance at most
  // half of it (and a pixel for the rounding).
  OcclusionSampling sampling{kEdge / 10, kEdge, 64};
  const int rho = erosionRadius(sampling), side = 64 + 2 * (rho + 1), shift = 8;
  std::vector<std::uint8_t> radius(static_cast<std::size_t>(side * side));
  erosionRadii(sampling, side, radius);
  const DepthWindows depth(sampling, side, shift);
  EXPECT_EQ(depth.widest(), (side - 1) / 2);
  const auto near_key = static_cast<std::uint32_t>(kEdge >> shift);
  for (int py = 0; py < side; ++py) {
    for (int px = 0; px < side; ++px) {
      const std::size_t i = static_cast<std::size_t>(py * side + px);
      EXPECT_GE(depth.radius(i, near_key), radius[i]);
      if (radius[i] < rho) {
        EXPECT_EQ(depth.radius(i, near_key), radius[i]);
      }
      EXPECT_LE(depth.radius(i, 8 * near_key), radius[i] / 2 + 1);
    }
  }
  // Far away, at the centre: the grid's pixel and the reach's rounding up.
  EXPECT_EQ(depth.radius(static_cast<std::size_t>(side / 2 * side + side / 2), 64 * near_key), 2);
  // Within eps: wider than the frame.
  EXPECT_EQ(depth.radius(0, static_cast<std::uint32_t>((kEdge / 20) >> shift)), depth.widest() + 1);
}

TEST(CellOcclusion, ANearSurfaceInADepthWindowWidensIt) {
  // Far words (64 edges: a window of 2 pixels at the centre) around pixel p, a word half an edge
  // away 2 pixels to its right (asin(eps / d) needs 9 there) and sky 7 pixels to its right: the
  // window grows to take in the sky, and p is empty; without the near word, or with it on the
  // ground (no surface for the window's size), p keeps the far word. No cracks (eps 0 for them).
  const OcclusionSampling sampling{kEdge / 10, kEdge, 64};
  const int rho = erosionRadius(sampling), side = 64 + 2 * (rho + 1), shift = 8;
  const DepthWindows depth(sampling, side, shift);
  const std::size_t pixels = static_cast<std::size_t>(side * side);
  const std::size_t p = static_cast<std::size_t>(side / 2 * side + side / 2);
  const std::uint32_t far = FrameView::pack(static_cast<std::uint32_t>((64 * kEdge) >> shift), 0);
  const std::uint32_t near = FrameView::pack(static_cast<std::uint32_t>((kEdge / 2) >> shift), 0);
  ASSERT_EQ(depth.radius(p, FrameView::depthKeyOf(far)), 2);
  ASSERT_GE(depth.radius(p, FrameView::depthKeyOf(near)), 8);
  std::vector<std::uint32_t> words(pixels, far), map(pixels), scratch;
  words[p + 7] = FrameView::kEmpty;
  const auto mapAtP = [&](std::span<const std::uint8_t> ground) {
    occlusionMap(words, side, side, 0, 0, 64, rho, map, scratch, ground, {}, &depth);
    return map[p];
  };
  EXPECT_EQ(mapAtP({}), far | 0xFF);
  words[p + 2] = near;
  EXPECT_EQ(mapAtP({}), FrameView::kEmpty);
  std::vector<std::uint8_t> ground(pixels, 0);
  ground[p + 2] = 1;
  EXPECT_EQ(mapAtP(ground), far | 0xFF);
}

TEST(CellOcclusion, TheMapErodesNearPixelsAndCracks) {
  // 8 x 1 words: keys 100 (near), then 1000 x 3, then 2000 x 4 (a crack at 3|4).
  std::vector<std::uint32_t> words;
  for (const std::uint32_t key : {100u, 1000u, 1000u, 1000u, 2000u, 2000u, 2000u, 2000u})
    words.push_back(FrameView::pack(key, 0));
  std::vector<std::uint32_t> map(8), scratch;
  occlusionMap(words, 8, 1, 500, 0, 64, 0, map, scratch);
  EXPECT_EQ(map[0], FrameView::kEmpty);  // nearer than the near key
  EXPECT_EQ(map[1], words[1] | 0xFF);    // a point at the map's depth writes
  EXPECT_EQ(map[4], words[4] | 0xFF);
  occlusionMap(words, 8, 1, 500, kEdge / 10, 64, 0, map, scratch);
  EXPECT_EQ(map[2], words[2] | 0xFF);
  EXPECT_EQ(map[3], FrameView::kEmpty);  // both sides of the crack
  EXPECT_EQ(map[4], FrameView::kEmpty);
  EXPECT_EQ(map[5], words[5] | 0xFF);
}

// Keys along a line on which 1/key is affine in pieces: a plane seen at a slant, two planes
// meeting at a crease, and two at different depths.
std::vector<std::uint32_t> affineKeys(std::initializer_list<std::pair<double, double>> pieces,
                                      int each) {
  std::vector<std::uint32_t> words;
  for (const auto& [start, step] : pieces) {
    for (int i = 0; i < each; ++i) {
      const double key = 1e9 / (start + step * i);
      words.push_back(FrameView::pack(static_cast<std::uint32_t>(key), 0));
    }
  }
  return words;
}

int cracksIn(const std::vector<std::uint32_t>& words) {
  std::vector<std::uint32_t> map(words.size()), scratch;
  occlusionMap(words, static_cast<std::int32_t>(words.size()), 1, 0, kEdge / 10, 64, 0, map,
               scratch);
  int empty = 0;
  for (const std::uint32_t word : map) empty += word == FrameView::kEmpty ? 1 : 0;
  return empty;
}

TEST(CellOcclusion, ASlantedPlaneAndACreaseAreNoCracksButAJumpIs) {
  // 1/key from 10^5 (key 10^4) falling 4% of that a pixel: a surface running away at a slant,
  // each pixel's depth 4% past the last's (the old rule's threshold here: 2%).
  EXPECT_EQ(cracksIn(affineKeys({{1e5, -4e3}}, 16)), 0);
  // A building's corner: the same, then a face coming back towards the eye.
  EXPECT_EQ(cracksIn(affineKeys({{1e5, -4e3}, {0.6e5, 2e3}}, 10)), 0);
  // Two walls facing the eye, the second a quarter farther, side by side: both words at the jump.
  EXPECT_EQ(cracksIn(affineKeys({{1e5, 0}, {0.8e5, 0}}, 8)), 2);
  // A slanted wall, then another half again as far slanted alike.
  EXPECT_EQ(cracksIn(affineKeys({{1e5, -1e3}, {0.6e5, -1e3}}, 8)), 2);
}

// A wall drawn by the renderer, turned 60 degrees from the view: its voxels' splats stray from
// its plane, yet the map keeps it whole.
TEST(CellOcclusion, ARenderedSlantedWallHasNoCracks) {
  const ModelView* models[] = {&wallModel()};
  const std::vector<SceneInstance> scene = {{0, {{0, 0, 3 * kEdge}, Angle::fromDegrees(60), 2}}};
  SceneError error;
  SceneRenderer renderer(models, scene, &error);
  ASSERT_EQ(error, SceneError::kNone);
  PerspectiveCamera camera;
  camera.eye = {0, 0, 0};
  camera.fov = Angle::fromDegrees(90);
  camera.width = camera.height = 64;
  PerspectiveView view;
  ASSERT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  Framebuffer frame(64, 64);
  frame.clear();
  ASSERT_TRUE(renderer.draw(view, frame));
  std::vector<std::uint32_t> map(64 * 64), scratch;
  occlusionMap(frame.pixels(), 64, 64, 0, kEdge / 10, 64, 0, map, scratch);
  int covered = 0, cracked = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    covered += frame.pixels()[i] != FrameView::kEmpty ? 1 : 0;
    cracked += frame.pixels()[i] != FrameView::kEmpty && map[i] == FrameView::kEmpty ? 1 : 0;
  }
  EXPECT_GT(covered, 300);
  // Only along the wall's outline (its ends against the sky are no cracks: the sky is empty).
  EXPECT_EQ(cracked, 0);
}

}  // namespace
}  // namespace octopoint

// The eroded occlusion maps with a ground plane (tools/cell_occlusion.h): pixels on the ground are
// no holes (near or far), yet an instance seen from an eye within eps beside a wall, past its edge
// over the ground, stays in the sample's set, and a wall standing on the ground hides what is
// behind its middle only when the ground is known.
#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

#include "renderer/scene_renderer.h"
#include "tests/support/perspective_reference.h"
#include "tests/support/synthetic_levels.h"
#include "tools/cell_occlusion.h"

namespace octopoint {
namespace cell_ground {  // named: the unity build joins this file with the others'

using testing_support::encodeLevel;
using testing_support::mortonKey;
using testing_support::SyntheticLevel;

constexpr std::int64_t kEdge = kPerspectiveUnit;  // one scene edge, Q.24

const ModelView& modelOf(const char* name, std::vector<std::uint64_t> keys, int depth) {
  // Leaked on purpose: the views must outlive every test (static storage per model).
  auto* level = new SyntheticLevel(
      encodeLevel(std::move(keys), depth, [](std::uint64_t) { return std::uint8_t{1}; }));
  static const std::array<std::uint8_t, 768> palette{};
  auto* embedded = new EmbeddedLevel{static_cast<std::uint8_t>(depth),
                                     level->nodes.data(),
                                     static_cast<std::uint32_t>(level->nodes.size()),
                                     level->leaves.data(),
                                     static_cast<std::uint32_t>(level->leaves.size()),
                                     nullptr};
  auto* model =
      new EmbeddedModel{name, format::kVersion2, 0, 0, 2, palette.data(), 0, nullptr, 1, embedded};
  ModelIssue issue;
  return *new ModelView(*ModelView::fromEmbedded(*model, &issue));
}

// A wall a quarter of the cube wide (centred), its whole height, two voxels of depth 6 thick.
const ModelView& wall() {
  static const ModelView& view = []() -> const ModelView& {
    std::vector<std::uint64_t> keys;
    for (std::uint32_t i = 24; i < 40; ++i)
      for (std::uint32_t j = 0; j < 64; ++j)
        for (std::uint32_t k = 31; k <= 32; ++k) keys.push_back(mortonKey(i, j, k, 6));
    return modelOf("wall", std::move(keys), 6);
  }();
  return view;
}

// A plate: the cube's top layer of voxels of depth 7 (the ground).
const ModelView& plate() {
  static const ModelView& view = []() -> const ModelView& {
    std::vector<std::uint64_t> keys;
    for (std::uint32_t i = 0; i < 128; ++i)
      for (std::uint32_t k = 0; k < 128; ++k) keys.push_back(mortonKey(i, 0, k, 7));
    return modelOf("plate", std::move(keys), 7);
  }();
  return view;
}

// The eye at the origin, the ground a quarter edge below it (y down), its plate 16 edges wide
// (voxels of 1/8 edge, their centres on the plane) from z = 1/2 to 33/2 (none under the eye,
// where voxels that coarse would be drawn across the whole frame). Wall A (model 0, 2 edges
// wide, 8 tall) stands on it 2 edges ahead, x from -1 to 1; backdrop C (16 edges wide, x from -4
// to 12, and 64 tall) 12 edges ahead, so that nothing near the instances below shows sky.
constexpr std::int64_t kGround = kEdge / 4;
const SceneInstance kPlate{1, {{0, kGround + 8 * kEdge - kEdge / 16, 17 * kEdge / 2}, Angle{}, 4}};
const SceneInstance kWallA{0, {{0, kGround - 4 * kEdge, 2 * kEdge}, Angle{}, 3}};
const SceneInstance kBackdrop{0, {{4 * kEdge, kGround - 32 * kEdge, 12 * kEdge}, Angle{}, 6}};
// Hidden: an instance 1/8 edge wide and 1/2 tall on the ground behind A's middle, 4 edges ahead.
const SceneInstance kHidden{0, {{0, kGround - kEdge / 4, 4 * kEdge}, Angle{}, -1}};
// Past A's right edge (x/z 1/2) from an eye 1/6 edge to the right: 6 edges ahead, its right
// edge at x/z 0.494 from the sample.
const SceneInstance kBeside{0, {{29 * kEdge / 10, kGround - kEdge / 4, 6 * kEdge}, Angle{}, -1}};

std::vector<std::uint32_t> frameFrom(const std::vector<SceneInstance>& instances,
                                     const Point3<std::int64_t>& eye) {
  const ModelView* models[] = {&wall(), &plate()};
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(perspectiveCameraOf(eye, 0, 0, 90, 128, 128), kDefaultFractionBits,
                                 &view),
            PerspectiveError::kNone);
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  EXPECT_EQ(error, SceneError::kNone);
  Framebuffer frame(128, 128);
  frame.clear();
  EXPECT_TRUE(renderer.draw(view, frame));
  return {frame.pixels().begin(), frame.pixels().end()};
}

// Whether the last instance changes the frame seen from `eye` (looking along +z).
bool lastSeen(std::vector<SceneInstance> instances, const Point3<std::int64_t>& eye) {
  const std::vector<std::uint32_t> with = frameFrom(instances, eye);
  instances.pop_back();
  return with != frameFrom(instances, eye);
}

// The sample at the origin's marks, eps 1/6 edge, near 3/2 edges, with or without the ground.
constexpr std::int64_t kEps = kEdge / 6;
std::vector<std::uint8_t> marksOf(const std::vector<SceneInstance>& instances, bool ground,
                                  OcclusionStats* stats = nullptr, bool radii = false,
                                  bool depth_windows = false) {
  const ModelView* models[] = {&wall(), &plate()};
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  EXPECT_EQ(error, SceneError::kNone);
  OcclusionSampling sampling{kEps, 3 * kEdge / 2, 64};
  sampling.ground = ground;
  sampling.ground_y = kGround;
  sampling.ground_voxel = kEdge / 8;
  sampling.radii = radii;
  sampling.depth_windows = depth_windows;
  OcclusionSampler sampler(renderer, sampling);
  std::uint64_t frames = 0;
  sampler.look({0, 0, 0}, &frames);
  if (stats != nullptr) *stats = sampler.stats();
  return {sampler.marks().begin(), sampler.marks().end()};
}

TEST(CellGround, TheGroundHidesNothingBesideAWall) {
  const std::vector<SceneInstance> scene = {kPlate, kWallA, kBackdrop, kBeside};
  // The geometry: hidden from the sample, seen from an eye eps to the right.
  EXPECT_FALSE(lastSeen(scene, {0, 0, 0}));
  EXPECT_TRUE(lastSeen(scene, {kEps, 0, 0}));
  OcclusionStats stats;
  const std::vector<std::uint8_t> marks = marksOf(scene, true, &stats);
  EXPECT_GT(stats.ground, 1000u);  // the plate is seen as the ground
  EXPECT_EQ(marks[0], 1);
  EXPECT_EQ(marks[1], 1);
  EXPECT_EQ(marks.back(), 1);
  EXPECT_EQ(marksOf(scene, true, nullptr, true).back(), 1);         // each pixel's own radius
  EXPECT_EQ(marksOf(scene, true, nullptr, false, true).back(), 1);  // sized by depth
}

TEST(CellGround, AWallOnTheGroundHidesWhatIsBehindItOnlyWithTheGround) {
  const std::vector<SceneInstance> scene = {kPlate, kWallA, kBackdrop, kHidden};
  EXPECT_FALSE(lastSeen(scene, {0, 0, 0}));
  EXPECT_FALSE(lastSeen(scene, {kEps, 0, 0}));
  EXPECT_FALSE(lastSeen(scene, {-kEps, 0, 0}));
  EXPECT_FALSE(lastSeen(scene, {0, -kEps, 0}));
  // Without the ground its near pixels empty every window that reaches below the wall's base.
  EXPECT_EQ(marksOf(scene, false).back(), 1);
  EXPECT_EQ(marksOf(scene, true).back(), 0);
  EXPECT_EQ(marksOf(scene, true, nullptr, true).back(), 0);
  EXPECT_EQ(marksOf(scene, true, nullptr, false, true).back(), 0);
}

TEST(CellGround, RadiiAllTheCornersAreTheConstantErosion) {
  // Random words with some empty: every pixel's radius rho gives the running maxima's map; the
  // radii shrink towards the face's centre and never pass rho.
  const OcclusionSampling sampling{kEdge / 10, kEdge, 32};
  const int rho = erosionRadius(sampling), side = 32 + 2 * (rho + 1);
  const std::size_t pixels = static_cast<std::size_t>(side * side);
  std::vector<std::uint32_t> words(pixels);
  std::uint32_t state = 12345;
  for (auto& word : words) {
    state = state * 1103515245u + 12345u;
    word = (state >> 28) == 0 ? FrameView::kEmpty : FrameView::pack(1000 + (state >> 20), 0);
  }
  std::vector<std::uint8_t> radius(pixels, static_cast<std::uint8_t>(rho));
  std::vector<std::uint32_t> constant(pixels), variable(pixels), scratch;
  occlusionMap(words, side, side, 0, 0, 32, rho, constant, scratch);
  occlusionMap(words, side, side, 0, 0, 32, rho, variable, scratch, {}, radius);
  EXPECT_EQ(constant, variable);
  erosionRadii(sampling, side, radius);
  const std::size_t centre = static_cast<std::size_t>(side / 2 * side + side / 2);
  EXPECT_LT(radius[centre], rho / 2 + 2);
  EXPECT_EQ(radius[static_cast<std::size_t>(rho + 1) * static_cast<std::size_t>(side + 1)], rho);
  for (const std::uint8_t r : radius) EXPECT_LE(r, rho);
}

TEST(CellGround, AWindowOfGroundAloneKeepsThePixelsOwnWord) {
  // 4 x 1 words, all ground: the map keeps each word (a point behind it is below the ground); a
  // word beside them that is no ground is the farthest of its window.
  std::vector<std::uint32_t> words;
  for (const std::uint32_t key : {1000u, 1100u, 1200u, 1300u, 5000u})
    words.push_back(FrameView::pack(key, 0));
  const std::vector<std::uint8_t> ground = {1, 1, 1, 1, 0};
  std::vector<std::uint32_t> map(5), scratch;
  occlusionMap(words, 5, 1, 2000, 0, 64, 0, map, scratch, ground);
  EXPECT_EQ(map[0], words[0] | 0xFF);
  EXPECT_EQ(map[3], words[3] | 0xFF);
  EXPECT_EQ(map[4], words[4] | 0xFF);
  EXPECT_EQ(scratch[1], kGroundWord);  // near, yet no hole
}

}  // namespace cell_ground
}  // namespace octopoint

// Pixel winners (SceneRenderer::setPixelWinners) and the cells built from them
// (tools/cell_build.h, CellBuildOptions::winners): the frame is the same bit for bit with the ids
// taken; every drawn pixel names the instance whose word it keeps and no empty pixel names one;
// drawing only the winners gives the same frame; and some instance that submitted a point (the
// looser test the default cells use) wins no pixel, so the winners' sets leave it out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/scene.h"
#include "renderer/scene_renderer.h"
#include "tests/support/perspective_reference.h"
#include "tools/cell_build.h"

namespace octopoint {
namespace cell_winners {  // named: the unity build joins this file with the others'
namespace {

constexpr std::int64_t kEdge = kPerspectiveUnit;  // one scene edge, Q.24
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

const ModelView& defaultModelView() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

// A street of the default model: two rows of 6 along z, an edge apart, each turned its own way,
// and a few behind them, so that from the middle of the row most stand behind nearer ones.
std::vector<SceneInstance> street() {
  std::vector<SceneInstance> instances;
  for (int k = 0; k < 6; ++k) {
    for (int side = -1; side <= 1; side += 2) {
      instances.push_back(
          {0, {{side * kEdge, 0, k * kEdge}, Angle::fromDegrees(37 * k + 20 * side), 0}});
      instances.push_back({0, {{side * 5 * kEdge / 2, 0, k * kEdge + kEdge / 2}, Angle{}, -1}});
    }
  }
  return instances;
}

struct Drawn {
  std::vector<std::uint32_t> words, winners;
  std::vector<std::uint8_t> submitted;
};

Drawn drawWith(SceneRenderer& renderer, const PerspectiveView& view, bool take_winners) {
  const std::int32_t w = view.camera.width, h = view.camera.height;
  Drawn drawn;
  drawn.winners.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), kNone);
  drawn.submitted.assign(renderer.instanceCount(), 0);
  renderer.setSubmittedMarks(drawn.submitted);
  if (take_winners) renderer.setPixelWinners(drawn.winners);
  Framebuffer frame(w, h);
  frame.clear();
  EXPECT_TRUE(renderer.draw(view, frame));
  renderer.setSubmittedMarks({});
  renderer.setPixelWinners({});
  drawn.words.assign(frame.pixels().begin(), frame.pixels().end());
  return drawn;
}

TEST(CellWinners, EachPixelNamesItsWinnerAndTheWinnersAloneDrawTheSameFrame) {
  const std::vector<SceneInstance> instances = street();
  const ModelView* models[] = {&defaultModelView()};
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  ASSERT_EQ(error, SceneError::kNone);
  std::size_t submitted_not_winning = 0;
  for (const int yaw : {0, 30, 90, 180, 215}) {
    for (const std::int64_t z : {-kEdge, 2 * kEdge, 5 * kEdge / 2}) {
      PerspectiveView view;
      ASSERT_EQ(
          buildPerspectiveView(perspectiveCameraOf({kEdge / 8, -kEdge / 16, z}, yaw, 5, 60, 96, 72),
                               kDefaultFractionBits, &view),
          PerspectiveError::kNone);
      renderer.clearVisibleSet();
      const Drawn plain = drawWith(renderer, view, false);
      const Drawn with = drawWith(renderer, view, true);
      EXPECT_EQ(plain.words, with.words) << "yaw " << yaw << " z " << z;  // frame unchanged
      std::vector<std::uint32_t> ids;
      for (std::size_t p = 0; p < with.words.size(); ++p) {
        EXPECT_EQ(with.winners[p] == kNone, with.words[p] == FrameView::kEmpty) << p;
        if (with.winners[p] != kNone) ids.push_back(with.winners[p]);
      }
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      for (const std::uint32_t id : ids) EXPECT_EQ(with.submitted[id], 1) << id;
      for (std::size_t i = 0; i < instances.size(); ++i) {
        submitted_not_winning +=
            with.submitted[i] != 0 && !std::binary_search(ids.begin(), ids.end(), i);
      }
      // Only the winners: the same words (what lost every pixel changes none).
      renderer.setVisibleSet(ids);
      EXPECT_EQ(drawWith(renderer, view, false).words, plain.words) << "yaw " << yaw << " z " << z;
      // Each winner's words: a pixel it wins holds a word it writes drawn alone.
      for (const std::uint32_t id : ids) {
        const std::uint32_t alone[] = {id};
        renderer.setVisibleSet(alone);
        const Drawn own = drawWith(renderer, view, false);
        for (std::size_t p = 0; p < with.words.size(); ++p) {
          if (with.winners[p] == id) {
            EXPECT_EQ(own.words[p], with.words[p]) << id << " " << p;
          }
        }
      }
    }
  }
  // Submitting is looser than winning: behind the rows some instances pass the occlusion tiles
  // and lose every pixel.
  EXPECT_GT(submitted_not_winning, 0u);
}

TEST(CellWinners, WinnersSetsAreWithinTheSubmittedOnesAndSomeSmaller) {
  const std::vector<SceneInstance> instances = street();
  const ModelView* models[] = {&defaultModelView()};
  CellBuildOptions options;
  options.edge = 2 * kEdge;
  options.y = {-kEdge / 4, -kEdge / 8};
  options.face = 48;
  options.margin = 0;
  options.neighbours = false;
  const CellBuild loose = buildCells(models, instances, options);
  options.winners = true;
  const CellBuild tight = buildCells(models, instances, options);
  ASSERT_GT(loose.grid.nx, 0u);
  ASSERT_EQ(loose.sets.size(), tight.sets.size());
  std::size_t loose_total = 0, tight_total = 0;
  for (std::size_t c = 0; c < loose.sets.size(); ++c) {
    EXPECT_TRUE(std::includes(loose.sets[c].begin(), loose.sets[c].end(), tight.sets[c].begin(),
                              tight.sets[c].end()))
        << c;
    loose_total += loose.sets[c].size();
    tight_total += tight.sets[c].size();
  }
  EXPECT_LT(tight_total, loose_total);
}

TEST(CellWinners, SpacedSamplesReachFartherWithReach) {
  // The lattice of --spacing: a cell takes what the samples within reach of it saw, so a larger
  // reach only adds, and a reach of a whole cell adds something on this street.
  const std::vector<SceneInstance> instances = street();
  const ModelView* models[] = {&defaultModelView()};
  CellBuildOptions options;
  options.edge = kEdge;
  options.y = {-kEdge / 4, -kEdge / 8};
  options.face = 32;
  options.margin = 0;
  options.winners = true;
  options.spacing = {kEdge};
  const CellBuild near = buildCells(models, instances, options);
  options.reach = kEdge;
  const CellBuild far = buildCells(models, instances, options);
  ASSERT_GT(near.grid.nx, 0u);
  EXPECT_EQ(near.samples, far.samples);
  std::size_t near_total = 0, far_total = 0;
  for (std::size_t c = 0; c < near.sets.size(); ++c) {
    EXPECT_TRUE(std::includes(far.sets[c].begin(), far.sets[c].end(), near.sets[c].begin(),
                              near.sets[c].end()))
        << c;
    near_total += near.sets[c].size();
    far_total += far.sets[c].size();
  }
  EXPECT_GT(near_total, 0u);
  EXPECT_LT(near_total, far_total);
}

}  // namespace
}  // namespace cell_winners
}  // namespace octopoint

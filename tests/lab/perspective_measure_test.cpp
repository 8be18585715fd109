// The walk-through measurement (lab/perspective_measure.h) on a small case: the default model seen
// from the table's edge (docs/perspective.md, "Walk-through views") at 160x120. Its walks hand over
// what the renderer draws, every leaf lies within the issue's half pixel of its exact projection,
// the double-precision silhouette is the frame's and the frame covers it, culling submits no more.

#include "lab/perspective_measure.h"

#include <gtest/gtest.h>

#include <optional>

#include "octopoint/models.h"
#include "tests/support/perspective_reference.h"

namespace octopoint::lab {
namespace {

// The eye at the table's edge (tests/core/perspective_cull_test.cpp's view, perspective_bench's).
PerspectiveView tableEdgeView(int width, int height) {
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(tableEdgeCamera(width, height), kDefaultFractionBits, &view),
            PerspectiveError::kNone);
  return view;
}

TEST(PerspectiveMeasure, TableEdgeOfTheDefaultModel) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  ASSERT_TRUE(model.has_value());
  std::vector<std::uint8_t> rgb, silhouette;
  const PerspectiveMeasurement m =
      measurePerspective(*model, tableEdgeView(160, 120), 1, &rgb, &silhouette);
  EXPECT_EQ(m.depths, (std::vector<int>{6, 7, 8}));
  // The measured leaves are the ones the renderer hands to its plot without culling.
  EXPECT_GT(m.leaves, 10000u);
  EXPECT_EQ(m.leaves, m.points_unculled);
  EXPECT_LE(m.points_culled, m.points_unculled);
  // Positions: within the half pixel, and not trivially exact (the affine maps round).
  EXPECT_GT(m.max_position_px, 0.0);
  EXPECT_LE(m.max_position_px, 0.5);
  // The silhouette is the frame's shape: most of what the frame covers (the splats are a little
  // larger than the voxels' exact shadows), and the frame leaves at most 1% of it empty.
  EXPECT_GT(m.silhouette_pixels, m.covered_pixels * 9 / 10);
  EXPECT_LE(m.silhouette_pixels, m.covered_pixels);
  EXPECT_LE(m.emptyShare(), 0.01);
  ASSERT_EQ(silhouette.size(), 160u * 120u);
  ASSERT_EQ(rgb.size(), 3 * silhouette.size());
  // One round of each frame was timed.
  EXPECT_GT(m.perspective_ms, 0.0);
  EXPECT_GT(m.orthographic_ms, 0.0);
  EXPECT_EQ(m.orthographic_depth, 7);  // depth auto at 160x120
}

}  // namespace
}  // namespace octopoint::lab

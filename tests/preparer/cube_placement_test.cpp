// Where the model cube lies in the scan (format versions 4 and 5, octopoint/model.h): the preparer
// records its lowest corner and edge in the scan's own units and axes, the frame --crop takes,
// whatever the scan's axis convention, and the `.oct` file, the chunked file and the model read
// back from them carry the same bits.
#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "codegen/chunked_writer.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "octopoint/model.h"
#include "octopoint/progressive.h"

namespace octopoint {
namespace {

// Four points spanning x 0..8, y 0..4 and z 0..2 scan units (exact in binary).
prepare::Scan placementScan() {
  prepare::Scan scan;
  scan.positions = {{0, 0, 0}, {8, 4, 0}, {2, 0, 2}, {1, 1, 1}};
  scan.points_in_file = scan.positions.size();
  return scan;
}

prepare::PreparedModel preparedPlacementModel(prepare::ScanAxes axes) {
  prepare::PrepareOptions options;
  options.name = "placed";
  options.depths = {2, 3};
  options.axes = axes;
  return prepare::prepareModel(placementScan(), "placed.pcd", options);
}

double corner(const CubePlacement& cube, int axis) {
  return std::bit_cast<double>(cube.corner_bits[axis]);
}

TEST(CubePlacement, TheCubesCornerAndEdgeAreRecordedInTheScansUnits) {
  const CubePlacement cube = preparedPlacementModel(prepare::ScanAxes::kYDown).cube;
  // The box 0..8 x 0..4 x 0..2 centred in a cube of edge 8: corner (0, 2 - 4, 1 - 4).
  EXPECT_EQ(corner(cube, 0), 0.0);
  EXPECT_EQ(corner(cube, 1), -2.0);
  EXPECT_EQ(corner(cube, 2), -3.0);
  EXPECT_EQ(std::bit_cast<double>(cube.edge_bits), 8.0);
  EXPECT_EQ(cube.scan_axes, format::kScanAxesYDown);
}

TEST(CubePlacement, AYUpScanRecordsTheSameCubeInItsOwnAxes) {
  // The model is the scan turned about x, but the corner is the scan's, as --crop gives it.
  const CubePlacement down = preparedPlacementModel(prepare::ScanAxes::kYDown).cube;
  const CubePlacement up = preparedPlacementModel(prepare::ScanAxes::kYUp).cube;
  for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(corner(up, axis), corner(down, axis)) << axis;
  EXPECT_EQ(up.edge_bits, down.edge_bits);
  EXPECT_EQ(up.scan_axes, format::kScanAxesYUp);
}

TEST(CubePlacement, OctAndChunkedFilesCarryThePlacement) {
  const prepare::PreparedModel model = preparedPlacementModel(prepare::ScanAxes::kYUp);
  ASSERT_TRUE(model.cube.recorded());
  const std::vector<std::uint8_t> oct = prepare::serializeModel(model);
  ModelIssue issue;
  const std::optional<ModelView> view = ModelView::fromBytes(oct, &issue);
  ASSERT_TRUE(view) << describe(issue.error);
  EXPECT_EQ(view->formatVersion(), format::kFormatVersion);  // 6: version 4 and the reaches
  EXPECT_EQ(view->cubePlacement(), model.cube);

  const std::vector<std::uint8_t> chunked = prepare::serializeChunkedModel(model);
  ChunkedIssue chunked_issue;
  const std::optional<ProgressiveModel> progressive =
      progressiveModelFromPrefix(chunked, &chunked_issue);
  ASSERT_TRUE(progressive) << describe(chunked_issue.error);
  EXPECT_EQ(progressive->head().format_version, chunked::kFormatVersion);  // 7
  EXPECT_EQ(progressive->head().cube, model.cube);
}

}  // namespace
}  // namespace octopoint

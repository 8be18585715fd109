// Normal estimation (codegen/normal_estimation.h) against surfaces whose normals are known, with
// scanner noise of half a voxel: the per-voxel normals the preparer stores must be within 5
// degrees of the truth on average, before and after quantization to the normal palette. Both
// estimators are measured: k-NN PCA on scattered points and integral images on range images.
#include "codegen/normal_estimation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "codegen/cube_fit.h"
#include "codegen/normal_palette.h"
#include "codegen/prepare.h"
#include "codegen/voxelizer.h"
#include "tests/support/synthetic_surfaces.h"

namespace octopoint {
namespace {

using testing::Surface;

constexpr int kDepth = 6;
constexpr double kTargetMeanDegrees = 5.0;

struct Errors {
  double mean_deg = 0;
  double quantized_mean_deg = 0;
  double worst_deg = 0;
  std::size_t voxels = 0;
};

// The angle between the lines of `a` and `b` (0..90 degrees): the renderer lights both sides of a
// surface and compares normals as lines for creases, so a normal flipped by noise where the
// surface turns away from the sensor draws the same. Flips are counted apart.
double angleDegrees(const std::array<float, 3>& a, const testing::Vec3d& b) {
  const double d = std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  return std::acos(std::min(d, 1.0)) * 180.0 / 3.14159265358979323846;
}

// The scan through the preparer's normal steps (estimate, voxel mean, palette) at kDepth, with
// noise of `noise_voxels` voxel edges; angles against the true normal at each voxel's centre,
// oriented toward the sensor as the estimate is.
Errors measure(const Surface& surface, prepare::Scan scan) {
  const prepare::CubeFit fit = prepare::fitCube(scan.positions, "synthetic");
  const double voxel = fit.edge / std::ldexp(1.0, kDepth);
  prepare::NormalOptions options;
  options.neighbours = prepare::neighboursForDensity(
      static_cast<double>(scan.positions.size()) /
      static_cast<double>(prepare::occupiedVoxelKeys(scan, fit, kDepth).size()));
  scan.normals = prepare::estimateNormals(scan, voxel, options, "synthetic");
  const prepare::VoxelSet voxels = prepare::voxelize(scan, fit, kDepth);
  const prepare::NormalPalette palette =
      prepare::NormalPalette::build(voxels.normals, prepare::NormalPaletteKind::kAdaptive);
  Errors errors;
  errors.voxels = voxels.keys.size();
  for (std::size_t i = 0; i < voxels.keys.size(); ++i) {
    const auto xyz = prepare::mortonDecode(voxels.keys[i], kDepth);
    std::array<float, 3> centre{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      centre[axis] = static_cast<float>(fit.origin[axis] + (xyz[axis] + 0.5) * voxel);
    }
    testing::Vec3d truth = testing::trueNormal(surface, centre);
    if (truth[0] * centre[0] + truth[1] * centre[1] + truth[2] * centre[2] > 0) {
      truth = {-truth[0], -truth[1], -truth[2]};  // toward the sensor at the origin
    }
    const double error = angleDegrees(voxels.normals[i], truth);
    const prepare::NormalQ14& stored = palette.entries()[palette.indexOf(voxels.normals[i])];
    const std::array<float, 3> stored_unit = {stored[0] / 16384.0f, stored[1] / 16384.0f,
                                              stored[2] / 16384.0f};
    errors.mean_deg += error;
    errors.quantized_mean_deg += angleDegrees(stored_unit, truth);
    errors.worst_deg = std::max(errors.worst_deg, error);
  }
  errors.mean_deg /= static_cast<double>(errors.voxels);
  errors.quantized_mean_deg /= static_cast<double>(errors.voxels);
  return errors;
}

const Surface kSphere{Surface::Kind::kSphere, {0.1, -0.05, 2.0}, 0.5, {}, 0};
const Surface kPlane{Surface::Kind::kPlane, {0.0, 0.0, 2.0}, 0, {0.36, -0.48, -0.8}, 0.5};

// Half a voxel of kDepth for a scan whose fitted cube has edge about `edge`.
double halfVoxel(double edge) { return 0.5 * edge / std::ldexp(1.0, kDepth); }

void expectWithinTarget(const char* what, const Errors& e) {
  std::printf("%-34s %6zu voxels: mean %.2f deg (%.2f stored), worst %.1f deg\n", what, e.voxels,
              e.mean_deg, e.quantized_mean_deg, e.worst_deg);
  EXPECT_LE(e.mean_deg, kTargetMeanDegrees) << what;
  EXPECT_LE(e.quantized_mean_deg, kTargetMeanDegrees) << what;
}

TEST(NormalEstimation, ScatteredSphereWithHalfAVoxelOfNoise) {
  expectWithinTarget("k-NN PCA, sphere",
                     measure(kSphere, testing::scatteredScan(kSphere, 26000, halfVoxel(1.0), 1)));
}

TEST(NormalEstimation, ScatteredPlaneWithHalfAVoxelOfNoise) {
  // The tilted 1 x 1 patch spans about 1.2 along its widest axis.
  expectWithinTarget("k-NN PCA, plane",
                     measure(kPlane, testing::scatteredScan(kPlane, 20000, halfVoxel(1.2), 2)));
}

TEST(NormalEstimation, RangeImageOfASphereWithHalfAVoxelOfNoise) {
  const prepare::Scan scan = testing::rangeImage(kSphere, 200, 150, 40, halfVoxel(1.0), 3);
  expectWithinTarget("integral images, sphere", measure(kSphere, scan));
}

TEST(NormalEstimation, RangeImageOfAPlaneWithHalfAVoxelOfNoise) {
  const prepare::Scan scan = testing::rangeImage(kPlane, 200, 150, 40, halfVoxel(1.2), 4);
  expectWithinTarget("integral images, plane", measure(kPlane, scan));
}

TEST(NormalEstimation, NormalsFaceTheSensor) {
  prepare::Scan scan = testing::scatteredScan(kPlane, 3000, 0.0, 5);
  scan.normals = prepare::estimateNormals(scan, 1.0 / 64, {}, "plane");
  for (std::size_t i = 0; i < scan.positions.size(); ++i) {
    const auto& p = scan.positions[i];
    const auto& n = scan.normals[i];
    ASSERT_LT(n[0] * p[0] + n[1] * p[1] + n[2] * p[2], 0.0f) << "point " << i;  // toward the origin
  }
}

// Threads this process has now.
std::size_t threadsNow() {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++count;
  return count;
}

// --threads 1 --normals: PCL's OpenMP estimator took a thread per core whatever it was told, and
// libgomp keeps them after the estimate (idle, in its pool), which is what is counted here.
TEST(NormalEstimation, TakesTheThreadsThePreparerIsGiven) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core: one thread either way";
  const prepare::Scan scan = testing::scatteredScan(kPlane, 3000, 0.0, 5);
  prepare::PrepareOptions options;
  options.name = "plane";
  options.depths = {4, 5};
  options.normals = prepare::NormalOptions{};
  const std::size_t before = threadsNow();
  const prepare::PreparedModel model = prepare::prepareModel(scan, "plane", options, 1);
  EXPECT_GT(model.normal_neighbours, 0);  // the k-NN PCA ran
  EXPECT_EQ(threadsNow(), before);
}

TEST(NormalEstimation, RefusesFewerThanThreePoints) {
  prepare::Scan scan;
  scan.positions = {{0, 0, 1}, {1, 0, 1}};
  EXPECT_THROW(prepare::estimateNormals(scan, 0.1, {}, "two.pcd"), std::exception);
}

}  // namespace
}  // namespace octopoint

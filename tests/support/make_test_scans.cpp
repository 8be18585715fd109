// Writes the scan files the end-to-end tests read: a coloured sphere for the generated-source test,
// an organized depth image for the trade-off sweep's smoke test, and one broken scan per kind of
// bad input for the CLI error tests. PCD files are written by hand (the format is simple) so that
// each byte of the broken ones is deliberate.
// usage: make_test_scans OUTDIR
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "tests/support/synthetic_scans.h"

namespace {

namespace fs = std::filesystem;

struct Point {
  float x, y, z;
  std::uint32_t rgba;
};

// `rows` > 1: an organized scan of points / rows columns.
std::string pcdHeader(std::size_t points, const char* data, std::size_t rows = 1) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgba\nSIZE 4 4 4 "
         "4\n"
         "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " +
         std::to_string(points / rows) + "\nHEIGHT " + std::to_string(rows) +
         "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " + data + "\n";
}

std::string binaryPcd(const std::vector<Point>& points, std::size_t rows = 1) {
  std::string out = pcdHeader(points.size(), "binary", rows);
  out.append(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(Point));
  return out;
}

std::string asciiPcd(const std::vector<Point>& points) {
  std::string out = pcdHeader(points.size(), "ascii");
  for (const Point& p : points) {
    char line[128];
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g %u\n", static_cast<double>(p.x),
                  static_cast<double>(p.y), static_cast<double>(p.z), p.rgba);
    out += line;
  }
  return out;
}

void write(const fs::path& path, const std::string& contents) {
  std::ofstream(path, std::ios::binary) << contents;
}

// A depth camera's view (160 x 120, focal length 150 pixels, from the origin) of a ball of radius
// 0.3 at 1.5 in front of a wall at 2.5, the image's corners unmeasured (NaN), as a Kinect's are.
std::vector<Point> depthImageOfBall() {
  constexpr int kColumns = 160, kRows = 120;
  constexpr double kFocal = 150, kBallZ = 1.5, kBallRadius = 0.3, kWallZ = 2.5;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Point> points;
  for (int row = 0; row < kRows; ++row) {
    for (int col = 0; col < kColumns; ++col) {
      const double u = col - (kColumns - 1) / 2.0, v = row - (kRows - 1) / 2.0;
      if (std::hypot(u / kColumns, v / kRows) > 0.68) {
        points.push_back({nan, nan, nan, 0});
        continue;
      }
      // The ray t (dx, dy, 1) meets the ball where |t d - c|^2 = r^2: the nearer root.
      const double dx = u / kFocal, dy = v / kFocal;
      const double a = dx * dx + dy * dy + 1, b = -2 * kBallZ;
      const double c = kBallZ * kBallZ - kBallRadius * kBallRadius;
      const double discriminant = b * b - 4 * a * c;
      const bool ball = discriminant >= 0;
      const double t = ball ? (-b - std::sqrt(discriminant)) / (2 * a) : kWallZ;
      points.push_back({static_cast<float>(t * dx), static_cast<float>(t * dy),
                        static_cast<float>(t), ball ? 0xffd04020u : 0xff8090a0u});
    }
  }
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_test_scans OUTDIR\n");
    return 1;
  }
  const fs::path out = argv[1];
  fs::create_directories(out / "bad");

  const octopoint::prepare::Scan sphere = octopoint::testing::colouredSphere(20000);
  std::vector<Point> points;
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    const auto& p = sphere.positions[i];
    const auto& c = sphere.colours[i];
    points.push_back({p[0], p[1], p[2],
                      0xff000000u | std::uint32_t{c[0]} << 16 | std::uint32_t{c[1]} << 8 | c[2]});
  }
  write(out / "sphere.pcd", binaryPcd(points));
  write(out / "depth_image.pcd", binaryPcd(depthImageOfBall(), 120));

  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string valid = binaryPcd(points);
  write(out / "bad" / "truncated.pcd", valid.substr(0, valid.size() / 2));
  std::string garbage(4096, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i)
    garbage[i] = static_cast<char>((i * 2654435761u) >> 13);
  write(out / "bad" / "garbage.pcd", garbage);
  write(out / "bad" / "garbage.ply", garbage);
  write(out / "bad" / "truncated.ply",
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty "
        "float y\n"
        "property float z\nend_header\n" +
            std::string(100, '\0'));
  write(out / "bad" / "empty.pcd", asciiPcd({}));
  write(out / "bad" / "all_nan.pcd",
        asciiPcd({{nan, nan, nan, 0}, {nan, 1, 2, 0}, {3, nan, 1, 0}}));
  write(out / "bad" / "identical.pcd", asciiPcd({{1, 2, 3, 0}, {1, 2, 3, 0}, {1, 2, 3, 0}}));
  write(out / "bad" / "absurd.pcd", asciiPcd({{0, 0, 0, 0}, {1, 1, 1, 0}, {1e30f, 0, 0, 0}}));
  // Distinct points 0.1 nm apart (in metres): smaller than the model format's 1 nm cube.
  write(out / "bad" / "sub_nanometre.pcd",
        asciiPcd({{0, 0, 0, 0}, {1e-10f, 0, 0, 0}, {0, 5e-11f, 0, 0}}));
  write(out / "bad" / "good_small.pcd",
        asciiPcd({{0, 0, 0, 0}, {1, 1, 1, 0}, {0.5f, 0.2f, 0.1f, 0}}));
  fs::create_directories(out / "bad" / "directory.pcd");
  return 0;
}

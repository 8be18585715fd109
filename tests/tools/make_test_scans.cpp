// Writes the scan files the end-to-end tests read: a coloured sphere for the generated-source test,
// and one broken scan per kind of bad input for the CLI error tests. PCD files are written by hand
// (the format is simple) so that each byte of the broken ones is deliberate.
// usage: make_test_scans OUTDIR
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "tests/synthetic_scans.h"

namespace {

namespace fs = std::filesystem;

struct Point {
  float x, y, z;
  std::uint32_t rgba;
};

std::string pcdHeader(std::size_t points, const char* data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgba\nSIZE 4 4 4 4\n"
         "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " + std::to_string(points) + "\nHEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " + data + "\n";
}

std::string binaryPcd(const std::vector<Point>& points) {
  std::string out = pcdHeader(points.size(), "binary");
  out.append(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(Point));
  return out;
}

std::string asciiPcd(const std::vector<Point>& points) {
  std::string out = pcdHeader(points.size(), "ascii");
  for (const Point& p : points) {
    char line[128];
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g %u\n", static_cast<double>(p.x), static_cast<double>(p.y),
                  static_cast<double>(p.z), p.rgba);
    out += line;
  }
  return out;
}

void write(const fs::path& path, const std::string& contents) {
  std::ofstream(path, std::ios::binary) << contents;
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
    points.push_back({p[0], p[1], p[2], 0xff000000u | std::uint32_t{c[0]} << 16 | std::uint32_t{c[1]} << 8 | c[2]});
  }
  write(out / "sphere.pcd", binaryPcd(points));

  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string valid = binaryPcd(points);
  write(out / "bad" / "truncated.pcd", valid.substr(0, valid.size() / 2));
  std::string garbage(4096, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 2654435761u) >> 13);
  write(out / "bad" / "garbage.pcd", garbage);
  write(out / "bad" / "garbage.ply", garbage);
  write(out / "bad" / "truncated.ply",
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n" + std::string(100, '\0'));
  write(out / "bad" / "empty.pcd", asciiPcd({}));
  write(out / "bad" / "all_nan.pcd", asciiPcd({{nan, nan, nan, 0}, {nan, 1, 2, 0}, {3, nan, 1, 0}}));
  write(out / "bad" / "identical.pcd", asciiPcd({{1, 2, 3, 0}, {1, 2, 3, 0}, {1, 2, 3, 0}}));
  write(out / "bad" / "absurd.pcd", asciiPcd({{0, 0, 0, 0}, {1, 1, 1, 0}, {1e30f, 0, 0, 0}}));
  write(out / "bad" / "good_small.pcd", asciiPcd({{0, 0, 0, 0}, {1, 1, 1, 0}, {0.5f, 0.2f, 0.1f, 0}}));
  fs::create_directories(out / "bad" / "directory.pcd");
  return 0;
}

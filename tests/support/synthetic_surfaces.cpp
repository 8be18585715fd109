#include "tests/support/synthetic_surfaces.h"

#include <cmath>
#include <random>

namespace octopoint::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3d add(const Vec3d& a, const Vec3d& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3d scale(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d unit(const Vec3d& a) { return scale(a, 1.0 / std::sqrt(dot(a, a))); }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::array<float, 3> toFloat(const Vec3d& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

// Two unit vectors spanning the plane orthogonal to `n`.
std::array<Vec3d, 2> tangents(const Vec3d& n) {
  const Vec3d helper = std::fabs(n[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d u = unit(cross(n, helper));
  return {u, cross(n, u)};
}

// The distance along the unit ray `d` from the origin to `surface`, or a negative number.
double hit(const Surface& surface, const Vec3d& d) {
  if (surface.kind == Surface::Kind::kSphere) {
    const double b = dot(d, surface.centre);
    const double c = dot(surface.centre, surface.centre) - surface.radius * surface.radius;
    const double discriminant = b * b - c;
    return discriminant < 0 ? -1 : b - std::sqrt(discriminant);
  }
  const double denominator = dot(d, surface.normal);
  if (std::fabs(denominator) < 1e-9) return -1;
  const double t = dot(surface.centre, surface.normal) / denominator;
  const Vec3d p = scale(d, t);
  const auto [u, v] = tangents(surface.normal);
  const Vec3d offset = add(p, scale(surface.centre, -1));
  if (std::fabs(dot(offset, u)) > surface.half_size ||
      std::fabs(dot(offset, v)) > surface.half_size)
    return -1;
  return t;
}

prepare::Scan emptyScan() {
  prepare::Scan scan;
  scan.shading = prepare::ScanShading::kNone;
  return scan;
}

}  // namespace

Vec3d trueNormal(const Surface& surface, const std::array<float, 3>& p) {
  if (surface.kind == Surface::Kind::kPlane) return surface.normal;
  return unit(add({p[0], p[1], p[2]}, scale(surface.centre, -1)));
}

prepare::Scan scatteredScan(const Surface& surface, std::size_t count, double noise,
                            std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  prepare::Scan scan = emptyScan();
  while (scan.positions.size() < count) {
    Vec3d p, n;
    if (surface.kind == Surface::Kind::kSphere) {
      n = unit({gauss(random), gauss(random), gauss(random)});
      p = add(surface.centre, scale(n, surface.radius));
      if (dot(n, scale(p, -1)) <= 0) continue;  // the far side: not seen from the sensor
    } else {
      const auto [u, v] = tangents(surface.normal);
      n = surface.normal;
      p = add(surface.centre, add(scale(u, uniform(random) * surface.half_size),
                                  scale(v, uniform(random) * surface.half_size)));
    }
    scan.positions.push_back(toFloat(add(p, scale(n, noise * gauss(random)))));
  }
  scan.points_in_file = scan.positions.size();
  return scan;
}

prepare::Scan rangeImage(const Surface& surface, int width, int height, double fov_degrees,
                         double noise, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  prepare::Scan scan = emptyScan();
  scan.organized = true;
  scan.grid_width = static_cast<std::uint32_t>(width);
  scan.grid_height = static_cast<std::uint32_t>(height);
  const double focal = (width / 2.0) / std::tan(fov_degrees / 2 * kPi / 180);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const Vec3d d =
          unit({(column + 0.5 - width / 2.0) / focal, (row + 0.5 - height / 2.0) / focal, 1.0});
      const double t = hit(surface, d);
      if (t <= 0) continue;
      scan.positions.push_back(toFloat(scale(d, t + gauss(random))));
      scan.grid_index.push_back(static_cast<std::uint32_t>(row * width + column));
    }
  }
  scan.points_in_file = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return scan;
}

prepare::Scan pointSampledCube(const Vec3d& centre, double edge, std::size_t per_face, double noise,
                               std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  prepare::Scan scan = emptyScan();
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-0.5, 0.5}) {
      for (std::size_t i = 0; i < per_face; ++i) {
        Vec3d p = {uniform(random) * edge, uniform(random) * edge, uniform(random) * edge};
        p[static_cast<std::size_t>(axis)] = side * edge + gauss(random);
        scan.positions.push_back(toFloat(add(centre, p)));
      }
    }
  }
  scan.points_in_file = scan.positions.size();
  return scan;
}

}  // namespace octopoint::testing

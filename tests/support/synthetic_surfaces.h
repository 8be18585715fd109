#pragma once
// Synthetic range scans of surfaces whose normals are known, with scanner noise: what the normal
// estimation targets are measured on (tests/preparer/normal_estimation_test.cpp). The sensor sits
// at the origin looking along +z (the preparer's y-down axes), as a real range scanner's frame.

#include <array>
#include <cstdint>

#include "codegen/scan_loader.h"

namespace octopoint::testing {

using Vec3d = std::array<double, 3>;

// A surface: the nearest hit along a ray from the sensor, and its outward normal there.
struct Surface {
  enum class Kind { kSphere, kPlane } kind;
  Vec3d centre;          // sphere centre, or a point of the plane
  double radius = 0;     // sphere only
  Vec3d normal{};        // plane only: unit, facing the sensor
  double half_size = 0;  // plane only: the patch is |u|, |v| <= half_size around the centre
};

// The true outward normal of `surface` at (or nearest to) `p`.
Vec3d trueNormal(const Surface& surface, const std::array<float, 3>& p);

// An unorganized scan: `count` points spread evenly over the part of `surface` the sensor sees,
// each moved along the surface normal by Gaussian noise of standard deviation `noise`.
prepare::Scan scatteredScan(const Surface& surface, std::size_t count, double noise,
                            std::uint32_t seed);

// An organized scan: a width x height pinhole image (horizontal field of view `fov_degrees`), each
// pixel the surface's hit along its ray (pixels that miss stay empty), moved along the ray by
// Gaussian noise of standard deviation `noise`.
prepare::Scan rangeImage(const Surface& surface, int width, int height, double fov_degrees,
                         double noise, std::uint32_t seed);

// The six faces of an axis-aligned cube of edge `edge` centred at `centre`, `per_face` random
// points each, moved along their face's normal by Gaussian noise of `noise`.
prepare::Scan pointSampledCube(const Vec3d& centre, double edge, std::size_t per_face, double noise,
                               std::uint32_t seed);

}  // namespace octopoint::testing

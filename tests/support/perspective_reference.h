#pragma once
// The perspective camera in double precision, as renderer/perspective.h defines it: the reference
// its integer core and walk are tested against.

#include <array>
#include <cmath>

#include "renderer/perspective.h"

namespace octopoint {

inline constexpr double kUnit = static_cast<double>(kPerspectiveUnit);
inline constexpr double kPi = 3.14159265358979323846;

// A camera of the tests' views: the eye in Q.24 cube edges, the angles in degrees.
inline PerspectiveCamera perspectiveCameraOf(ModelPoint eye, int yaw, int pitch, int fov, int width,
                                             int height) {
  PerspectiveCamera camera;
  camera.eye = eye;
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  camera.fov = Angle::fromDegrees(fov);
  camera.width = width;
  camera.height = height;
  return camera;
}

// The eye at the default model's table's edge looking down at the objects (tests/paths/
// table_walk.json's first frame; docs/perspective.md, "Occlusion culling"): the tests' and the
// benchmarks' inside view.
inline PerspectiveCamera tableEdgeCamera(int width, int height) {
  const std::int64_t u = kPerspectiveUnit;
  return perspectiveCameraOf({0, 28 * u / 100, -46 * u / 100}, 0, 28, 90, width, height);
}

inline double radiansOf(Angle angle) { return angle.turns16() * 2 * kPi / Angle::kUnitsPerTurn; }

using Matrix = std::array<std::array<double, 3>, 3>;

inline Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix product{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) product[i][j] += a[i][k] * b[k][j];
  return product;
}

// World to camera in double: Rz(-roll) * Rx(-pitch) * Ry(-yaw), as octopoint/fixed.h defines them.
inline Matrix worldToCamera(const PerspectiveCamera& camera) {
  const double y = -radiansOf(camera.yaw), p = -radiansOf(camera.pitch),
               r = -radiansOf(camera.roll);
  const Matrix ry{{{std::cos(y), 0, std::sin(y)}, {0, 1, 0}, {-std::sin(y), 0, std::cos(y)}}};
  const Matrix rx{{{1, 0, 0}, {0, std::cos(p), -std::sin(p)}, {0, std::sin(p), std::cos(p)}}};
  const Matrix rz{{{std::cos(r), -std::sin(r), 0}, {std::sin(r), std::cos(r), 0}, {0, 0, 1}}};
  return multiply(rz, multiply(rx, ry));
}

using Vector3 = std::array<double, 3>;

inline Vector3 rotated(const Matrix& m, const Vector3& d) {
  Vector3 out{};
  for (int row = 0; row < 3; ++row)
    out[row] = m[row][0] * d[0] + m[row][1] * d[1] + m[row][2] * d[2];
  return out;
}

// A point of the model (Q.24 cube edges) in camera space (units), without the integer code's
// rounding; `world_to_camera` is worldToCamera(camera), made once per camera by the caller.
inline Vector3 exactCameraSpace(const Matrix& world_to_camera, const ModelPoint& eye,
                                const Vector3& point) {
  return rotated(world_to_camera,
                 {point[0] - static_cast<double>(eye.x), point[1] - static_cast<double>(eye.y),
                  point[2] - static_cast<double>(eye.z)});
}

inline Vector3 exactCameraSpace(const Matrix& world_to_camera, const ModelPoint& eye,
                                const ModelPoint& point) {
  return rotated(world_to_camera,
                 {static_cast<double>(point.x - eye.x), static_cast<double>(point.y - eye.y),
                  static_cast<double>(point.z - eye.z)});
}

inline double focalOf(const PerspectiveCamera& camera) {
  // The view halves the angle in whole units, as the integer code does.
  const double half = (camera.fov.turns16() / 2) * 2 * kPi / Angle::kUnitsPerTurn;
  return camera.height / 2.0 / std::tan(half);
}

struct Projected {
  double x, y;  // pixels
};

// The exact projection of a camera-space point given in units.
inline Projected exactProjection(const PerspectiveCamera& camera, double x, double y, double z) {
  const double f = focalOf(camera);
  return {camera.width / 2.0 + f * x / z, camera.height / 2.0 + f * y / z};
}

}  // namespace octopoint

#include "renderer/perspective.h"

#include <algorithm>
#include <cassert>

#include "fixedpoint/trig.h"

namespace octopoint {
namespace {

constexpr std::int64_t kQ30One = std::int64_t{1} << 30;

// |value| for the int64 coordinates of this file (std::llabs takes long long, another type here).
std::int64_t magnitude(std::int64_t value) { return value < 0 ? -value : value; }

bool fitsInt32(std::int64_t value) { return value >= INT32_MIN && value <= INT32_MAX; }

// significantBits(value) <= bits (0..62), by two comparisons: -2^bits < value < 2^bits.
bool within(std::int64_t value, int bits) {
  return value > -(std::int64_t{1} << bits) && value < (std::int64_t{1} << bits);
}

// round(numerator * 2^shift / denominator) for a shift that may be negative (then the denominator
// takes the power of two): the screen's F against a Q.16 focal length.
std::optional<std::int64_t> divScaled(std::int64_t numerator, std::int64_t denominator, int shift) {
  if (shift >= 0) return divShiftRound(numerator, denominator, shift);
  return divShiftRound(numerator, denominator << -shift, 0);
}

// round(numerator / denominator), ties toward +infinity as divShiftRound rounds, by one division
// (the hardware's; on a Cortex-M longDivide, octopoint/fixed.h: the same bits); denominator > 0,
// |numerator| < 2^63.
std::int64_t divideRounded(std::int64_t numerator, std::int64_t denominator) {
  const bool negative = numerator < 0;
  const UnsignedDivision division =
      divideUnsigned(static_cast<std::uint64_t>(negative ? -numerator : numerator),
                     static_cast<std::uint64_t>(denominator));
  // The magnitude rounds up from half the denominator, a negative result's only past it.
  const std::uint64_t twice_remainder = 2 * division.remainder;
  const auto divisor = static_cast<std::uint64_t>(denominator);
  const bool up = negative ? twice_remainder > divisor : twice_remainder >= divisor;
  const auto magnitude = static_cast<std::int64_t>(division.quotient + (up ? 1 : 0));
  return negative ? -magnitude : magnitude;
}

// f rounded up to whole pixels plus half the larger side (pixels, f from Q.16): the most a unit's
// rounding in camera space, scaled by 1 + |c.x| / c.z, can move a screen position, per unit of 1/z.
std::int64_t focalAndHalfSide(std::int64_t focal_q16, std::int32_t width, std::int32_t height) {
  return (focal_q16 >> 16) + 1 + (std::max(width, height) + 1) / 2;
}

}  // namespace

std::int64_t nearPlaneFloor(std::int64_t focal_q16, std::int32_t width, std::int32_t height) {
  // Rounding a camera-space coordinate to the unit moves x = f * c.x / c.z by at most
  // f * (1/2) * (1 + |c.x| / c.z) / c.z pixels, and |c.x| / c.z <= (W / 2) / f on the screen:
  // (f + W / 2) / (2 z), at most 1/8 pixel from z = 4 (f + max(W, H) / 2) units on. f <= 2^16.
  return 4 * focalAndHalfSide(focal_q16, width, height);
}

int walkFractionBits(std::int64_t focal_q16, std::int32_t width, std::int32_t height,
                     std::int64_t near) {
  // f (Q.16) rounded up, plus half the larger side, times 68: below 2^24 for every frame.
  const std::int64_t need = 68 * focalAndHalfSide(focal_q16, width, height);
  int bits = 0;
  while (bits < kMaxWalkBits && (near << bits) < need) ++bits;
  return bits;
}

const char* describe(PerspectiveError error) {
  switch (error) {
    case PerspectiveError::kNone:
      return "ok";
    case PerspectiveError::kBadViewport:
      return "viewport size out of range";
    case PerspectiveError::kBadFieldOfView:
      return "field of view outside 10 to 120 degrees";
    case PerspectiveError::kBadNearPlane:
      return "near plane not greater than 0 or beyond 128 cube edges";
    case PerspectiveError::kEyeTooFar:
      return "eye farther than 128 cube edges from the model's centre";
    case PerspectiveError::kBadFractionBits:
      return "fraction bits out of range";
  }
  return "unknown error";
}

PerspectiveError buildPerspectiveView(const PerspectiveCamera& camera, int fraction_bits,
                                      PerspectiveView* view) {
  if (camera.width < 1 || camera.height < 1 || camera.width > kMaxViewportSide ||
      camera.height > kMaxViewportSide) {
    return PerspectiveError::kBadViewport;
  }
  if (fraction_bits < kMinFractionBits || fraction_bits > kMaxFractionBits)
    return PerspectiveError::kBadFractionBits;
  const std::int32_t fov = camera.fov.turns16();
  if (fov < Angle::fromDegrees(kMinFieldOfViewDegrees).turns16() ||
      fov > Angle::fromDegrees(kMaxFieldOfViewDegrees).turns16()) {
    return PerspectiveError::kBadFieldOfView;
  }
  constexpr std::int64_t kLimit = kMaxEyeDistance * kPerspectiveUnit;
  if (camera.near <= 0 || camera.near > kLimit) return PerspectiveError::kBadNearPlane;
  for (std::int64_t coordinate : {camera.eye.x, camera.eye.y, camera.eye.z}) {
    if (coordinate < -kLimit || coordinate > kLimit) return PerspectiveError::kEyeTooFar;
  }

  PerspectiveView built;
  built.camera = camera;
  built.fraction_bits = fraction_bits;
  // The eye's turns are camera to world, Ry(yaw) * Rx(pitch) * Rz(roll); points need the inverse,
  // its transpose Rz(-roll) * Rx(-pitch) * Ry(-yaw), which is the orbit camera's composition.
  built.world_to_camera = rotationFromYawPitchRoll(-camera.yaw, -camera.pitch, -camera.roll);
  // f = (height / 2) * cos(fov / 2) / sin(fov / 2), Q.16; half an odd angle unit is dropped
  // (0.003 degrees). At 10 degrees and 8192 rows f is 46,817 pixels: below 2^32 in Q.16.
  const Angle half = Angle::fromTurns16(fov / 2);
  const std::optional<std::int64_t> focal =
      divShiftRound(std::int64_t{camera.height} * cosQ30(half), 2 * std::int64_t{sinQ30(half)}, 16);
  if (!focal) return PerspectiveError::kBadFieldOfView;  // unreachable for 10..120 degrees
  built.focal_q16 = *focal;
  built.camera.near = std::max(camera.near, nearPlaneFloor(*focal, camera.width, camera.height));
  built.walk_bits = walkFractionBits(*focal, camera.width, camera.height, built.camera.near);
  built.centre_x = std::int64_t{camera.width} << (fraction_bits - 1);
  built.centre_y = std::int64_t{camera.height} << (fraction_bits - 1);
  *view = built;
  return PerspectiveError::kNone;
}

PerspectiveError orbitPerspective(const Camera& camera, Angle fov, int fraction_bits,
                                  PerspectiveView* view, std::int64_t near) {
  PerspectiveCamera perspective;
  perspective.near = near;
  perspective.width = camera.width;
  perspective.height = camera.height;
  perspective.fov = fov;
  // The orbit turns the model by R = Rz(roll) Rx(pitch) Ry(yaw); a perspective camera turned by
  // the opposite angles has R as its world-to-camera rotation.
  perspective.yaw = -camera.yaw;
  perspective.pitch = -camera.pitch;
  perspective.roll = -camera.roll;
  PerspectiveView built;
  if (const PerspectiveError error = buildPerspectiveView(perspective, fraction_bits, &built);
      error != PerspectiveError::kNone) {
    return error;
  }
  // A cube edge spans zoom * min(W, H) pixels in the orthographic view and f / D at distance D:
  // D = f / (zoom * min(W, H)) cube edges, Q.24 (the zoom is Q16.16, as f is).
  const std::int64_t pixels_per_edge_q16 =
      std::int64_t{camera.zoom.raw()} * std::min(camera.width, camera.height);
  if (pixels_per_edge_q16 <= 0) return PerspectiveError::kBadViewport;
  const std::optional<std::int64_t> distance =
      divShiftRound(built.focal_q16, pixels_per_edge_q16, kPerspectiveUnitBits);
  if (!distance || *distance > kMaxEyeDistance * kPerspectiveUnit)
    return PerspectiveError::kEyeTooFar;
  // The eye lies at -D along the line of sight, which in model space is R's third row.
  const Rotation turn = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
  const auto& row = turn.m_q30[2];
  perspective.eye = {roundShiftRight(-*distance * row[0], 30),
                     roundShiftRight(-*distance * row[1], 30),
                     roundShiftRight(-*distance * row[2], 30)};
  if (const PerspectiveError error = buildPerspectiveView(perspective, fraction_bits, &built);
      error != PerspectiveError::kNone) {
    return error;
  }
  built.centre_x += std::int64_t{camera.pan_x_px} << fraction_bits;
  built.centre_y += std::int64_t{camera.pan_y_px} << fraction_bits;
  *view = built;
  return PerspectiveError::kNone;
}

namespace {

// The camera-space position of `point` rounded once to 2^-bits units (bits 0..kMaxWalkBits).
CameraPoint rotateAboutEye(const PerspectiveView& view, const ModelPoint& point, int bits) {
  // |point| <= one cube edge and |eye| <= 128 edges: |d| < 2^31.1, each product below 2^61.1,
  // each sum of three below 2^62.7.
  assert(magnitude(point.x) <= kPerspectiveUnit && magnitude(point.y) <= kPerspectiveUnit &&
         magnitude(point.z) <= kPerspectiveUnit);
  const std::int64_t d[3] = {point.x - view.camera.eye.x, point.y - view.camera.eye.y,
                             point.z - view.camera.eye.z};
  std::int64_t c[3];
  for (int row = 0; row < 3; ++row) {
    const auto& m = view.world_to_camera.m_q30[row];
    c[row] = roundShiftRight(m[0] * d[0] + m[1] * d[1] + m[2] * d[2], 30 - bits);
  }
  return {c[0], c[1], c[2]};
}

}  // namespace

CameraPoint toCameraSpace(const PerspectiveView& view, const ModelPoint& point) {
  return rotateAboutEye(view, point, 0);
}

CameraPoint toWalkSpace(const PerspectiveView& view, const ModelPoint& point) {
  return rotateAboutEye(view, point, view.walk_bits);
}

std::optional<ScreenPoint> project(const PerspectiveView& view, const CameraPoint& point) {
  if (point.z < view.camera.near) return std::nullopt;
  // Below 2^30 each, so that f (Q.16, below 2^32) times a coordinate fits int64: far points lose
  // their low bits together, a relative error of 2^-30 at most (2^-17 pixel on an 8192 screen).
  const std::int64_t largest = std::max({magnitude(point.x), magnitude(point.y), point.z});
  int shift = 0;
  while ((largest >> shift) >= kQ30One) ++shift;
  const std::int64_t x = roundShiftRight(point.x, shift);
  const std::int64_t y = roundShiftRight(point.y, shift);
  const std::int64_t z = roundShiftRight(point.z, shift);
  if (z <= 0) return std::nullopt;
  // Q(32-F).F: f * x / z * 2^F with f in Q.16, rounded once.
  const int scale = view.fraction_bits - 16;
  const std::optional<std::int64_t> dx = divScaled(view.focal_q16 * x, z, scale);
  const std::optional<std::int64_t> dy = divScaled(view.focal_q16 * y, z, scale);
  if (!dx || !dy) return std::nullopt;
  const std::int64_t screen_x = view.centre_x + *dx, screen_y = view.centre_y + *dy;
  if (!fitsInt32(screen_x) || !fitsInt32(screen_y)) return std::nullopt;
  return ScreenPoint{static_cast<std::int32_t>(screen_x), static_cast<std::int32_t>(screen_y),
                     point.z};
}

std::optional<std::int64_t> affineErrorBound(const PerspectiveView& view, const CameraPoint& centre,
                                             std::int64_t reach) {
  assert(reach >= 0 && reach < (std::int64_t{1} << 32));
  if (centre.z - reach < view.camera.near) return std::nullopt;
  // f * (r / z)^2 * (m + z) / (z - r), every factor rounded up: a = r / z in Q.30, b = (m + z) /
  // (z - r) in Q.16, then f * a^2 in Q.16 pixels and times b in Q(32-F).F.
  const std::int64_t off_axis = std::max(magnitude(centre.x), magnitude(centre.y));
  const std::optional<std::int64_t> a = divShiftRound(reach, centre.z, 30);
  const std::optional<std::int64_t> b = divShiftRound(off_axis + centre.z, centre.z - reach, 16);
  if (!a || !b) return std::nullopt;
  const std::optional<std::int64_t> a_squared = mulShiftRound(*a + 1, *a + 1, 30);
  if (!a_squared) return std::nullopt;
  const std::optional<std::int64_t> f_a_squared = mulShiftRound(view.focal_q16, *a_squared + 1, 30);
  if (!f_a_squared) return std::nullopt;
  const std::optional<std::int64_t> bound =
      mulShiftRound(*f_a_squared + 1, *b + 1, 32 - view.fraction_bits);
  if (!bound || *bound == INT64_MAX) return std::nullopt;
  return *bound + 1;
}

std::optional<AffineProjection> affineAt(const PerspectiveView& view, const CameraPoint& centre) {
  AffineProjection affine;
  if (!affineAtInto(view, centre, &affine)) return std::nullopt;
  return affine;
}

bool affineAtInto(const PerspectiveView& view, const CameraPoint& centre,
                  AffineProjection* affine_out) {
  if (centre.z < view.camera.near) return false;
  assert(magnitude(centre.x) < (std::int64_t{1} << 32) &&
         magnitude(centre.y) < (std::int64_t{1} << 32));
  // f / z in Q.16 pixels per cube edge; the slopes x / z and y / z in Q.30: three hardware
  // divisions (numerators below 2^62), this runs once per subtree drawn from its map.
  const std::int64_t z = centre.z;
  const std::int64_t inverse = divideRounded(view.focal_q16 << kPerspectiveUnitBits, z);
  const std::int64_t slope_x = divideRounded(centre.x * kQ30One, z);
  const std::int64_t slope_y = divideRounded(centre.y * kQ30One, z);
  // The centre's projection f * slope, Q.16 * Q.30 to Q(32-F).F: within 1/2 ulp plus f * 2^-31
  // pixel of the exact one (the slope's rounding).
  const int shift = 46 - view.fraction_bits;
  // mulShiftRoundQuick's choice with f's bits counted once: significantBits(slope) <= 62 - those.
  const int slope_bits = 62 - significantBits(view.focal_q16);
  const auto offset = [&](std::int64_t slope) -> std::optional<std::int64_t> {
    if (within(slope, slope_bits)) return mulShiftRoundSmall(view.focal_q16, slope, shift);
    return mulShiftRound(view.focal_q16, slope, shift);
  };
  const std::optional<std::int64_t> dx = offset(slope_x);
  const std::optional<std::int64_t> dy = offset(slope_y);
  if (!dx || !dy) return false;
  const std::int64_t screen_x = view.centre_x + *dx, screen_y = view.centre_y + *dy;
  if (!fitsInt32(screen_x) || !fitsInt32(screen_y)) return false;
  AffineProjection& affine = *affine_out;
  affine.centre = {static_cast<std::int32_t>(screen_x), static_cast<std::int32_t>(screen_y), z};
  const auto& m = view.world_to_camera.m_q30;
  // The projection's derivative along w: (f / z) * (w.x - (x / z) * w.z), likewise for y. With
  // |slope| < 2 (31 bits, Q.30) and f / z below 2^30 (Q.16), every product below fits int64
  // (|w| <= 2^30, |w - tilt| < 2^32): one multiplication each, no check per product.
  if (within(slope_x, 31) && within(slope_y, 31) && within(inverse, 30)) {
    for (int a = 0; a < 3; ++a) {
      const std::int64_t w_z = m[2][a];
      affine.axis[a] = {
          mulShiftRoundSmall(inverse, m[0][a] - mulShiftRoundSmall(slope_x, w_z, 30), shift),
          mulShiftRoundSmall(inverse, m[1][a] - mulShiftRoundSmall(slope_y, w_z, 30), shift),
          roundShiftRight(w_z, 30 - kPerspectiveUnitBits)};
    }
    return true;
  }
  for (int a = 0; a < 3; ++a) {
    const std::int64_t w_x = m[0][a], w_y = m[1][a], w_z = m[2][a];
    const std::optional<std::int64_t> tilt_x = mulShiftRoundQuick(slope_x, w_z, 30);
    const std::optional<std::int64_t> tilt_y = mulShiftRoundQuick(slope_y, w_z, 30);
    if (!tilt_x || !tilt_y) return false;
    const std::optional<std::int64_t> x = mulShiftRoundQuick(inverse, w_x - *tilt_x, shift);
    const std::optional<std::int64_t> y = mulShiftRoundQuick(inverse, w_y - *tilt_y, shift);
    if (!x || !y) return false;
    affine.axis[a] = {*x, *y, roundShiftRight(w_z, 30 - kPerspectiveUnitBits)};
  }
  return true;
}

std::int64_t rotatedCubeReach(std::int64_t half) {
  // 1774 / 1024 = 1.73242 >= sqrt(3) = 1.73205.
  return (half * 1774 + 1023) >> 10;
}

}  // namespace octopoint

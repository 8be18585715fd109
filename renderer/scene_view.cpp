#include "renderer/scene_view.h"

#include <algorithm>
#include <climits>

#include "fixedpoint/trig.h"

namespace octopoint {
namespace {

// An instance farther than this many of its own cube edges from the eye on a scene axis is beyond
// the draw distance: turned about y, its eye would lie beyond kMaxEyeDistance edges on some model
// axis (256 / sqrt(2) > 128). Q.24 cube edges; every coordinate below it keeps a rotated sum of
// three Q1.30 products below 2^63.
constexpr std::int64_t kBoxLimit = 2 * kMaxEyeDistance * kPerspectiveUnit;  // 2^32

// a / 2^scale in the model's units: floor for a positive scale (the box's reach takes the unit
// lost), exact for a negative one (|a| is then small enough: checked by the caller).
std::int64_t toModelUnits(std::int64_t a, int scale) {
  return scale >= 0 ? a >> scale : a * (std::int64_t{1} << -scale);
}

// Scene units to a model's for a length that must stay positive (the near plane).
std::int64_t lengthToModelUnits(std::int64_t length, int scale) {
  return std::max<std::int64_t>(
      1, scale >= 0 ? roundShiftRight(length, scale) : length * (std::int64_t{1} << -scale));
}

bool withinBox(const Point3<std::int64_t>& d, int scale) {
  // Compared in scene units before any shift: kBoxLimit * 2^scale fits (scale <= 8: 2^40).
  const std::int64_t limit = scale >= 0 ? kBoxLimit << scale : kBoxLimit >> -scale;
  return d.x >= -limit && d.x <= limit && d.y >= -limit && d.y <= limit && d.z >= -limit &&
         d.z <= limit;
}

}  // namespace

int sceneDepthShift(int largest_scale) {
  return kPerspectiveDepthShift + std::max(0, largest_scale);
}

std::optional<InstanceBox> instanceBox(const PerspectiveView& scene_view,
                                       const InstanceTransform& transform) {
  const Point3<std::int64_t> d{transform.at.x - scene_view.camera.eye.x,
                               transform.at.y - scene_view.camera.eye.y,
                               transform.at.z - scene_view.camera.eye.z};
  if (!withinBox(d, transform.scale)) return std::nullopt;
  const std::int64_t q[3] = {toModelUnits(d.x, transform.scale), toModelUnits(d.y, transform.scale),
                             toModelUnits(d.z, transform.scale)};
  const auto& m = scene_view.world_to_camera.m_q30;
  std::int64_t c[3];
  for (int row = 0; row < 3; ++row) {
    // |q| <= 2^32 on every axis and a row of a rotation has length 1 (within ulps): every partial
    // sum below 2^62.9.
    c[row] = roundShiftRight(m[row][0] * q[0] + m[row][1] * q[1] + m[row][2] * q[2], 30);
  }
  InstanceBox box;
  box.centre = {c[0], c[1], c[2]};
  // The model cube's half edge rotated, plus the floor's unit, the rounding and the rotation's
  // ulps (a few units at 2^32).
  box.reach = rotatedCubeReach(kPerspectiveUnit / 2) + 4;
  return box;
}

bool instanceOutsideFrustum(const PerspectiveView& scene_view, const PerspectiveWalkTables& tables,
                            const InstanceTransform& transform, const InstanceBox& box) {
  // The side slopes are ratios x / z: the same in any unit. The near plane in the model's units.
  return outsideFrustumSides(tables, box.centre, box.reach,
                             lengthToModelUnits(scene_view.camera.near, transform.scale));
}

bool instanceHidden(const PerspectiveView& scene_view, const InstanceTransform& transform,
                    const InstanceBox& box, int model_depth_shift, OcclusionTiles& tiles) {
  const std::int64_t nearest = box.centre.z - box.reach;  // Q.24 model cube edges
  if (nearest < lengthToModelUnits(scene_view.camera.near, transform.scale) || nearest <= 0)
    return false;
  // The box's corners on the screen (x / z and y / z are monotonic on it, z > 0): their bounds hold
  // its projection. The near plane is checked above in the model's units; project's own check in
  // the scene's is not meant here, so it is given a view without one.
  PerspectiveView ratios = scene_view;
  ratios.camera.near = 1;
  std::int64_t low_x = INT64_MAX, high_x = INT64_MIN, low_y = INT64_MAX, high_y = INT64_MIN;
  for (int corner = 0; corner < 8; ++corner) {
    const CameraPoint point{box.centre.x + (corner & 1 ? box.reach : -box.reach),
                            box.centre.y + (corner & 2 ? box.reach : -box.reach),
                            box.centre.z + (corner & 4 ? box.reach : -box.reach)};
    const std::optional<ScreenPoint> screen = project(ratios, point);
    if (!screen) return false;
    low_x = std::min<std::int64_t>(low_x, screen->x);
    high_x = std::max<std::int64_t>(high_x, screen->x);
    low_y = std::min<std::int64_t>(low_y, screen->y);
    high_y = std::max<std::int64_t>(high_y, screen->y);
  }
  // Q(32-F).F to pixels, widened by two.
  const int f = scene_view.fraction_bits;
  const std::int64_t x0 = std::max<std::int64_t>(0, (low_x >> f) - 2);
  const std::int64_t x1 = std::min<std::int64_t>(tiles.width() - 1, (high_x >> f) + 2);
  const std::int64_t y0 = std::max<std::int64_t>(0, (low_y >> f) - 2);
  const std::int64_t y1 = std::min<std::int64_t>(tiles.height() - 1, (high_y >> f) + 2);
  if (x0 > x1 || y0 > y1) return false;  // off the frame: the frustum test's to judge
  // Every point's key is at least the nearest's (keys are z >> shift, capped), less one for the
  // model view's eye, rounded apart from the box's: every word of the box at least this one.
  const std::uint64_t key = std::min<std::uint64_t>(
      static_cast<std::uint64_t>(nearest) >> model_depth_shift, FrameView::kMaxDepthKey);
  const std::uint32_t word = FrameView::packLeaf<PixelPayload::kColour>(
      static_cast<std::uint32_t>(key > 0 ? key - 1 : 0), 0);
  return tiles.hidden(static_cast<std::int32_t>(x0), static_cast<std::int32_t>(x1),
                      static_cast<std::int32_t>(y0), static_cast<std::int32_t>(y1), word);
}

PerspectiveError instanceView(const PerspectiveView& scene_view, const InstanceTransform& transform,
                              int scene_depth_shift, PerspectiveView* view) {
  const PerspectiveCamera& camera = scene_view.camera;
  const Point3<std::int64_t> d{camera.eye.x - transform.at.x, camera.eye.y - transform.at.y,
                               camera.eye.z - transform.at.z};
  if (!withinBox(d, transform.scale)) return PerspectiveError::kEyeTooFar;
  // Ry(-turn) * d / 2^scale: x' = c x - s z, z' = s x + c z (c, s: cos and sin of the turn, Q1.30),
  // each product rounded once (|d| <= 2^40 makes c x up to 2^70: mulShiftRound's wide product);
  // exact at quarter turns, where c and s are 0 and +-1.
  const std::int64_t c = cosQ30(transform.turn), s = sinQ30(transform.turn);
  const int shift = 30 + transform.scale;  // 22..38
  const auto product = [shift](std::int64_t a, std::int64_t b) {
    return mulShiftRound(a, b, shift).value_or(0);  // |a b| / 2^shift <= 2^40: always fits
  };
  PerspectiveCamera model_camera = camera;
  model_camera.eye = {product(d.x, c) - product(d.z, s), product(d.y, std::int64_t{1} << 30),
                      product(d.x, s) + product(d.z, c)};
  model_camera.yaw = camera.yaw - transform.turn;
  model_camera.near = lengthToModelUnits(camera.near, transform.scale);
  PerspectiveView built;
  if (const PerspectiveError error =
          buildPerspectiveView(model_camera, scene_view.fraction_bits, &built);
      error != PerspectiveError::kNone) {
    return error;
  }
  built.centre_x = scene_view.centre_x;  // the scene view's principal point (a pan)
  built.centre_y = scene_view.centre_y;
  built.depth_shift = scene_depth_shift - transform.scale;
  *view = built;
  return PerspectiveError::kNone;
}

}  // namespace octopoint

#pragma once
// The perspective camera's integer core: where the eye is, how a point of the model projects, and
// how far a subtree's projection is from the affine map at its centre (docs/perspective.md).
//
// Units and Q formats:
// - Model space: the model cube [-1/2, 1/2)^3 centred on the origin, in the scan's camera frame
//   (x right, y down, z away: the orthographic camera's frame), in Q.24 cube edges (int64). A
//   voxel of depth 16 is 2^8 units, its centre 2^7 units from its corner: exact.
// - Camera space: the same units, rotated so that the eye looks along +z, x right, y down.
// - Screen: Q(32-F).F pixels (F = fraction_bits), the orthographic decoders' format; depth is the
//   camera-space z in Q.24 cube edges.
//
// Projection: x = width / 2 + f * c.x / c.z, y = height / 2 + f * c.y / c.z with the focal length
// f = (height / 2) / tan(fov / 2) pixels. The per-level displacement vectors of the decoders are
// affine, which a perspective projection is not; around a camera-space centre c the projection of
// c + d differs from its affine (first-order) map by
//   err_x = f * d.z * (c.x * d.z - d.x * c.z) / (c.z^2 * (c.z + d.z)),
// so for a box whose every point has |d.x|, |d.y|, |d.z| <= r, in front of the eye (c.z > r):
//   |err_x| <= f * r^2 * (|c.x| + c.z) / (c.z^2 * (c.z - r)),
// and the same with c.y for y: about f * (r / z)^2 pixels near the view's axis. That bound decides
// where a walk may add vectors and where it must project anew.

#include <bit>
#include <cstdint>
#include <optional>

#include "octopoint/camera.h"
#include "octopoint/fixed.h"

namespace octopoint {

inline constexpr int kPerspectiveUnitBits = 24;  // Q.24 cube edges
inline constexpr std::int64_t kPerspectiveUnit = std::int64_t{1} << kPerspectiveUnitBits;
// The eye lies within this many cube edges of the cube's centre on every axis: then every
// camera-space coordinate of a model point is a sum of three products below 2^62 (exact in int64).
inline constexpr std::int64_t kMaxEyeDistance = 128;
inline constexpr int kMinFieldOfViewDegrees = 10;
inline constexpr int kMaxFieldOfViewDegrees = 120;
// The depth key a perspective leaf writes: camera-space z in units of 2^-14 cube edge (z >> 10),
// which keeps every z the eye can see (below 2^33.5 units) within FrameView::kMaxDepthKey.
inline constexpr int kPerspectiveDepthShift = 10;

// The number of bits |v| takes (0 for 0, 64 for INT64_MIN).
inline int significantBits(std::int64_t v) {
  return std::bit_width(v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v)
                              : static_cast<std::uint64_t>(v));
}

// round(a * b / 2^shift), ties toward +infinity as mulShiftRound rounds, by one 64-bit
// multiplication: only where significantBits(a) + significantBits(b) <= 62 and 1 <= shift <= 62
// (the product and the rounding half then fit int64).
inline std::int64_t mulShiftRoundSmall(std::int64_t a, std::int64_t b, int shift) {
  return (a * b + (std::int64_t{1} << (shift - 1))) >> shift;  // >> of a negative is floor
}

// mulShiftRound's result, by mulShiftRoundSmall where the operands are that small and by
// mulShiftRound's wide product otherwise: most of the walk's products are that small, and the
// wide one costs tens of instructions.
[[nodiscard]] inline std::optional<std::int64_t> mulShiftRoundQuick(std::int64_t a, std::int64_t b,
                                                                    int shift) {
  if (shift >= 1 && shift <= 62 && significantBits(a) + significantBits(b) <= 62)
    return mulShiftRoundSmall(a, b, shift);
  return mulShiftRound(a, b, shift);
}

// 2^(62 - significantBits(b)), 0 where b takes more than 62 bits: a factor a with |a| below it
// meets mulShiftRoundSmall's condition significantBits(a) + significantBits(b) <= 62. Made once
// for a factor that many products share, so that each product compares instead of counting a's
// bits (a library call per count on a Cortex-M0+, which has no CLZ instruction).
inline std::int64_t smallProductLimit(std::int64_t b) {
  const int bits = significantBits(b);
  return bits > 62 ? 0 : std::int64_t{1} << (62 - bits);
}

// mulShiftRoundQuick(a, b, shift) for a b whose smallProductLimit is `limit`: the same bits.
[[nodiscard]] inline std::optional<std::int64_t> mulShiftRoundLimited(std::int64_t a,
                                                                      std::int64_t b,
                                                                      std::int64_t limit,
                                                                      int shift) {
  if (shift >= 1 && shift <= 62 && a > -limit && a < limit) return mulShiftRoundSmall(a, b, shift);
  return mulShiftRound(a, b, shift);
}

using ModelPoint = Point3<std::int64_t>;   // Q.24 cube edges, model space
using CameraPoint = Point3<std::int64_t>;  // Q.24 cube edges, camera space

struct PerspectiveCamera {
  ModelPoint eye{0, 0, -2 * kPerspectiveUnit};  // Q.24 cube edges: two edges before the cube
  Angle yaw;                           // turns the view right (towards +x); 0 looks along +z
  Angle pitch;                         // turns the view up (towards -y)
  Angle roll;                          // turns the picture clockwise
  Angle fov = Angle::fromDegrees(60);  // vertical field of view, 10 to 120 degrees
  // Q.24 cube edges, > 0: nearer points are not drawn. A camera built for a model takes
  // nearPlaneForDepth of its finest depth; this default (1/64 edge) is for a bare camera.
  std::int64_t near = kPerspectiveUnit / 64;
  std::int32_t width = 320;
  std::int32_t height = 240;
};

// The near plane a model of finest stored depth `depth` (1..16) is seen with: half that depth's
// voxel edge, Q.24 cube edges (2^(23 - depth), at least 2^7). A leaf whose centre lies that near
// spans twice the focal length in pixels (its edge at half an edge's distance: the frame's height
// at a 90 degree field of view), so only leaves that cover most of the frame are left out, and the
// ground at the eye's feet and what is right before it are drawn.
constexpr std::int64_t nearPlaneForDepth(int depth) {
  const int clamped = depth < 1 ? 1 : depth > 16 ? 16 : depth;
  return kPerspectiveUnit >> (clamped + 1);
}

enum class PerspectiveError : std::uint8_t {
  kNone,
  kBadViewport,      // width or height outside 1..kMaxViewportSide
  kBadFieldOfView,   // outside 10..120 degrees
  kBadNearPlane,     // near <= 0 or farther than kMaxEyeDistance cube edges
  kEyeTooFar,        // an eye coordinate beyond kMaxEyeDistance cube edges
  kBadFractionBits,  // outside kMinFractionBits..kMaxFractionBits
};

const char* describe(PerspectiveError error);

// One frame's perspective view, built once (buildPerspectiveView) and only read afterwards.
struct PerspectiveView {
  PerspectiveCamera camera;
  Rotation world_to_camera;    // Q1.30
  std::int64_t focal_q16 = 0;  // f in pixels, Q.16
  int fraction_bits = kDefaultFractionBits;
  std::int64_t centre_x = 0;  // width / 2, Q(32-F).F
  std::int64_t centre_y = 0;  // height / 2, Q(32-F).F
  // A leaf's depth key is its camera-space z >> depth_shift. A scene of many models
  // (renderer/scene_renderer.h) draws a model scaled by 2^s with depth_shift + s of the scene's
  // own, so that every instance's keys measure the same distance in one z-buffer.
  int depth_shift = kPerspectiveDepthShift;
  // The walk (renderer/perspective_walk.h) carries camera-space positions in Q.(24 + walk_bits)
  // cube edges, so that the rounding of its per-level child offsets, up to half a Q.(24 +
  // walk_bits) unit per addition, stays below 1/8 pixel (walkFractionBits). 0 where the
  // Q.24 unit is fine enough (most views: their frames are those of a walk in Q.24).
  int walk_bits = 0;
};

// The least near plane a view keeps, Q.24 cube edges: 4 (f + max(W, H) / 2) units for the focal
// length f (Q.16 pixels), where rounding a camera-space coordinate to the unit moves a point's
// projection on the screen by at most 1/8 pixel. Below the bare camera's 1/64 edge at every size
// and field of view (203,660 units at 8192 rows and 10 degrees). buildPerspectiveView raises a
// nearer plane to it: a 1 km cube's unit is 60 micrometres, and at a few thousand units from the
// eye the rounding of the eye and the points alone would move them by a pixel and more.
std::int64_t nearPlaneFloor(std::int64_t focal_q16, std::int32_t width, std::int32_t height);

// The least number of sub-unit bits S (0..kMaxWalkBits) with which the walk's rounding stays below
// 1/8 pixel at the near plane `near` (Q.24 cube edges): a leaf of depth 16 is the root's rounding
// plus 16 child offsets, each within half a Q.(24 + S) unit per axis, 17 / 2^(S + 1) units in
// all, which move its projection by at most (f + max(W, H) / 2) / near pixels per unit (as
// nearPlaneFloor's): 68 (f + max(W, H) / 2) <= near * 2^S. Without them (S = 0), near a large
// model's near plane a leaf could be 2 pixels off (f / near grows with the frame).
inline constexpr int kMaxWalkBits = 8;
int walkFractionBits(std::int64_t focal_q16, std::int32_t width, std::int32_t height,
                     std::int64_t near);

// The camera-space position of a model point in the walk's units, Q.(24 + view.walk_bits): as
// toCameraSpace, rounded once to that unit.
CameraPoint toWalkSpace(const PerspectiveView& view, const ModelPoint& point);

[[nodiscard]] PerspectiveError buildPerspectiveView(const PerspectiveCamera& camera,
                                                    int fraction_bits, PerspectiveView* view);

// The orbit camera of the orthographic view (`camera`: its turn, zoom, pan and size) seen in
// perspective with the field of view `fov`: the eye on the line of sight through the cube's
// centre, at the distance where a cube edge at the centre's depth spans as many pixels as in the
// orthographic view, so that a narrow field of view converges to its picture; the pan moves the
// picture as it does there. kEyeTooFar when that distance exceeds kMaxEyeDistance cube edges.
// `near` is the camera's near plane (Q.24 cube edges).
[[nodiscard]] PerspectiveError orbitPerspective(const Camera& camera, Angle fov, int fraction_bits,
                                                PerspectiveView* view,
                                                std::int64_t near = PerspectiveCamera{}.near);

// The camera-space position of a model point within kMaxEyeDistance cube edges of the centre:
// each coordinate rounded once to the nearest unit (error <= 1/2 unit plus the rotation's).
CameraPoint toCameraSpace(const PerspectiveView& view, const ModelPoint& point);

struct ScreenPoint {
  std::int32_t x = 0;  // Q(32-F).F pixels
  std::int32_t y = 0;
  std::int64_t z = 0;  // camera-space depth, Q.24 cube edges
};

// The projection of a camera-space point, each coordinate within 1/2 + 2^-10 unit in the last
// place of the exact projection of that point; nullopt when it lies nearer than the near plane or
// projects beyond what Q(32-F).F holds (far outside the screen).
std::optional<ScreenPoint> project(const PerspectiveView& view, const CameraPoint& point);

// The bound above, in Q(32-F).F pixels rounded up, for a box of half-extent `reach` (every point
// within `reach` units of `centre` on every camera axis); nullopt when the box reaches the near
// plane (or its centre is so near the eye that the bound does not fit int64).
std::optional<std::int64_t> affineErrorBound(const PerspectiveView& view, const CameraPoint& centre,
                                             std::int64_t reach);

// The first-order map of the projection at a camera-space centre: a model-space displacement d
// (Q.24 cube edges) lands at centre + sum over axes a of axis[a] * d_a / 2^24 on screen.
struct AffineProjection {
  ScreenPoint centre;
  // axis[a]: the screen displacement of one cube edge along model axis a: x and y in Q(32-F).F
  // pixels, z in Q.24 cube edges (int64: near the eye one edge spans millions of pixels).
  Point3<std::int64_t> axis[3];
};

// Its centre is within 1/2 unit in the last place plus f * 2^-31 pixel of the exact projection
// (f the focal length in pixels: below 0.71 ulp of Q17.15 at any field of view and height).
// nullopt when `centre` lies nearer than the near plane, projects beyond what Q(32-F).F holds, or
// an axis vector does not fit int64.
std::optional<AffineProjection> affineAt(const PerspectiveView& view, const CameraPoint& centre);
// The same map written to `*affine` (false, and *affine unspecified, where affineAt gives
// nullopt): the walk's form, which does not copy the map out of an optional per subtree.
bool affineAtInto(const PerspectiveView& view, const CameraPoint& centre, AffineProjection* affine);

// A rotated cube of half-edge `half` (Q.24) reaches at most this far on any camera axis
// (half * sqrt(3), rounded up).
std::int64_t rotatedCubeReach(std::int64_t half);

}  // namespace octopoint

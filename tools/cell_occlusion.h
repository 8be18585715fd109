#pragma once
// The instances one sample point stands for, by an eroded occlusion map (docs/city.md, "Visibility
// cells"; after Wonka, Wimmer and Schmalstieg 2000, "Visibility preprocessing with occluder fusion
// for urban walkthroughs"). A sample e stands for every eye within `eps` of it. From e the scene is
// drawn to the six faces of a cube (each widened by a border, so that every direction lies at least
// the erosion's radius inside some face); per face, the occlusion map:
//  - every pixel whose surface is nearer than `near` (camera-space z) is empty: near occluders do
//    not occlude (from an eye eps away they move by up to eps / near radians, unbounded in pixels);
//  - a crack: both pixels of every pair of 4-neighbours between which the surface jumps: where
//    the lines through 1/z of the two pixels before and the two after (1/z is affine across a
//    plane in screen space) do not cross between them, and miss each other there by more than
//    kLeastGap / eps of 1/z (plus the voxels' rounding): a gap between two surfaces at different
//    depths that touch from e opens from an eye eps away (by eps times the jump in 1/z, radians),
//    while a slanted plane, or two meeting at a crease, stays closed;
//  - then the farthest word over a square window of `rho` pixels around each pixel, rho covering
//    asin(eps / near) at the faces' corners (+1 pixel for the grid), and empty where the window
//    leaves the face;
//  - or (OcclusionSampling::depth_windows) a window sized by the depths inside it: the smallest
//    radius r whose window's nearest surface, at depth d, needs no more than r (asin(eps / d) at
//    that pixel's offset from the face's axis): an occluder at depth d is eroded by eps at its own
//    depth (Wonka et al.'s object-space erosion), not at the nearest depth one may have. Why it is
//    as conservative: the segment from an eye e' within eps to a point P behind the map leaves
//    the ball of radius d about e once and then only moves away from e (its distance from e is
//    convex along it and already grown past eps), at distance t within asin(eps / t) <=
//    asin(eps / d) of P's direction: inside the window. There it is in front of every surface of
//    the window (all at least d away) and at P behind the one on P's ray, so it crosses the
//    window's cap of surfaces, which has no crack: P is hidden from e'. The ground's pixels are no
//    surfaces for d (the segment never passes behind one: it stays above the plane); a window of
//    ground alone is sized 1. docs/city.md has the whole argument;
//  - with a ground plane (OcclusionSampling::ground): a pixel whose surface lies on it (and is no
//    crack) is neither near nor a candidate for the farthest word: a point behind the ground as
//    seen from e is below it, where no segment from an eye above it to a point above it passes
//    (docs/city.md); a window of ground alone keeps the pixel's own word.
// Every instance with a point nearer than the map at its pixel (tested alone, not against the
// others: SceneRenderer::markWriters) is in the sample's set. Why that is conservative for every
// eye within eps: docs/city.md. eps 0: no erosion, no cracks (the map is the nearest surface
// beyond `near`): the sample's own view. Host side; the frames are sized once.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/framebuffer.h"
#include "renderer/scene_renderer.h"

namespace octopoint {

// The narrowest gap the crack rule looks for, Q.24 scene edges: 1/512 scene edge, 6 cm in the
// generated city, a voxel of its buildings' finest depth (9): narrower gaps the splats close.
inline constexpr std::int64_t kLeastGap = kPerspectiveUnit / 512;

struct OcclusionSampling {
  std::int64_t eps = 0;   // Q.24 scene edges: the eyes a sample stands for
  std::int64_t near = 0;  // Q.24 scene edges: surfaces nearer do not occlude; > eps
  int face = 128;         // pixels of a cube face's side, without the border
  // Maps at near, 2 near, ... 2^(steps - 1) near, each eroded by its own radius: a sample's set
  // is what every one of them lets in (near walls occlude in the first, the far city's small
  // gaps stay open in the last).
  int near_steps = 1;
  // The scene's ground: the plane y = ground_y (Q.24 scene edges, y down), every eye above it and
  // no instance's point below it (the generated city's street and pavement tiles at y = 0).
  bool ground = false;
  std::int64_t ground_y = 0;
  // Q.24 scene edges: the edge of the ground's finest voxels (a splat's depth strays from the
  // plane by up to one): 1/512 scene edge in the generated city.
  std::int64_t ground_voxel = kLeastGap;
  // The erosion's radius per pixel (erosionRadii: narrower towards the face's centre) rather
  // than the corner's everywhere.
  bool radii = false;
  // Each pixel's window sized by the nearest depth in it (DepthWindows): supersedes `radii`. The
  // border then fits 120 degrees whatever near is (a window wider than the frame: empty), so
  // near may be nearly eps (a wall across the street occludes where its windows fit).
  bool depth_windows = false;
};

// The erosion's radius in pixels for `sampling` (0 when eps is 0).
int erosionRadius(const OcclusionSampling& sampling);
// Whether the face widened by the erosion's border stays within the camera's field of view (120
// degrees: a border of at most about a third of the face each way, eps / near up to about 0.2;
// with depth windows the border is cut to fit, so only near > eps is asked).
bool erosionFits(const OcclusionSampling& sampling);

// The erosion's radius by depth for a widened face (side x side pixels): per pixel, the window a
// nearest surface at depth key k needs, ceil(reach / pixel) + 1 with reach the image's move under
// a turn of asin(eps / z) (z = k << depth_shift, the key's nearer end: the turn is never
// underestimated) at that pixel's offset from the face's axis, as erosionRadii.
// Depths are read in buckets of a 256th of a key (the bucket's nearest key: a wider window).
class DepthWindows {
 public:
  DepthWindows(const OcclusionSampling& sampling, int side, int depth_shift);
  // At most widest() + 1 (a window that leaves the frame wherever it is centred).
  int radius(std::size_t pixel, std::uint32_t key) const;
  int widest() const { return widest_; }  // the widest window a frame holds: (side - 1) / 2

 private:
  int widest_ = 0;
  double unit_ = 1;             // a pixel in x/z units
  std::vector<double> angle_;   // per depth bucket: asin(eps / z) at its nearest key, radians
  std::vector<double> offset_;  // per pixel: its x/z offset from the face's axis
};

// The occlusion map of a face's words (width x height, row-major, PixelPayload::kColour) into
// `map`: near pixels and cracks empty, then the farthest word within `rho` (empty where the window
// leaves the face). `near_key`: the depth key of the near distance; `eps`: for the crack rule
// (0: no cracks); `face`: pixels of the face's side without its border (the voxels' rounding).
// `scratch`: any vector, resized once; after the call its first width x height words are the
// map before the erosion (ground pixels kGroundWord). `ground`: empty, or width x height flags,
// 1 where the pixel's surface is the ground plane (groundMask). `radius`: empty, or per pixel its
// window's radius (erosionRadii); `depth`: null, or each window sized by the depths in it (then
// `radius` is not read).
inline constexpr std::uint32_t kGroundWord = 0;  // below every word: never a window's farthest
void occlusionMap(std::span<const std::uint32_t> words, std::int32_t width, std::int32_t height,
                  std::uint32_t near_key, std::int64_t eps, int face, int rho,
                  std::span<std::uint32_t> map, std::vector<std::uint32_t>& scratch,
                  std::span<const std::uint8_t> ground = {},
                  std::span<const std::uint8_t> radius = {}, const DepthWindows* depth = nullptr);

// Per pixel of a widened face (side x side), the erosion's radius there, at most
// erosionRadius(sampling): a turn of asin(eps / near) moves a direction's image by a factor
// 1 + t^2 (t: its x/z offset from the face's axis), 3 at the face's corner, 1 at its centre, so
// the window need only be that wide around each pixel (`radius` for occlusionMap; empty: the
// corner's radius everywhere).
void erosionRadii(const OcclusionSampling& sampling, int side, std::span<std::uint8_t> radius);

// The pixels of a face (camera `view`, whose pitch is 0 or +-90 degrees) whose surface lies on
// the plane y = ground_y (Q.24, y down), into `mask` (1 each): the pixel's point, its depth key's
// nearer end along its ray, within the voxels' rounding of the plane (half a face pixel at its
// depth, plus the ground's finest voxel `voxel` and a depth key's step). Host side (double):
// where the map's maximum looks, not a frame.
void groundMask(const FrameView& frame, const PerspectiveView& view, int face,
                std::int64_t ground_y, std::int64_t voxel, int depth_shift,
                std::span<std::uint8_t> mask);

// The heights (Q.24 scene edges, y down: top <= bottom) of the eyes a sample stands for; none
// (top > bottom) by default.
struct EyeSlab {
  std::int64_t top = 1, bottom = 0;
};

// What the maps held, summed over the samples looked from: pixels of the faces, those emptied as
// near, as cracks (and not near), on the ground plane (and no crack), and empty in the map after
// the erosion (the first near step's map; `open_steps`: each step's); samples enclosed.
inline constexpr int kMaxNearSteps = 8;
struct OcclusionStats {
  std::uint64_t pixels = 0, near = 0, cracks = 0, ground = 0, open = 0, enclosed = 0;
  std::uint64_t open_steps[kMaxNearSteps] = {};
};

class OcclusionSampler {
 public:
  OcclusionSampler(SceneRenderer& renderer, const OcclusionSampling& sampling);

  // The instances sample `eye` stands for: marks() after it (1 per instance in the set). With a
  // slab, a sample is **enclosed** and stands for no eye (its marks all 0) when every pixel of
  // its six faces holds a surface (it is shut in: inside a building, which the walk's collision
  // never enters) and no surface lies within eps of it at the slab's heights (so every eye it
  // stands for there is shut in with it).
  void look(const Point3<std::int64_t>& eye, std::uint64_t* frames, const EyeSlab& slab = {});
  std::span<const std::uint8_t> marks() const { return marks_; }
  const OcclusionStats& stats() const { return stats_; }
  int side() const { return side_; }  // pixels of a widened face
  int rho() const { return rho_; }

 private:
  SceneRenderer& renderer_;
  OcclusionSampling sampling_;
  int rho_ = 0, side_ = 0;
  Angle fov_;
  std::vector<Framebuffer> faces_;
  PerspectiveView views_[6];
  std::vector<std::uint32_t> map_, work_, scratch_;
  OcclusionStats stats_;
  std::vector<std::uint8_t> marks_, step_marks_, ground_[6];
  std::vector<std::uint8_t> radii_[kMaxNearSteps];  // per near step: erosionRadii
  std::optional<DepthWindows> depth_;               // with depth_windows
};

}  // namespace octopoint

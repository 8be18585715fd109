#include "tools/cell_occlusion.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace octopoint {
namespace {

constexpr std::uint32_t kEmpty = FrameView::kEmpty;

// out[i * stride] = the largest of in[(i - r) * stride .. (i + r) * stride], kEmpty where that
// window leaves [0, n); `out` may be `in` (the line is read whole before it is written): van Herk's
// and Gil and Werman's running maxima, three comparisons a word whatever r. `prefix` and `suffix`:
// n words each.
void maxFilter(const std::uint32_t* in, std::size_t stride, std::int32_t n, int r,
               std::uint32_t* out, std::uint32_t* prefix, std::uint32_t* suffix) {
  const std::int32_t block = 2 * r + 1;
  for (std::int32_t start = 0; start < n; start += block) {
    const std::int32_t end = std::min(n, start + block);
    prefix[start] = in[static_cast<std::size_t>(start) * stride];
    for (std::int32_t i = start + 1; i < end; ++i)
      prefix[i] = std::max(prefix[i - 1], in[static_cast<std::size_t>(i) * stride]);
    suffix[end - 1] = in[static_cast<std::size_t>(end - 1) * stride];
    for (std::int32_t i = end - 2; i >= start; --i)
      suffix[i] = std::max(suffix[i + 1], in[static_cast<std::size_t>(i) * stride]);
  }
  for (std::int32_t i = 0; i < n; ++i) {
    out[static_cast<std::size_t>(i) * stride] =
        i - r < 0 || i + r >= n ? kEmpty : std::max(suffix[i - r], prefix[i + r]);
  }
}

// A slanted surface's splats stray from it by up to about half its depth step between
// neighbouring pixels: that share (Q16) of the step |w_a - w_b| is tolerated too. A jump between
// two surfaces of step s each is still a crack when it exceeds about s / 3.
constexpr std::int64_t kSlopeShare = std::int64_t{1} << 14;

// 1 / depth of a word, Q40 of one over its depth key (keys 1..2^24: 2^16..2^40, well apart
// between neighbouring keys at every depth the maps hold). On a plane seen in perspective 1/z
// is affine in the pixel's coordinates, so its second difference along a line is 0 but for the
// voxels' rounding.
std::int64_t inverseDepth(std::uint32_t word) {
  return (std::int64_t{1} << 40) /
         static_cast<std::int64_t>(std::max<std::uint32_t>(1, FrameView::depthKeyOf(word)));
}

// Empties both words of every crack along one line of n words (`stride` apart) of `words` in
// `open`. Between neighbours a (at i) and b (at i + 1), with w = 1/z (inverseDepth), the line
// through the two words before b extrapolated to b misses it by d_b = 2 w_a - w_(i-1) - w_b,
// the line through the two after a extrapolated to a by d_a = w_a - 2 w_b + w_(i+2). Where the
// two lines cross within [i, i + 1] (d_a and d_b of opposite signs, or either within the
// tolerance) the surfaces meet there: one plane, or two meeting at a crease (a building's
// corner), with no gap between them. Otherwise the surfaces jump by at least min(|d_a|, |d_b|)
// in 1/z, which from an eye eps to the side opens by eps times that jump (radians): a crack
// where that exceeds the tolerance, `tolerance` (Q16) times the farther word's 1/z. With a
// neighbour missing (the line's end, an empty word) the one line there is tested alone; with
// both missing, the jump w_a - w_b itself.
// The crack rule's tolerance, Q16 of the farther word's 1/z: the jump that opens by kLeastGap
// from an eye eps away (kLeastGap / eps), plus the voxels' rounding: the detail by distance draws
// voxels up to a pixel wide (docs/perspective.md), 2 / face of their depth in x/z units, so a
// splat's depth strays from its surface's by up to half that, and a second difference sums three.
std::int64_t crackTolerance(std::int64_t eps, int face) {
  const std::int64_t gap = (kLeastGap << 16) / std::max<std::int64_t>(1, eps);
  return std::min<std::int64_t>(std::int64_t{1} << 16, gap + (std::int64_t{3} << 16) / face);
}

// `ground`: null, or the line's ground flags (`stride` apart): two neighbours both on the ground
// plane are no crack (a gap between them leads below the ground, where nothing is seen from
// above it; the coarse voxels of a near ground would otherwise step in 1/z like cracks).
void crackLine(const std::uint32_t* words, std::size_t stride, std::int32_t n,
               std::int64_t tolerance, std::uint32_t* open, const std::uint8_t* ground) {
  const auto at = [&](std::int32_t i) { return words[static_cast<std::size_t>(i) * stride]; };
  for (std::int32_t i = 0; i + 1 < n; ++i) {
    if (at(i) == kEmpty || at(i + 1) == kEmpty) continue;
    if (ground != nullptr && ground[static_cast<std::size_t>(i) * stride] != 0 &&
        ground[static_cast<std::size_t>(i + 1) * stride] != 0) {
      continue;
    }
    const std::int64_t wa = inverseDepth(at(i)), wb = inverseDepth(at(i + 1));
    // Q40 1/key times Q16: below 2^56.
    const std::int64_t limit =
        (std::min(wa, wb) * tolerance >> 16) + (std::abs(wa - wb) * kSlopeShare >> 16);
    const bool left = i >= 1 && at(i - 1) != kEmpty, right = i + 2 < n && at(i + 2) != kEmpty;
    const std::int64_t d_b = left ? 2 * wa - inverseDepth(at(i - 1)) - wb : 0;
    const std::int64_t d_a = right ? wa - 2 * wb + inverseDepth(at(i + 2)) : 0;
    bool crack;
    if (left && right) {
      crack = ((d_a > 0 && d_b > 0) || (d_a < 0 && d_b < 0)) &&
              std::min(std::abs(d_a), std::abs(d_b)) > limit;
    } else if (left || right) {
      crack = std::abs(left ? d_b : d_a) > limit;
    } else {
      crack = std::abs(wa - wb) > limit;
    }
    if (crack) {
      open[static_cast<std::size_t>(i) * stride] = kEmpty;
      open[static_cast<std::size_t>(i + 1) * stride] = kEmpty;
    }
  }
}

}  // namespace

namespace {

// Sparse tables of the maxima (and minima) over squares of 2^k pixels, k up to log2(2 rho + 1)
// (levelsOf): a square window of any radius up to rho is the largest (smallest) of four such
// squares at its corners.
int levelsOf(int rho) {
  int top = 0;
  while ((2 << top) <= 2 * rho + 1) ++top;
  return top + 1;
}

// `levels`: levelsOf(rho) x width x height words, level 0 `in`, level k the `pick` (max or min)
// of four squares of level k - 1.
template <typename Pick>
void buildLevels(const std::uint32_t* in, std::int32_t width, std::int32_t height, int rho,
                 std::uint32_t* levels, Pick pick) {
  const std::size_t w = static_cast<std::size_t>(width),
                    pixels = w * static_cast<std::size_t>(height);
  std::copy(in, in + pixels, levels);
  for (int k = 1; k < levelsOf(rho); ++k) {
    const std::uint32_t* below = levels + pixels * static_cast<std::size_t>(k - 1);
    std::uint32_t* level = levels + pixels * static_cast<std::size_t>(k);
    const std::size_t half = std::size_t{1} << (k - 1), down = half * w;
    for (std::int32_t y = 0; y + 2 * static_cast<std::int32_t>(half) <= height; ++y) {
      for (std::int32_t x = 0; x + 2 * static_cast<std::int32_t>(half) <= width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x);
        level[i] =
            pick(pick(below[i], below[i + half]), pick(below[i + down], below[i + down + half]));
      }
    }
  }
}

// The `pick` of the square of radius r around (x, y) (inside the frame) from buildLevels' table.
template <typename Pick>
std::uint32_t windowOf(const std::uint32_t* levels, std::int32_t width, std::int32_t height,
                       std::int32_t x, std::int32_t y, std::int32_t r, Pick pick) {
  int k = 0;
  while ((2 << k) <= 2 * r + 1) ++k;
  const std::int32_t far = 2 * r + 1 - (1 << k);  // the corner squares' offset
  const std::size_t w = static_cast<std::size_t>(width);
  const std::uint32_t* level =
      levels + w * static_cast<std::size_t>(height) * static_cast<std::size_t>(k);
  const auto at = [&](std::int32_t px, std::int32_t py) {
    return level[static_cast<std::size_t>(py) * w + static_cast<std::size_t>(px)];
  };
  return pick(pick(at(x - r, y - r), at(x - r + far, y - r)),
              pick(at(x - r, y - r + far), at(x - r + far, y - r + far)));
}

constexpr auto kMax = [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); };
constexpr auto kMin = [](std::uint32_t a, std::uint32_t b) { return std::min(a, b); };

bool leaves(std::int32_t x, std::int32_t y, std::int32_t r, std::int32_t width,
            std::int32_t height) {
  return x - r < 0 || y - r < 0 || x + r >= width || y + r >= height;
}

// map[i] = the largest of `open` over the square of radius[i] pixels around pixel i, kEmpty where
// it leaves the face. `levels`: levelsOf(rho) x width x height words.
void variableMax(const std::uint32_t* open, std::int32_t width, std::int32_t height,
                 std::span<const std::uint8_t> radius, int rho, std::uint32_t* map,
                 std::uint32_t* levels) {
  buildLevels(open, width, height, rho, levels, kMax);
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x);
      const std::int32_t r = radius[i];
      map[i] =
          leaves(x, y, r, width, height) ? kEmpty : windowOf(levels, width, height, x, y, r, kMax);
    }
  }
}

// map[i] = the largest of `open` over the square around pixel i whose radius r is the least
// fixed point of r = depth.radius(i, nearest key within r) (ground pixels no surface: radius 1
// where only ground is near), kEmpty where the window holds an empty word or leaves the face.
// Growing r only brings nearer surfaces in, so r rises to the fixed point, or past the widest
// window the frame holds (then the pixel is empty).
// `nearest`: width x height words (`open` with the ground's words kEmpty); `levels`: twice
// levelsOf(depth.widest()) x width x height words.
void depthMax(const std::uint32_t* open, std::uint32_t* nearest, std::int32_t width,
              std::int32_t height, const DepthWindows& depth, std::uint32_t* map,
              std::uint32_t* levels) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  for (std::size_t i = 0; i < pixels; ++i) nearest[i] = open[i] == kGroundWord ? kEmpty : open[i];
  std::uint32_t* const farthest = levels;
  std::uint32_t* const closest =
      levels + pixels * static_cast<std::size_t>(levelsOf(depth.widest()));
  buildLevels(open, width, height, depth.widest(), farthest, kMax);
  buildLevels(nearest, width, height, depth.widest(), closest, kMin);
  const auto radiusOf = [&](std::size_t i, std::uint32_t word) {
    return word == kEmpty ? 1 : depth.radius(i, FrameView::depthKeyOf(word));
  };
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x);
      std::uint32_t word = open[i];
      for (std::int32_t r = radiusOf(i, nearest[i]); word != kEmpty;) {
        if (leaves(x, y, r, width, height)) {
          word = kEmpty;
          break;
        }
        word = windowOf(farthest, width, height, x, y, r, kMax);
        if (word == kEmpty) break;
        const std::int32_t need = radiusOf(i, windowOf(closest, width, height, x, y, r, kMin));
        if (need <= r) break;
        r = need;
      }
      map[i] = word;
    }
  }
}

// How far (x/z units) a turn of `angle` radians moves the image of a direction at x/z offset t
// from a face's axis: d (1 + t^2) to first order; t taken at the move's far side (once around),
// 10% more for the second order.
double reachOf(double angle, double t) {
  const double first = angle * (1 + t * t) * 1.1;
  return angle * (1 + (t + first) * (t + first)) * 1.1;
}

// The x/z offset of a widened face's pixel (px, py) from its axis (`unit`: a pixel in x/z).
double offsetOf(int px, int py, int side, double unit) {
  const double x = (px + 0.5 - side / 2.0) * unit, y = (py + 0.5 - side / 2.0) * unit;
  return std::sqrt(x * x + y * y);
}

double erosionAngle(std::int64_t eps, double distance) {
  return std::asin(std::min(1.0, static_cast<double>(eps) / std::max(1.0, distance)));
}

// A depth key's bucket for DepthWindows: keys below 256 each their own, then 256 a power of two.
std::size_t bucketOf(std::uint32_t key) {
  if (key < 256) return key;
  const int shift = std::bit_width(key) - 9;
  return 256 + static_cast<std::size_t>(shift) * 256 + ((key >> shift) & 255);
}

std::uint32_t nearestKeyOf(std::size_t bucket) {
  if (bucket < 256) return static_cast<std::uint32_t>(bucket);
  const std::size_t shift = (bucket - 256) / 256;
  return static_cast<std::uint32_t>((256 + (bucket & 255)) << shift);
}

}  // namespace

DepthWindows::DepthWindows(const OcclusionSampling& sampling, int side, int depth_shift)
    : widest_(sampling.eps > 0 ? (side - 1) / 2 : 0),
      unit_(2.0 / sampling.face),
      angle_(bucketOf(FrameView::kEmpty >> 8) + 1),
      offset_(static_cast<std::size_t>(side) * static_cast<std::size_t>(side)) {
  for (std::size_t b = 0; b < angle_.size(); ++b)
    angle_[b] = erosionAngle(sampling.eps, std::ldexp(nearestKeyOf(b), depth_shift));
  for (int py = 0; py < side; ++py) {
    for (int px = 0; px < side; ++px) {
      offset_[static_cast<std::size_t>(py) * static_cast<std::size_t>(side) +
              static_cast<std::size_t>(px)] = offsetOf(px, py, side, unit_);
    }
  }
}

int DepthWindows::radius(std::size_t pixel, std::uint32_t key) const {
  if (widest_ == 0) return 0;
  const double reach = reachOf(angle_[bucketOf(key)], offset_[pixel]);
  return std::min(widest_ + 1, static_cast<int>(std::ceil(reach / unit_)) + 1);
}

void erosionRadii(const OcclusionSampling& sampling, int side, std::span<std::uint8_t> radius) {
  const int rho = erosionRadius(sampling);
  const double angle =
      rho == 0 ? 0 : erosionAngle(sampling.eps, static_cast<double>(sampling.near));
  const double unit = 2.0 / sampling.face;  // a pixel in x/z (tan) units
  for (int py = 0; py < side; ++py) {
    for (int px = 0; px < side; ++px) {
      // One pixel for the grid; at most rho (the face's corner, whose border the face has).
      const double reach = reachOf(angle, offsetOf(px, py, side, unit));
      const int r = rho == 0 ? 0 : static_cast<int>(std::ceil(reach / unit)) + 1;
      radius[static_cast<std::size_t>(py) * static_cast<std::size_t>(side) +
             static_cast<std::size_t>(px)] = static_cast<std::uint8_t>(std::min(r, rho));
    }
  }
}

int erosionRadius(const OcclusionSampling& sampling) {
  if (sampling.eps <= 0) return 0;
  // At a face's corner (tan x = tan y = 1) a turn of d radians moves the image by up to
  // d (1 + x^2 + y^2) = 3 d in the image plane, whose pixels are 2 / face wide; 10% more for
  // the angle's second order, and one pixel for the grid.
  const double angle = erosionAngle(sampling.eps, static_cast<double>(sampling.near));
  return static_cast<int>(std::ceil(angle * 1.5 * sampling.face * 1.1)) + 1;
}

void occlusionMap(std::span<const std::uint32_t> words, std::int32_t width, std::int32_t height,
                  std::uint32_t near_key, std::int64_t eps, int face, int rho,
                  std::span<std::uint32_t> map, std::vector<std::uint32_t>& scratch,
                  std::span<const std::uint8_t> ground, std::span<const std::uint8_t> radius,
                  const DepthWindows* depth) {
  const std::size_t w = static_cast<std::size_t>(width),
                    pixels = w * static_cast<std::size_t>(height);
  const std::size_t lines = 2 * static_cast<std::size_t>(std::max(width, height));
  const std::size_t tables = depth != nullptr
                                 ? 1 + 2 * static_cast<std::size_t>(levelsOf(depth->widest()))
                             : radius.empty() ? 0
                                              : static_cast<std::size_t>(levelsOf(rho));
  scratch.resize(pixels + lines + pixels * tables);
  std::uint32_t* const open = scratch.data();  // near pixels and cracks emptied
  // The palette byte of a map word is set: a point at the map's own depth writes (the surface the
  // map holds there is seen, so its instance is in the set). The ground, near or far, is below
  // every word: no window's farthest (a crack on it still empties it, below).
  const bool has_ground = !ground.empty();
  for (std::size_t i = 0; i < pixels; ++i) {
    open[i] = has_ground && ground[i] != 0 && words[i] != kEmpty ? kGroundWord
              : FrameView::depthKeyOf(words[i]) < near_key       ? kEmpty
                                                                 : words[i] | 0xFF;
  }
  if (eps > 0) {
    const std::int64_t tolerance = crackTolerance(eps, face);
    for (std::int32_t y = 0; y < height; ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * w;
      crackLine(words.data() + row, 1, width, tolerance, open + row,
                has_ground ? ground.data() + row : nullptr);
    }
    for (std::int32_t x = 0; x < width; ++x) {
      crackLine(words.data() + x, w, height, tolerance, open + x,
                has_ground ? ground.data() + x : nullptr);
    }
  }
  if (rho == 0) {
    std::copy(open, open + pixels, map.begin());
  } else if (depth != nullptr) {
    depthMax(open, open + pixels + lines, width, height, *depth, map.data(),
             open + 2 * pixels + lines);
  } else if (!radius.empty()) {
    variableMax(open, width, height, radius, rho, map.data(), open + pixels + lines);
  } else {
    std::uint32_t* const prefix = open + pixels;
    std::uint32_t* const suffix = prefix + std::max(width, height);
    for (std::int32_t y = 0; y < height; ++y) {  // rows into the map, then its columns in place
      maxFilter(open + static_cast<std::size_t>(y) * w, 1, width, rho,
                map.data() + static_cast<std::size_t>(y) * w, prefix, suffix);
    }
    // The columns in place: each filter reads its whole line before it writes.
    for (std::int32_t x = 0; x < width; ++x) {
      std::uint32_t* const column = map.data() + x;
      maxFilter(column, w, height, rho, column, prefix, suffix);
    }
  }
  // A window of ground alone: the pixel's own word (a point behind it is below the ground).
  if (has_ground) {
    for (std::size_t i = 0; i < pixels; ++i)
      if (map[i] == kGroundWord) map[i] = words[i] | 0xFF;
  }
}

void groundMask(const FrameView& frame, const PerspectiveView& view, int face,
                std::int64_t ground_y, std::int64_t voxel, int depth_shift,
                std::span<std::uint8_t> mask) {
  const double pitch = view.camera.pitch.turns16() >= 32768
                           ? view.camera.pitch.turns16() - 65536.0
                           : static_cast<double>(view.camera.pitch.turns16());
  const double f = static_cast<double>(frame.width()) /
                   (2 * std::tan(view.camera.fov.turns16() * std::numbers::pi / 65536));
  const double below = static_cast<double>(ground_y - view.camera.eye.y);  // y down: > 0
  const double step = std::ldexp(1.0, depth_shift);
  for (std::int32_t py = 0; py < frame.height(); ++py) {
    // The y of a point at depth z along this row: eye + slope z (the face looking down: every
    // ray's y grows as its depth; up: falls, so no ground).
    const double slope = pitch == 0  ? (py + 0.5 - frame.height() / 2.0) / f
                         : pitch < 0 ? 1.0
                                     : -1.0;
    for (std::int32_t px = 0; px < frame.width(); ++px) {
      const std::size_t i = static_cast<std::size_t>(py) * static_cast<std::size_t>(frame.width()) +
                            static_cast<std::size_t>(px);
      const std::uint32_t word = frame.pixelAt(px, py);
      mask[i] = 0;
      if (word == FrameView::kEmpty || slope <= 0 || below <= 0) continue;
      const double z = std::ldexp(static_cast<double>(FrameView::depthKeyOf(word)), depth_shift);
      const double tolerance = z / face + static_cast<double>(voxel) + step * slope;
      mask[i] = std::abs(slope * z - below) <= tolerance ? 1 : 0;
    }
  }
}

namespace {

// The face's side with a border of rho + 1 pixels each way (the fov's rounding), and the widened
// face's field of view, rounded up to a thousandth of a degree.
int sideOf(const OcclusionSampling& sampling, int rho) {
  return sampling.face + (rho > 0 ? 2 * (rho + 1) : 0);
}

Angle fovOf(int face, int side) {
  const double degrees = 2 * std::atan(static_cast<double>(side) / face) * 180 / std::numbers::pi;
  return Angle::fromMilliDegrees(static_cast<std::int64_t>(std::ceil(degrees * 1000)));
}

bool fits(const OcclusionSampling& sampling, int rho) {
  return fovOf(sampling.face, sideOf(sampling, rho)).turns16() <= Angle::fromDegrees(120).turns16();
}

// The border's radius: rho. With depth windows, at most what fits in 120 degrees (a window
// wider than the frame holds leaves it: that pixel is empty), so that the near distance may be
// below 5 eps.
int borderOf(const OcclusionSampling& sampling) {
  int rho = erosionRadius(sampling);
  while (sampling.depth_windows && rho > 1 && !fits(sampling, rho)) --rho;
  return rho;
}

}  // namespace

bool erosionFits(const OcclusionSampling& sampling) {
  if (sampling.eps > 0 && sampling.near <= sampling.eps) return false;
  return fits(sampling, borderOf(sampling));
}

OcclusionSampler::OcclusionSampler(SceneRenderer& renderer, const OcclusionSampling& sampling)
    : renderer_(renderer),
      sampling_(sampling),
      rho_(borderOf(sampling)),
      side_(sideOf(sampling, rho_)),
      fov_(fovOf(sampling.face, side_)),
      faces_(6, Framebuffer(side_, side_)),
      map_(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_)),
      work_(map_.size()),
      marks_(renderer.instanceCount()),
      step_marks_(renderer.instanceCount()) {
  for (auto& mask : ground_) mask.resize(sampling.ground ? map_.size() : 0);
  if (sampling.depth_windows && rho_ > 0) {
    depth_.emplace(sampling, side_, renderer.depthShift());
    return;
  }
  for (int step = 0; sampling.radii && step < std::clamp(sampling.near_steps, 1, kMaxNearSteps);
       ++step) {
    OcclusionSampling at = sampling;
    at.near = sampling.near << step;
    radii_[step].resize(map_.size());
    erosionRadii(at, side_, radii_[step]);
  }
}

namespace {

constexpr int kFaces[6][2] = {{0, 0}, {90, 0}, {180, 0}, {270, 0}, {0, 90}, {0, -90}};

// Whether some surface drawn in a face (camera `view`) lies within `eps` of the eye and within the
// slab's heights (y down), every pixel's point taken at its depth key's nearer end (host side,
// double: a test of where to sample, not a frame).
bool nearSurfaceInSlab(const FrameView& frame, const PerspectiveView& view, int pitch,
                       std::int64_t eps, const EyeSlab& slab, int depth_shift) {
  const double f = static_cast<double>(frame.width()) /
                   (2 * std::tan(view.camera.fov.turns16() * std::numbers::pi / 65536));
  const double e = static_cast<double>(eps), eye_y = static_cast<double>(view.camera.eye.y);
  for (std::int32_t py = 0; py < frame.height(); ++py) {
    for (std::int32_t px = 0; px < frame.width(); ++px) {
      const std::uint32_t word = frame.pixelAt(px, py);
      if (word == FrameView::kEmpty) continue;
      const double z = std::ldexp(static_cast<double>(FrameView::depthKeyOf(word)), depth_shift);
      const double cx = (px + 0.5 - frame.width() / 2.0) / f * z,
                   cy = (py + 0.5 - frame.height() / 2.0) / f * z;
      if (cx * cx + cy * cy + z * z > e * e) continue;
      // y down: a face looking up (pitch 90) sees y falling with depth; its image's y is the
      // world's z, whatever its sign, so the slab test takes the depth alone.
      const double y = pitch == 0 ? eye_y + cy : pitch > 0 ? eye_y - z : eye_y + z;
      if (y >= static_cast<double>(slab.top) - 1 && y <= static_cast<double>(slab.bottom) + 1)
        return true;
    }
  }
  return false;
}

}  // namespace

void OcclusionSampler::look(const Point3<std::int64_t>& eye, std::uint64_t* frames,
                            const EyeSlab& slab) {
  std::fill(marks_.begin(), marks_.end(), std::uint8_t{0});
  // The six faces first: whether the sample stands only for eyes no walk reaches.
  bool enclosed = slab.top <= slab.bottom, seen[6] = {};
  for (int k = 0; k < 6; ++k) {
    PerspectiveCamera camera;
    camera.eye = eye;
    camera.yaw = Angle::fromDegrees(kFaces[k][0]);
    camera.pitch = Angle::fromDegrees(kFaces[k][1]);
    camera.fov = fov_;
    camera.width = side_;
    camera.height = side_;
    seen[k] =
        buildPerspectiveView(camera, kDefaultFractionBits, &views_[k]) == PerspectiveError::kNone;
    if (!seen[k]) {  // an eye beyond the camera's reach: the margin's instances stand for it
      enclosed = false;
      continue;
    }
    Framebuffer& frame = faces_[static_cast<std::size_t>(k)];
    frame.clear();
    static_cast<void>(renderer_.draw(views_[k], frame));
    ++*frames;
    if (sampling_.ground) {
      groundMask(frame, views_[k], sampling_.face, sampling_.ground_y, sampling_.ground_voxel,
                 renderer_.depthShift(), ground_[k]);
    }
    if (!enclosed) continue;
    const auto pixels = frame.pixels();
    enclosed = std::find(pixels.begin(), pixels.end(), FrameView::kEmpty) == pixels.end() &&
               !nearSurfaceInSlab(frame, views_[k], kFaces[k][1], sampling_.eps, slab,
                                  renderer_.depthShift());
  }
  if (enclosed) {
    ++stats_.enclosed;
    return;
  }
  // Per near distance (near, 2 near, 4 near, ...: each with its own, narrower, erosion) the
  // instances that write a pixel of some face's map; in the sample's set those every distance
  // lets in (each distance's set alone holds every instance seen from an eye within eps).
  for (int step = 0; step < std::clamp(sampling_.near_steps, 1, kMaxNearSteps); ++step) {
    const OcclusionSampling at{sampling_.eps, sampling_.near << step, sampling_.face, 1};
    const int rho = step == 0 ? rho_ : erosionRadius(at);
    const std::uint32_t near_key = static_cast<std::uint32_t>(std::min<std::uint64_t>(
        static_cast<std::uint64_t>(at.near) >> renderer_.depthShift(), kEmpty >> 8));
    std::fill(step_marks_.begin(), step_marks_.end(), std::uint8_t{0});
    for (int k = 0; k < 6; ++k) {
      if (!seen[k]) continue;
      const Framebuffer& frame = faces_[static_cast<std::size_t>(k)];
      occlusionMap(frame.pixels(), side_, side_, near_key, sampling_.eps, sampling_.face, rho, map_,
                   scratch_, ground_[k], radii_[step], depth_ ? &*depth_ : nullptr);
      for (std::size_t i = 0; step == 0 && i < map_.size(); ++i) {
        const std::uint32_t word = frame.pixels()[i];
        const bool on_ground = !ground_[k].empty() && ground_[k][i] != 0;
        const bool near = FrameView::depthKeyOf(word) < near_key && word != kEmpty && !on_ground;
        stats_.pixels += 1;
        stats_.near += near ? 1 : 0;
        stats_.cracks += !near && word != kEmpty && scratch_[i] == kEmpty ? 1 : 0;
        stats_.ground += scratch_[i] == kGroundWord ? 1 : 0;
        stats_.open += map_[i] == kEmpty ? 1 : 0;
      }
      for (const std::uint32_t word : map_) stats_.open_steps[step] += word == kEmpty ? 1 : 0;
      static_cast<void>(renderer_.markWriters(views_[k], map_, work_, step_marks_));
      ++*frames;
    }
    for (std::size_t i = 0; i < marks_.size(); ++i)
      marks_[i] = step == 0 ? step_marks_[i] : marks_[i] & step_marks_[i];
  }
}

}  // namespace octopoint

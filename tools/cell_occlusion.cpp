#include "tools/cell_occlusion.h"

#include <algorithm>
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

// Whether depth keys a and b of neighbouring pixels differ by more than kLeastGap / eps of the
// nearer: a crack (keys below 2^24, eps below 2^31: the products fit 64 bits).
bool crack(std::uint32_t a, std::uint32_t b, std::int64_t eps) {
  const std::uint64_t nearer = std::min(a, b), jump = std::max(a, b) - nearer;
  return jump * static_cast<std::uint64_t>(eps) > nearer * static_cast<std::uint64_t>(kLeastGap);
}

}  // namespace

int erosionRadius(const OcclusionSampling& sampling) {
  if (sampling.eps <= 0) return 0;
  // At a face's corner (tan x = tan y = 1) a turn of d radians moves the image by up to
  // d (1 + x^2 + y^2) = 3 d in the image plane, whose pixels are 2 / face wide; 10% more for
  // the angle's second order, and one pixel for the grid.
  const double angle = std::asin(
      std::min(1.0, static_cast<double>(sampling.eps) / static_cast<double>(sampling.near)));
  return static_cast<int>(std::ceil(angle * 1.5 * sampling.face * 1.1)) + 1;
}

void occlusionMap(std::span<const std::uint32_t> words, std::int32_t width, std::int32_t height,
                  std::uint32_t near_key, std::int64_t eps, int rho, std::span<std::uint32_t> map,
                  std::vector<std::uint32_t>& scratch) {
  const std::size_t w = static_cast<std::size_t>(width),
                    pixels = w * static_cast<std::size_t>(height);
  scratch.resize(pixels + 2 * static_cast<std::size_t>(std::max(width, height)));
  std::uint32_t* const open = scratch.data();  // near pixels and cracks emptied
  // The palette byte of a map word is set: a point at the map's own depth writes (the surface the
  // map holds there is seen, so its instance is in the set).
  for (std::size_t i = 0; i < pixels; ++i)
    open[i] = FrameView::depthKeyOf(words[i]) < near_key ? kEmpty : words[i] | 0xFF;
  if (eps > 0) {
    for (std::int32_t y = 0; y < height; ++y) {
      for (std::int32_t x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x);
        const std::uint32_t key = FrameView::depthKeyOf(words[i]);
        if (words[i] == kEmpty) continue;
        if (x + 1 < width && words[i + 1] != kEmpty &&
            crack(key, FrameView::depthKeyOf(words[i + 1]), eps)) {
          open[i] = open[i + 1] = kEmpty;
        }
        if (y + 1 < height && words[i + w] != kEmpty &&
            crack(key, FrameView::depthKeyOf(words[i + w]), eps)) {
          open[i] = open[i + w] = kEmpty;
        }
      }
    }
  }
  if (rho == 0) {
    std::copy(open, open + pixels, map.begin());
    return;
  }
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

}  // namespace

bool erosionFits(const OcclusionSampling& sampling) {
  if (sampling.eps > 0 && sampling.near <= sampling.eps) return false;
  const int side = sideOf(sampling, erosionRadius(sampling));
  return fovOf(sampling.face, side).turns16() <= Angle::fromDegrees(120).turns16();
}

OcclusionSampler::OcclusionSampler(SceneRenderer& renderer, const OcclusionSampling& sampling)
    : renderer_(renderer),
      sampling_(sampling),
      rho_(erosionRadius(sampling)),
      side_(sideOf(sampling, rho_)),
      fov_(fovOf(sampling.face, side_)),
      frame_(side_, side_),
      map_(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_)),
      work_(map_.size()),
      marks_(renderer.instanceCount()) {}

void OcclusionSampler::look(const Point3<std::int64_t>& eye, std::uint64_t* frames) {
  std::fill(marks_.begin(), marks_.end(), std::uint8_t{0});
  static constexpr int kFaces[6][2] = {{0, 0}, {90, 0}, {180, 0}, {270, 0}, {0, 90}, {0, -90}};
  const std::uint64_t near_key =
      static_cast<std::uint64_t>(sampling_.near) >> renderer_.depthShift();
  for (const auto& [yaw, pitch] : kFaces) {
    PerspectiveCamera camera;
    camera.eye = eye;
    camera.yaw = Angle::fromDegrees(yaw);
    camera.pitch = Angle::fromDegrees(pitch);
    camera.fov = fov_;
    camera.width = side_;
    camera.height = side_;
    PerspectiveView view;
    if (buildPerspectiveView(camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
      continue;  // an eye beyond the camera's reach: the margin's instances stand for it
    frame_.clear();
    static_cast<void>(renderer_.draw(view, frame_));
    occlusionMap(frame_.pixels(), side_, side_,
                 static_cast<std::uint32_t>(std::min<std::uint64_t>(near_key, kEmpty >> 8)),
                 sampling_.eps, rho_, map_, scratch_);
    static_cast<void>(renderer_.markWriters(view, map_, work_, marks_));
    *frames += 2;
  }
}

}  // namespace octopoint

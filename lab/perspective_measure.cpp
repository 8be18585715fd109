#include "lab/perspective_measure.h"

#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "renderer/level_of_detail.h"
#include "renderer/perspective_layers.h"
#include "renderer/perspective_renderer.h"
#include "renderer/perspective_walk.h"
#include "renderer/upper_tree_index.h"
#include "tests/support/perspective_reference.h"

namespace octopoint::lab {
namespace {

// A leaf as the walk handed it over: its index in its level and its screen position, pixels.
struct DrawnLeaf {
  std::size_t index;
  double x, y;
};

struct Vec2 {
  double x, y;
};

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull of `points` (Andrew's monotone chain), counter-clockwise in a y-down frame's
// terms (cross >= 0 inside); returns its vertex count, written to `hull`.
std::size_t convexHull(std::array<Vec2, 8> points, std::array<Vec2, 16>& hull) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  return k - 1;  // the last repeats the first
}

// The double-precision reference of one frame: each voxel's centre and corners projected exactly.
class ExactVoxels {
 public:
  ExactVoxels(const PerspectiveView& view, std::vector<std::uint8_t>& silhouette)
      : camera_(view.camera),
        m_(worldToCamera(view.camera)),
        silhouette_(silhouette),
        near_(static_cast<double>(view.camera.near)) {}

  // A voxel of `depth` centred on `centre` (Q.24 cube edges) that the walk handed over at
  // (`x`, `y`) pixels.
  void add(const ModelPoint& centre, int depth, double x, double y, PerspectiveMeasurement& out) {
    const Vector3 c = exactCameraSpace(m_, camera_.eye, centre);
    ++out.leaves;
    const double half = kUnit * std::ldexp(1.0, -(depth + 1));
    if (c[2] > 0) {
      const Projected exact = exactProjection(camera_, c[0], c[1], c[2]);
      const double error = std::max(std::abs(x - exact.x), std::abs(y - exact.y));
      out.max_position_all_px = std::max(out.max_position_all_px, error);
      // The splat's reach: sqrt(3) half edges at the centre's depth, less than 0.87 of an edge.
      const double reach = focalOf(camera_) * 1.74 * half / c[2];
      if (exact.x >= -reach && exact.y >= -reach && exact.x <= camera_.width + reach &&
          exact.y <= camera_.height + reach) {
        out.max_position_px = std::max(out.max_position_px, error);
      }
    } else {
      out.max_position_px = INFINITY;  // a voxel behind the eye was drawn
      out.max_position_all_px = INFINITY;
    }
    std::array<Vec2, 8> corners{};
    for (unsigned k = 0; k < 8; ++k) {
      const Vector3 s =
          rotated(m_, {(k & 4) ? half : -half, (k & 2) ? half : -half, (k & 1) ? half : -half});
      const Vector3 p{c[0] + s[0], c[1] + s[1], c[2] + s[2]};
      if (!(p[2] > near_)) {
        ++out.near_voxels;
        return;
      }
      const Projected q = exactProjection(camera_, p[0], p[1], p[2]);
      corners[k] = {q.x, q.y};
    }
    fill(corners);
  }

 private:
  // Marks the pixels whose centres lie in the corners' convex hull (on its edge included).
  void fill(const std::array<Vec2, 8>& corners) {
    std::array<Vec2, 16> hull{};
    const std::size_t n = convexHull(corners, hull);
    double x0 = hull[0].x, x1 = x0, y0 = hull[0].y, y1 = y0;
    for (std::size_t i = 1; i < n; ++i) {
      x0 = std::min(x0, hull[i].x), x1 = std::max(x1, hull[i].x);
      y0 = std::min(y0, hull[i].y), y1 = std::max(y1, hull[i].y);
    }
    const double w = camera_.width, h = camera_.height;
    const int col0 = static_cast<int>(std::max(0.0, std::ceil(x0 - 0.5)));
    const int col1 = static_cast<int>(std::min(w - 1, std::floor(x1 - 0.5)));
    const int row0 = static_cast<int>(std::max(0.0, std::ceil(y0 - 0.5)));
    const int row1 = static_cast<int>(std::min(h - 1, std::floor(y1 - 0.5)));
    for (int row = row0; row <= row1; ++row) {
      for (int col = col0; col <= col1; ++col) {
        const Vec2 p{col + 0.5, row + 0.5};
        bool inside = true;
        for (std::size_t i = 0; i < n && inside; ++i) inside = cross(hull[i], hull[i + 1], p) >= 0;
        if (inside) {
          silhouette_[static_cast<std::size_t>(row) * static_cast<std::size_t>(camera_.width) +
                      static_cast<std::size_t>(col)] = 1;
        }
      }
    }
  }

  PerspectiveCamera camera_;
  Matrix m_;
  std::vector<std::uint8_t>& silhouette_;
  double near_;
};

// Walks `level`'s stream in order and hands each leaf of `drawn` (sorted by index) to `voxels`
// with its model-space centre.
class LeafCentres {
 public:
  LeafCentres(const LevelView& level, std::span<const DrawnLeaf> drawn, ExactVoxels& voxels,
              PerspectiveMeasurement& out)
      : depth_(level.depth), node_(level.nodes.data()), drawn_(drawn), voxels_(voxels), out_(out) {}

  void run() { visit(0, {0, 0, 0}); }

 private:
  void visit(int level, const ModelPoint& centre) {
    if (next_ == drawn_.size()) return;
    if (level == depth_) {
      while (next_ < drawn_.size() && drawn_[next_].index == leaf_) {
        voxels_.add(centre, depth_, drawn_[next_].x, drawn_[next_].y, out_);
        ++next_;
      }
      ++leaf_;
      return;
    }
    const std::uint8_t mask = *node_++;
    const std::int64_t step = kPerspectiveUnit >> (level + 2);
    for (unsigned k = 0; k < 8; ++k) {
      if (!(mask & (1u << k))) continue;
      visit(level + 1, {centre.x + ((k & 4) ? step : -step), centre.y + ((k & 2) ? step : -step),
                        centre.z + ((k & 1) ? step : -step)});
      if (next_ == drawn_.size()) return;  // the rest is not needed
    }
  }

  int depth_;
  const std::uint8_t* node_;
  std::span<const DrawnLeaf> drawn_;
  ExactVoxels& voxels_;
  PerspectiveMeasurement& out_;
  std::size_t next_ = 0;
  std::size_t leaf_ = 0;
};

double threadMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// The position error and the silhouette: every leaf the frame's walks hand over, layer by layer
// as drawPerspectiveLayers walks them (the same tables, indexes and detail).
void measureLeaves(const ModelView& model, const PerspectiveView& view,
                   std::vector<std::uint8_t>& silhouette, PerspectiveMeasurement& out) {
  std::vector<std::vector<UpperTreeNode>> storage;
  std::vector<UpperTreeIndex> indexes;
  for (int i = 0; i < model.levelCount() && model.level(i).depth <= kMaxRenderDepth; ++i) {
    storage.emplace_back(upperTreeEntries(model.level(i)));
    indexes.push_back(buildUpperTreeIndex(model.level(i), storage.back()));
  }
  std::array<PerspectiveWalkTables, format::kMaxLevels> tables{};
  const PerspectiveLayers layers = perspectiveLayers(model, view, 0, indexes, tables);
  ExactVoxels voxels(view, silhouette);
  const double pixel = std::ldexp(1.0, -view.fraction_bits);
  for (std::size_t i = 0; i < layers.count; ++i) {
    const PerspectiveLayer& layer = layers.layer[i];
    out.depths.push_back(layer.level->depth);
    PerspectiveWalkParts parts;
    parts.index = layer.index;
    if (layers.count > 1) {
      parts.detail = {&layers.detail, static_cast<int>(i),
                      i == 0 ? -1 : layers.layer[i - 1].level->depth};
    }
    std::vector<DrawnLeaf> drawn;
    auto collect = [&](const PerspectiveLeaf& leaf) {
      drawn.push_back(
          {leaf.index, static_cast<double>(leaf.x) * pixel, static_cast<double>(leaf.y) * pixel});
    };
    PerspectiveWalk<decltype(collect)> walk(*layer.level, view, *layer.tables, collect, nullptr,
                                            parts);
    walk.run();
    std::sort(drawn.begin(), drawn.end(),
              [](const DrawnLeaf& a, const DrawnLeaf& b) { return a.index < b.index; });
    LeafCentres(*layer.level, drawn, voxels, out).run();
  }
}

std::uint64_t coveredPixels(const FrameView& frame) {
  std::uint64_t covered = 0;
  for (std::int32_t y = 0; y < frame.height(); ++y) {
    for (std::int32_t x = 0; x < frame.width(); ++x) covered += frame.covered(x, y) ? 1 : 0;
  }
  return covered;
}

}  // namespace

PerspectiveMeasurement measurePerspective(const ModelView& model, const PerspectiveView& view,
                                          int rounds, std::vector<std::uint8_t>* frame_rgb,
                                          std::vector<std::uint8_t>* silhouette) {
  PerspectiveMeasurement out;
  const std::int32_t width = view.camera.width, height = view.camera.height;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::uint8_t> mask(pixels, 0);
  measureLeaves(model, view, mask, out);

  PerspectiveRenderer renderer(model);
  PerspectiveRenderer::Options culled, unculled;
  unculled.cull = false;
  Framebuffer frame(width, height);
  frame.clear();
  PerspectiveDrawStats stats;
  if (!renderer.draw(view, unculled, frame, &stats)) return out;
  out.points_unculled = stats.leaves;
  stats = {};
  frame.clear();
  if (!renderer.draw(view, culled, frame, &stats)) return out;
  out.points_culled = stats.leaves;
  out.hidden_subtrees = stats.hidden_subtrees;
  out.covered_pixels = coveredPixels(frame);
  for (std::size_t i = 0; i < pixels; ++i) {
    if (mask[i] == 0) continue;
    ++out.silhouette_pixels;
    const auto x = static_cast<std::int32_t>(i % static_cast<std::size_t>(width));
    const auto y = static_cast<std::int32_t>(i / static_cast<std::size_t>(width));
    if (!frame.covered(x, y)) ++out.silhouette_empty;
  }
  if (frame_rgb != nullptr) {
    frame_rgb->assign(pixels * 3, 0);
    static_cast<void>(resolveToRgb(frame, model, Rgb{236, 236, 240}, *frame_rgb));
  }
  if (silhouette != nullptr) *silhouette = mask;

  // The orthographic frame of the same screen, as octopoint-render draws it (depth auto).
  Camera camera;
  camera.width = width;
  camera.height = height;
  const LevelView* level = autoLevel(model, camera);
  FrameSetup setup;
  if (level == nullptr ||
      buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    return out;
  }
  out.orthographic_leaves = level->leaves.size();
  out.orthographic_depth = level->depth;
  std::vector<double> perspective_ms, orthographic_ms;
  for (int round = 0; round < rounds; ++round) {
    double start = threadMilliseconds();
    frame.clear();
    static_cast<void>(renderer.draw(view, culled, frame));
    perspective_ms.push_back(threadMilliseconds() - start);
    start = threadMilliseconds();
    frame.clear();
    static_cast<void>(renderLevel(Variant::kFixedFast, *level, setup, frame));
    orthographic_ms.push_back(threadMilliseconds() - start);
  }
  if (!perspective_ms.empty()) out.perspective_ms = median(perspective_ms);
  if (!orthographic_ms.empty()) out.orthographic_ms = median(orthographic_ms);
  return out;
}

}  // namespace octopoint::lab

#include "codegen/eye_visibility.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <thread>

#include "codegen/parallel.h"
#include "codegen/progress.h"
#include "octopoint/framebuffer.h"
#include "renderer/level_of_detail.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_detail.h"
#include "renderer/perspective_splat.h"
#include "renderer/perspective_walk.h"

namespace octopoint::prepare {
namespace {

constexpr unsigned kMaxThreads = 2;

// The depth part of the word a leaf writes: FrameView::pack's key for a colour frame, the depth
// code of renderer/perspective_depth.h for a frame with normals. A pixel keeps the smallest word,
// so the leaves at its smallest key are the ones that may show there (their colours decide
// among them; all are kept).
enum class KeyKind : std::uint8_t { kColour, kNormal };

struct LeafPixels {
  const PerspectiveView& view;
  std::int64_t padding;  // splatPadding of the level's tables
  KeyKind kind;

  std::uint32_t key(std::int64_t z) const {
    if (kind == KeyKind::kNormal) return perspectiveNormalDepthCode(z);
    return static_cast<std::uint32_t>(
        std::min<std::int64_t>(z >> view.depth_shift, FrameView::kMaxDepthKey));
  }
  // Calls visit(pixel index) for each pixel the leaf's splat covers (the plot's rule).
  template <typename Visit>
  void forEach(const PerspectiveLeaf& leaf, Visit visit) const {
    const int f = view.fraction_bits;
    const std::int32_t width = view.camera.width, height = view.camera.height;
    const PixelSpan columns = pixelSpan(leaf.x, leaf.half_x + padding, f, width);
    const PixelSpan rows = pixelSpan(leaf.y, leaf.half_y + padding, f, height);
    for (std::int64_t y = rows.first; y <= rows.last; ++y) {
      for (std::int64_t x = columns.first; x <= columns.last; ++x)
        visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x));
    }
  }
};

// First pass: the nearest key per pixel.
struct NearestKeys {
  LeafPixels pixels_of;
  std::vector<std::uint32_t>& nearest;
  void operator()(const PerspectiveLeaf& leaf) {
    const std::uint32_t key = pixels_of.key(leaf.z);
    pixels_of.forEach(leaf, [&](std::size_t at) { nearest[at] = std::min(nearest[at], key); });
  }
};

// Second pass: a leaf at the nearest key of one of its pixels is visible.
struct MarkNearest {
  LeafPixels pixels_of;
  const std::vector<std::uint32_t>& nearest;
  std::vector<std::uint8_t>& visible;
  void operator()(const PerspectiveLeaf& leaf) {
    if (visible[leaf.index]) return;
    const std::uint32_t key = pixels_of.key(leaf.z);
    pixels_of.forEach(leaf, [&](std::size_t at) {
      if (nearest[at] == key) visible[leaf.index] = 1;
    });
  }
};

// The levels drawn into one frame: a run of them, with detail by distance when more than one.
struct FrameLevels {
  std::size_t first = 0;
  std::size_t count = 0;
};

// One view's frames: for each run of levels and key kind, the nearest keys, then the winners.
class EyeJudge {
 public:
  EyeJudge(std::span<const LevelView> levels, std::span<const std::int32_t> reaches,
           std::span<const FrameLevels> frames, bool normals)
      : levels_(levels),
        reaches_(reaches),
        frames_(frames),
        normals_(normals),
        tables_(levels.size()) {}

  void judge(const PerspectiveView& view, std::vector<std::vector<std::uint8_t>>& visible) {
    // A quarter pixel, as the renderer's perspectiveLayers takes it.
    const std::int64_t max_error = std::int64_t{1} << (view.fraction_bits - 2);
    for (const FrameLevels& frame : frames_) {
      std::array<int, format::kMaxLevels> depths{};
      for (std::size_t i = 0; i < frame.count; ++i) {
        const LevelView& level = levels_[frame.first + i];
        // Each level's splats as wide as the renderer draws them (its stored sample reach).
        tables_[frame.first + i] =
            perspectiveWalkTables(view, level.depth, max_error, reaches_[frame.first + i]);
        depths[i] = level.depth;
      }
      const PerspectiveDetail detail =
          perspectiveDetail(view, std::span(depths.data(), frame.count));
      for (const KeyKind kind : {KeyKind::kColour, KeyKind::kNormal}) {
        if (kind == KeyKind::kNormal && !normals_) continue;
        nearest_.assign(static_cast<std::size_t>(view.camera.width) *
                            static_cast<std::size_t>(view.camera.height),
                        std::numeric_limits<std::uint32_t>::max());
        for (const bool mark : {false, true}) {
          for (std::size_t i = 0; i < frame.count; ++i) {
            const std::size_t k = frame.first + i;
            PerspectiveWalkParts parts;
            if (frame.count > 1) {
              parts.detail = {&detail, static_cast<int>(i), i == 0 ? -1 : levels_[k - 1].depth};
            }
            const LeafPixels pixels_of{view, splatPadding(tables_[k]), kind};
            if (mark) {
              MarkNearest sink{pixels_of, nearest_, visible[k]};
              PerspectiveWalk<MarkNearest>(levels_[k], view, tables_[k], sink, nullptr, parts)
                  .run();
            } else {
              NearestKeys sink{pixels_of, nearest_};
              PerspectiveWalk<NearestKeys>(levels_[k], view, tables_[k], sink, nullptr, parts)
                  .run();
            }
          }
        }
      }
    }
  }

 private:
  std::span<const LevelView> levels_;
  std::span<const std::int32_t> reaches_;  // Q4 footprints, one per level
  std::span<const FrameLevels> frames_;
  bool normals_;
  std::vector<PerspectiveWalkTables> tables_;  // by level, for the view being judged
  std::vector<std::uint32_t> nearest_;
};

}  // namespace

std::vector<std::vector<std::uint8_t>> visibleFromEyes(std::span<const LevelView> levels,
                                                       std::span<const std::int32_t> sample_reaches,
                                                       std::span<const PerspectiveView> views) {
  assert(sample_reaches.size() == levels.size());
  std::vector<std::vector<std::uint8_t>> visible;
  for (const LevelView& level : levels) visible.emplace_back(level.leaves.size(), 0);
  // The levels the renderer draws (ascending: a prefix), the densely sampled ones together,
  // counted as the renderer counts them: a depth its reach draws whole is dense too.
  std::size_t drawable = 0;
  std::vector<std::uint64_t> counts;
  while (drawable < levels.size() && levels[drawable].depth <= kMaxRenderDepth) {
    counts.push_back(levels[drawable].leaves.size());
    ++drawable;
  }
  for (std::size_t i = drawable; i < levels.size(); ++i) visible[i].assign(visible[i].size(), 1);
  if (drawable == 0 || views.empty()) return visible;
  std::vector<FrameLevels> frames = {{0, denseDepthCount(counts, sample_reaches.first(drawable))}};
  for (std::size_t i = frames[0].count; i < drawable; ++i) frames.push_back({i, 1});
  const bool normals = std::all_of(levels.begin(), levels.end(), [](const LevelView& level) {
    return !level.leaves.empty() && level.normals.size() == level.leaves.size();
  });

  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, kMaxThreads);
  std::vector<std::vector<std::vector<std::uint8_t>>> seen(threads, visible);
  std::vector<EyeJudge> judges;
  for (unsigned t = 0; t < threads; ++t)
    judges.emplace_back(levels, sample_reaches, frames, normals);
  Progress progress("pruning for the eyes", views.size());
  parallelFor(threads, views.size(), [&](std::size_t view, unsigned thread) {
    judges[thread].judge(views[view], seen[thread]);
    if (thread == 0) progress.update(view);
  });
  for (unsigned t = 0; t < threads; ++t) {
    for (std::size_t k = 0; k < levels.size(); ++k) {
      for (std::size_t i = 0; i < visible[k].size(); ++i) visible[k][i] |= seen[t][k][i];
    }
  }
  return visible;
}

}  // namespace octopoint::prepare

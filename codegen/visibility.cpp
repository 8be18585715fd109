#include "codegen/visibility.h"

#include <algorithm>
#include <limits>
#include <thread>

#include "codegen/octree_encoder.h"
#include "codegen/parallel.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "renderer/decode_baseline.h"
#include "renderer/smooth_reach.h"

namespace octopoint::prepare {
namespace {

constexpr unsigned kMaxThreads = 2;

// Which leaves can show in a view, by the rule of Framebuffer::plot: off-screen pixels are
// dropped, and a pixel shows the smallest word of depth key and palette index. Colours are not
// known yet here (the palette comes after pruning), so every leaf at a pixel's nearest depth key
// is kept: whichever of them the palette makes win, it is still there. A leaf covers one pixel, or
// with footprint splats (FrameSetup::splat, drawn by fixed_fast and fixed_simd) a rectangle; a
// view whose set-up splats is judged both ways, so that the pruned model draws the same frame
// whichever variant draws it.
struct LeafPixels {
  std::int32_t width;
  std::int32_t height;
  const FrameSetup& setup;
  SplatFootprint splat;  // SplatFootprint{}: one pixel per leaf

  // Calls visit(pixel index) for each on-screen pixel the leaf at (x, y) (Q(32-F).F) covers.
  template <typename Visit>
  void forEach(std::int32_t x, std::int32_t y, Visit visit) const {
    const int f = setup.fraction_bits;
    const std::int32_t x_begin = std::max((x + splat.offset_x) >> f, 0);
    const std::int32_t x_end = std::min(((x + splat.offset_x + splat.span_x) >> f) + 1, width);
    const std::int32_t y_begin = std::max((y + splat.offset_y) >> f, 0);
    const std::int32_t y_end = std::min(((y + splat.offset_y + splat.span_y) >> f) + 1, height);
    for (std::int32_t py = y_begin; py < y_end; ++py) {
      for (std::int32_t px = x_begin; px < x_end; ++px)
        visit(static_cast<std::size_t>(py) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(px));
    }
  }
};

// First pass: the nearest depth key per pixel.
struct NearestKeySink {
  LeafPixels pixels_of;
  std::vector<std::uint32_t>& nearest;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::uint32_t key = pixels_of.setup.depthKey(z);
    pixels_of.forEach(x, y, [&](std::size_t at) { nearest[at] = std::min(nearest[at], key); });
  }
};

// Second pass: every leaf at the nearest key of one of its pixels is visible.
struct MarkNearestSink {
  LeafPixels pixels_of;
  const std::vector<std::uint32_t>& nearest;
  std::vector<std::uint8_t>& visible;
  std::uint32_t next_leaf = 0;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::uint32_t index = next_leaf++;
    const std::uint32_t key = pixels_of.setup.depthKey(z);
    pixels_of.forEach(x, y, [&](std::size_t at) {
      if (nearest[at] == key) visible[index] = 1;
    });
  }
};

// Third pass, for smooth frames (octopoint/smooth.h) that blend: every leaf whose kernel reaches a
// pixel whose nearest key (the box frame's, with splats) lies within the depth tolerance of its
// own adds to that pixel's blend, so it is kept, whether or not it wins a pixel. The tolerance is
// padded by 512 key units, because the blend of normals compares keys rounded to 256ths: a leaf
// either comparison lets in is kept (keeping a loser changes no frame: it sets no nearest key).
struct MarkBlendedSink {
  std::int32_t width;
  std::int32_t height;
  const FrameSetup& setup;
  SmoothReach reach;
  const std::vector<std::uint32_t>& nearest;
  std::vector<std::uint8_t>& visible;
  std::uint32_t next_leaf = 0;

  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::uint32_t index = next_leaf++;
    if (visible[index] != 0) return;
    const std::int64_t key = setup.depthKey(z);
    const std::int64_t tolerance = std::int64_t{reach.tolerance} + 512;
    const int f = setup.fraction_bits;
    const auto [x_begin, x_end] = kernelSpan(x, reach.radius, f, width);
    const auto [y_begin, y_end] = kernelSpan(y, reach.radius, f, height);
    for (std::int32_t py = y_begin; py < y_end; ++py) {
      const std::size_t row = static_cast<std::size_t>(py) * static_cast<std::size_t>(width);
      for (std::int32_t px = x_begin; px < x_end; ++px) {
        const std::uint32_t there = nearest[row + static_cast<std::size_t>(px)];
        if (there == std::numeric_limits<std::uint32_t>::max()) continue;  // nothing drawn
        if (key - there <= tolerance && there - key <= tolerance) {
          visible[index] = 1;
          return;
        }
      }
    }
  }
};

void markWinners(const LevelView& level, const FrameSetup& setup,
                 std::vector<std::uint32_t>& nearest, std::vector<std::uint8_t>& visible) {
  for (const bool splat : {false, true}) {
    if (splat && !setup.splat.active()) continue;
    const LeafPixels pixels_of{setup.width, setup.height, setup,
                               splat ? setup.splat : SplatFootprint{}};
    nearest.assign(static_cast<std::size_t>(setup.width) * static_cast<std::size_t>(setup.height),
                   std::numeric_limits<std::uint32_t>::max());
    NearestKeySink first{pixels_of, nearest};
    BaselineWalk<NearestKeySink>(level, setup, first).run();
    MarkNearestSink second{pixels_of, nearest, visible};
    BaselineWalk<MarkNearestSink>(level, setup, second).run();
  }
  // `nearest` is now the box frame's with splats (the frame a smooth frame blends over).
  const SmoothReach reach = smoothReachOf(setup);
  if (!reach.blends) return;
  MarkBlendedSink third{setup.width, setup.height, setup, reach, nearest, visible};
  BaselineWalk<MarkBlendedSink>(level, setup, third).run();
}

}  // namespace

std::vector<std::uint8_t> visibleVoxels(std::span<const std::uint64_t> sorted_keys, int depth,
                                        std::span<const Camera> cameras,
                                        std::int32_t sample_reach) {
  // Checked here, built again per view by the workers: a set-up is 1.6 KB, and a scene may have
  // 200,000 views (codegen/scene_views.h).
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    FrameSetup setup;
    const CameraError error =
        buildFrameSetup(cameras[i], depth, kDefaultFractionBits, &setup, sample_reach);
    if (error != CameraError::kNone) {
      throw PrepareError("scene view " + std::to_string(i) + " at depth " + std::to_string(depth) +
                         ": " + describe(error));
    }
  }
  const std::vector<std::uint8_t> nodes = encodeOctree(sorted_keys, depth);
  const std::vector<std::uint8_t> leaves(sorted_keys.size(), 0);  // colours play no part here
  const LevelView level{depth, nodes, leaves};

  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, kMaxThreads);
  std::vector<std::vector<std::uint8_t>> visible(threads,
                                                 std::vector<std::uint8_t>(sorted_keys.size(), 0));
  std::vector<std::vector<std::uint32_t>> nearest(threads);
  std::vector<FrameSetup> setups(threads);
  Progress progress("pruning depth " + std::to_string(depth), cameras.size());
  parallelFor(threads, cameras.size(), [&](std::size_t view, unsigned thread) {
    // Every camera was accepted above, before any thread started.
    if (buildFrameSetup(cameras[view], depth, kDefaultFractionBits, &setups[thread],
                        sample_reach) != CameraError::kNone)
      return;
    markWinners(level, setups[thread], nearest[thread], visible[thread]);
    if (thread == 0) progress.update(view);
  });
  for (unsigned t = 1; t < threads; ++t) {
    for (std::size_t i = 0; i < sorted_keys.size(); ++i) visible[0][i] |= visible[t][i];
  }
  return visible[0];
}

}  // namespace octopoint::prepare

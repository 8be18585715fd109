#include "codegen/visibility.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <thread>

#include "codegen/octree_encoder.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "renderer/decode_baseline.h"

namespace octopoint::prepare {
namespace {

constexpr unsigned kMaxThreads = 2;

// Which leaves can show in a view, by the rule of Framebuffer::plot: off-screen leaves are
// dropped, and a pixel shows the smallest word of depth key and palette index. Colours are not
// known yet here (the palette comes after pruning), so every leaf at a pixel's nearest depth key
// is kept: whichever of them the palette makes win, it is still there.
struct LeafPixel {
  std::int32_t width;
  std::int32_t height;
  const FrameSetup& setup;

  // The pixel a leaf at (x, y) (Q(32-F).F) lands on, or -1 off screen.
  std::ptrdiff_t operator()(std::int32_t x, std::int32_t y) const {
    const std::int32_t px = x >> setup.fraction_bits;
    const std::int32_t py = y >> setup.fraction_bits;
    if (static_cast<std::uint32_t>(px) >= static_cast<std::uint32_t>(width) ||
        static_cast<std::uint32_t>(py) >= static_cast<std::uint32_t>(height)) {
      return -1;
    }
    return static_cast<std::ptrdiff_t>(py) * width + px;
  }
};

// First pass: the nearest depth key per pixel.
struct NearestKeySink {
  LeafPixel pixel_of;
  std::vector<std::uint32_t>& nearest;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::ptrdiff_t at = pixel_of(x, y);
    if (at >= 0) nearest[static_cast<std::size_t>(at)] = std::min(nearest[static_cast<std::size_t>(at)], pixel_of.setup.depthKey(z));
  }
};

// Second pass: every leaf at its pixel's nearest key is visible.
struct MarkNearestSink {
  LeafPixel pixel_of;
  const std::vector<std::uint32_t>& nearest;
  std::vector<std::uint8_t>& visible;
  std::uint32_t next_leaf = 0;
  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::uint32_t index = next_leaf++;
    const std::ptrdiff_t at = pixel_of(x, y);
    if (at >= 0 && nearest[static_cast<std::size_t>(at)] == pixel_of.setup.depthKey(z)) visible[index] = 1;
  }
};

void markWinners(const LevelView& level, const FrameSetup& setup, std::vector<std::uint32_t>& nearest,
                 std::vector<std::uint8_t>& visible) {
  const LeafPixel pixel_of{setup.width, setup.height, setup};
  nearest.assign(static_cast<std::size_t>(setup.width) * static_cast<std::size_t>(setup.height),
                 std::numeric_limits<std::uint32_t>::max());
  NearestKeySink first{pixel_of, nearest};
  BaselineWalk<NearestKeySink>(level, setup, first).run();
  MarkNearestSink second{pixel_of, nearest, visible};
  BaselineWalk<MarkNearestSink>(level, setup, second).run();
}

}  // namespace

std::vector<std::uint8_t> visibleVoxels(std::span<const std::uint64_t> sorted_keys, int depth,
                                        std::span<const Camera> cameras) {
  std::vector<FrameSetup> setups(cameras.size());
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const CameraError error = buildFrameSetup(cameras[i], depth, kDefaultFractionBits, &setups[i]);
    if (error != CameraError::kNone) {
      throw PrepareError("scene view " + std::to_string(i) + " at depth " + std::to_string(depth) + ": " +
                         describe(error));
    }
  }
  const std::vector<std::uint8_t> nodes = encodeOctree(sorted_keys, depth);
  const std::vector<std::uint8_t> leaves(sorted_keys.size(), 0);  // colours play no part here
  const LevelView level{depth, nodes, leaves};

  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, kMaxThreads);
  std::vector<std::vector<std::uint8_t>> visible(threads, std::vector<std::uint8_t>(sorted_keys.size(), 0));
  std::atomic<std::size_t> next_view{0};
  Progress progress("pruning depth " + std::to_string(depth), setups.size());
  auto work = [&](unsigned thread) {
    std::vector<std::uint32_t> nearest;
    for (std::size_t view; (view = next_view.fetch_add(1)) < setups.size();) {
      markWinners(level, setups[view], nearest, visible[thread]);
      if (thread == 0) progress.update(view);
    }
  };
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work, t);
  work(0);
  for (std::thread& helper : helpers) helper.join();
  for (unsigned t = 1; t < threads; ++t) {
    for (std::size_t i = 0; i < sorted_keys.size(); ++i) visible[0][i] |= visible[t][i];
  }
  return visible[0];
}

}  // namespace octopoint::prepare

#include "codegen/visibility.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "codegen/octree_encoder.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "renderer/decode_baseline.h"
#include "renderer/framebuffer.h"

namespace octopoint::prepare {
namespace {

constexpr unsigned kMaxThreads = 2;

// Per pixel the nearest leaf so far, by the rule of Framebuffer::plot: off-screen leaves are
// dropped, a leaf wins only when strictly nearer, so among equals the first in stream order wins.
struct NearestLeafSink {
  std::vector<std::int32_t>& depth;
  std::vector<std::uint32_t>& leaf;
  std::int32_t width;
  std::int32_t height;
  int fraction_bits;
  std::uint32_t next_leaf = 0;

  void operator()(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t) {
    const std::uint32_t index = next_leaf++;
    const std::int32_t px = x >> fraction_bits;
    const std::int32_t py = y >> fraction_bits;
    if (static_cast<std::uint32_t>(px) >= static_cast<std::uint32_t>(width) ||
        static_cast<std::uint32_t>(py) >= static_cast<std::uint32_t>(height)) {
      return;
    }
    const std::size_t at = static_cast<std::size_t>(py) * static_cast<std::size_t>(width) + static_cast<std::size_t>(px);
    if (z < depth[at]) {
      depth[at] = z;
      leaf[at] = index;
    }
  }
};

void markWinners(const LevelView& level, const FrameSetup& setup, std::vector<std::int32_t>& depth,
                 std::vector<std::uint32_t>& leaf, std::vector<std::uint8_t>& visible) {
  const std::size_t pixels = static_cast<std::size_t>(setup.width) * static_cast<std::size_t>(setup.height);
  depth.assign(pixels, Framebuffer::kEmptyDepth);
  leaf.resize(pixels);
  NearestLeafSink sink{depth, leaf, setup.width, setup.height, setup.fraction_bits};
  BaselineWalk<NearestLeafSink>(level, setup, sink).run();
  for (std::size_t i = 0; i < pixels; ++i) {
    if (depth[i] != Framebuffer::kEmptyDepth) visible[leaf[i]] = 1;
  }
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
    std::vector<std::int32_t> z;
    std::vector<std::uint32_t> winner;
    for (std::size_t view; (view = next_view.fetch_add(1)) < setups.size();) {
      markWinners(level, setups[view], z, winner, visible[thread]);
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

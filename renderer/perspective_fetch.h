#pragma once
// The order in which a chunked model's chunks are fetched for a perspective view
// (docs/perspective.md, "Chunked models"): what ProgressiveModel::fetchPriority is to the
// orthographic view. Record tables first (a level's chunks cannot be listed without it), then the
// chunks: visible before invisible (a region wholly behind the near plane or beyond a side plane of
// the frustum is invisible), coarse levels before fine, and within a level nearest first, which at
// one level (one region size) is largest on screen first: a region's nearest depth z - reach, its
// on-screen size f * edge / z. A chunk is listed only where detail by distance asks for its depth:
// some point of its region is near enough for a voxel of the level's depth to span a pixel
// (renderer/perspective_detail.h, evaluated at the region's nearest depth); never a chunk held,
// waiting or unavailable, or one refining an unavailable chunk. Integer only; after the first call
// for a model, no allocation (the scratch is kept).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/progressive.h"
#include "renderer/perspective.h"

namespace octopoint {

class PerspectiveFetchOrder {
 public:
  // Writes up to out.size() items, most urgent first, and returns how many; `total`, when given,
  // gets how many there are in all. Invisible chunks only with `include_invisible`. `nearest_out`,
  // when given (at least as long as `out`), gets each chunk's region's nearest depth in 1/2^20
  // cube edge (0 for a record table): a scene merges its instances' orders by it
  // (net/scene_fetch_order.h).
  std::size_t order(const ProgressiveModel& model, const PerspectiveView& view,
                    bool include_invisible, std::span<FetchItem> out, std::size_t* total = nullptr,
                    std::span<std::uint32_t> nearest_out = {});

 private:
  struct Entry {
    std::uint64_t key;  // invisible (1 bit), level (4 bits), nearest depth (32 bits), index (27)
    FetchItem item;
  };
  std::vector<Entry> scratch_;
  std::array<std::vector<std::uint8_t>, chunked::kMaxChunkedLevels> blocked_;
};

}  // namespace octopoint

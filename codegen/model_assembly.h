#pragma once
// The last step of the streamed preparer: from each depth's node stream and leaf colours to a
// model: one palette from the finest depth's colours and a palette index per leaf (visibility
// pruning follows, codegen/scene_pruning.h).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "codegen/cube_fit.h"
#include "codegen/prepare.h"
#include "codegen/prepared_model.h"

namespace octopoint::prepare {

struct EncodedLevel {
  int depth = 0;
  std::vector<std::uint8_t> nodes;
  // 0xRRGGBB per leaf, in stream order, in the pieces the bins made (joined only as indices;
  // the memory is the preparer's, codegen/colour_store.h).
  std::vector<std::span<const std::uint32_t>> colours;
  std::size_t leaves = 0;
};

// `levels` ascending by depth, as options.depths; uses `threads` threads.
PreparedModel assembleModel(std::vector<EncodedLevel> levels, const CubeFit& fit,
                            const PrepareOptions& options, const std::string& path,
                            unsigned threads);

}  // namespace octopoint::prepare

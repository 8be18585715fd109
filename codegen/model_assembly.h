#pragma once
// The last step of the preparer: from each depth's node stream and leaf colours to a model: one
// palette from the finest depth's colours, a palette index per leaf, and visibility pruning when
// the options ask for it.

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

// `levels` ascending by depth, as options.depths; uses `threads` threads. Throws PrepareError
// naming `path` when pruning leaves a depth without any voxel.
PreparedModel assembleModel(std::vector<EncodedLevel> levels, const CubeFit& fit,
                            const PrepareOptions& options, const std::string& path,
                            unsigned threads);

}  // namespace octopoint::prepare

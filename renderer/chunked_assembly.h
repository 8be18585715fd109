#pragma once
// A chunked model (octopoint/progressive.h) as one ordinary model: the depths whose chunks are all
// held, each spliced back into the whole cube's depth-first stream, so that whatever draws a
// ModelView draws it (octopoint-render --perspective, --eye and --path on a chunked file: the
// perspective renderer's detail by distance chooses among these depths). A complete chunked model
// becomes the very model the same scan prepared as one file holds, stream for stream; a partial
// one keeps the base and the complete levels above it. On the heap (not on a bare-metal build): the
// streams are copied.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/progressive.h"

namespace octopoint {

struct AssembledModel {
  std::vector<std::vector<std::uint8_t>> nodes, leaves;  // per level: the whole cube's streams
  std::vector<EmbeddedLevel> levels;
  EmbeddedModel embedded{};
  std::optional<ModelView> view;  // points into the above: the object never moves (unique_ptr)
  int chunked_levels = 0;         // the chunked file's levels, the base included
};

// nullptr only if a held chunk's stream fails validation as part of the whole (it cannot: each
// was checked when it arrived).
std::unique_ptr<AssembledModel> assembleChunked(const ProgressiveModel& model);

// A chunked model held in part, as parts each drawn with its own finest held level
// (docs/perspective.md, "Chunked models"): a region where level L is held and level L + 1 is not
// (at level L + 1's region level) lies in the part whose finest level is L, which holds its stream
// at L and the coarser chunks above it. Drawn one after another into one frame, each by
// PerspectiveRenderer with detailDepths(), every region is drawn at the depth its distance asks
// for, or at the finest depth held there where that is coarser: never a hole where a coarser level
// is held. Held whole, one part: the model assembleChunked gives. A voxel of a coarser level whose
// region spans parts is in each of them, and drawn the same by each.
struct HeldParts {
  std::vector<std::unique_ptr<AssembledModel>> parts;  // coarsest finest level first
  // The depths detail by distance chooses among: the densely sampled ones of the levels whose
  // record tables are known (their point counts say which), at most format::kMaxLevels.
  std::array<int, format::kMaxLevels> detail_depths{};
  std::size_t detail_count = 0;

  std::span<const int> detailDepths() const { return {detail_depths.data(), detail_count}; }
};

HeldParts assembleHeldParts(const ProgressiveModel& model);

}  // namespace octopoint

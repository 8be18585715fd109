#pragma once
// A chunked model (octopoint/progressive.h) as one ordinary model: the depths whose chunks are all
// held, each spliced back into the whole cube's depth-first stream, so that whatever draws a
// ModelView draws it (octopoint-render --perspective, --eye and --path on a chunked file: the
// perspective renderer's detail by distance chooses among these depths). A complete chunked model
// becomes the very model the same scan prepared as one file holds, stream for stream; a partial
// one keeps the base and the complete levels above it. On the heap (not on a bare-metal build): the
// streams are copied.

#include <cstdint>
#include <memory>
#include <optional>
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

}  // namespace octopoint

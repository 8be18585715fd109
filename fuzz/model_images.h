#pragma once
// `.oct` images of real models, for the fuzzers' seed corpus and the robustness tests: the
// embedded default model (the committed output of octopoint-prepare on a real scan) written out
// with the preparer's own serializer, so the bytes are those octopoint-prepare writes.

#include <cstdint>
#include <vector>

#include "renderer/embedded_model.h"

namespace octopoint::fuzzing {

// The whole model, every level, as octopoint-prepare writes its `.oct` file.
std::vector<std::uint8_t> octImage(const EmbeddedModel& model);

// A smaller real model: the finest level of `model` coarsened to `depth` (1 .. its depth), each
// coarse voxel taking the colour of the first fine voxel inside it. One level only.
std::vector<std::uint8_t> coarsenedOctImage(const EmbeddedModel& model, int depth);

}  // namespace octopoint::fuzzing

#pragma once
// `.oct` images of real models, for the fuzzers' seed corpus and the robustness tests: the
// embedded default model (the committed output of octopoint-prepare on a real scan) written out
// with the preparer's own serializer, so the bytes are those octopoint-prepare writes.

#include <cstdint>
#include <vector>

#include "codegen/chunked_writer.h"
#include "octopoint/model.h"

namespace octopoint::fuzzing {

// The whole model, every level, as octopoint-prepare writes its `.oct` file.
std::vector<std::uint8_t> octImage(const EmbeddedModel& model);

// A smaller real model: the finest level of `model` coarsened to `depth` (1 .. its depth), each
// coarse voxel taking the colour of the first fine voxel inside it. One level only.
std::vector<std::uint8_t> coarsenedOctImage(const EmbeddedModel& model, int depth);

// The model as the preparer holds it, with its own depths, or, when `depths` is given, with those
// depths made from its finest level (each at most its finest depth; coarser ones coarsened as the
// chunked writer makes its base: codegen/level_voxels.h).
prepare::PreparedModel preparedModel(const EmbeddedModel& model,
                                     const std::vector<int>& depths = {});

// That model as octopoint-prepare --chunked writes it (format version 3).
std::vector<std::uint8_t> chunkedImage(const EmbeddedModel& model,
                                       const std::vector<int>& depths = {},
                                       const prepare::ChunkedOptions& options = {});

// Recomputes every CRC of a chunked image from its raw bytes (each record's chunk CRC, each record
// table's CRC in the level table, then the head's), so that a test or a fuzzer can change any field
// and reach the checks behind the CRCs. Reads offsets as the format says, within the image's
// bounds; what lies outside is left alone.
void resealChunked(std::vector<std::uint8_t>& image);

}  // namespace octopoint::fuzzing

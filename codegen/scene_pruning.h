#pragma once
// Visibility pruning of a prepared model for a scene's views (docs/scene.md): the orthographic
// cameras judged per depth (codegen/visibility.h) and the perspective eyes over all depths at once
// (codegen/eye_visibility.h); a voxel either kind of view sees is kept.

#include <string>

#include "codegen/prepare.h"
#include "codegen/prepared_model.h"

namespace octopoint::prepare {

// Prunes `model`'s levels (nodes, leaves and normals) to what options.visibility_cameras and
// options.visibility_eyes see; nothing without either. The levels' sample reaches are measured
// first (recordSampleReaches, unless measured already) and every view judged with the splats
// they widen. With eyes, pruned voxels are put back, the first in stream order first, where the
// model's densely sampled depths (denseDepthCount with the reaches) would otherwise change (the
// renderer chooses among those depths by their voxel counts), and a depth no eye draws keeps one
// voxel: the eyes' frames stay the unpruned model's. Throws PrepareError naming
// `path` when an eye cannot be drawn (its message names the eye) or a depth is left without any
// voxel.
void pruneModel(PreparedModel& model, const PrepareOptions& options, const std::string& path);

}  // namespace octopoint::prepare

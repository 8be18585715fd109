#pragma once
// Visibility pruning for perspective views (a scene's "eyes" and "paths", docs/scene.md): a voxel
// is kept when it wins the z-test at some pixel of one of the views, drawn as octopoint-render
// --eye draws them. The check walks every stored depth with the renderer's own perspective walk
// (renderer/perspective_walk.h) and detail by distance over the densely sampled depths, and
// records per pixel the nearest depth key the plot would keep, over the same splat rule
// (renderer/perspective_splat.h) and the splats as wide as the renderer draws them (each level's
// sample reach, widened by the walk itself: widenedHalfExtent, perspectiveSplatMargin). A leaf's
// screen position, splat and depth come from its own path in the tree and the view alone, and which
// depth draws a part of the frame from the node centres alone, so removing the losers leaves every
// winner where it was: from each of these views the pruned model draws the same frame as long as
// its densely sampled depths stay the same (codegen/scene_pruning.h keeps them so).

#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint::prepare {

// For each of `levels` (ascending depths, as a model stores them) with its stored sample reach
// (`sample_reaches`, one per level, Q4 footprints kOneSampleReach..kMaxSampleReach, as the model
// will store them): 1 per leaf some view draws into a pixel at that pixel's nearest depth, else 0.
// Each level's splats are widened by its reach, as the perspective renderer widens them. The
// densely sampled depths (renderer/level_of_detail.h, denseDepthCount on these levels' counts
// and reaches, as PerspectiveRenderer counts them) are drawn together by detail by distance, each
// other level alone (what --depth N draws); levels deeper than the renderer draws are all kept.
// When every level has normals, the frames of the styles that light (their coarser depth code,
// renderer/perspective_depth.h) are judged too. Up to two threads.
std::vector<std::vector<std::uint8_t>> visibleFromEyes(std::span<const LevelView> levels,
                                                       std::span<const std::int32_t> sample_reaches,
                                                       std::span<const PerspectiveView> views);

}  // namespace octopoint::prepare

#include "codegen/scene_pruning.h"

#include <chrono>
#include <cstdint>
#include <vector>

#include "codegen/eye_visibility.h"
#include "codegen/octree_encoder.h"
#include "codegen/prepare_error.h"
#include "codegen/sample_reach.h"
#include "codegen/visibility.h"
#include "renderer/level_of_detail.h"
#include "tools/scan_eye.h"

namespace octopoint::prepare {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The eyes' views of this model, as octopoint-render --eye builds them (its near plane too).
std::vector<PerspectiveView> eyeViews(const PreparedModel& model, const PrepareOptions& options,
                                      const std::string& path) {
  const std::optional<ScanCube> cube = scanCube(model.cube);
  if (!cube) throw PrepareError(path + ": the model records no cube placement for the eyes");
  const std::int64_t near = nearPlaneForDepth(model.levels.back().depth);
  std::vector<PerspectiveView> views;
  for (std::size_t i = 0; i < options.visibility_eyes.size(); ++i) {
    const SceneEye& eye = options.visibility_eyes[i];
    try {
      views.push_back(scanEyeView(*cube, eye.eye, eye.look, eye.fov, near, options.eye_width,
                                  options.eye_height, "scene eye " + std::to_string(i)));
    } catch (const cli::Error& error) {
      throw PrepareError(path + ": " + error.what());
    }
  }
  return views;
}

std::size_t countOf(const std::vector<std::uint8_t>& flags) {
  std::size_t n = 0;
  for (const std::uint8_t flag : flags) n += flag;
  return n;
}

// Marks unkept voxels of `flags` kept, in stream order, until `wanted` are.
void keepAtLeast(std::vector<std::uint8_t>& flags, std::size_t wanted) {
  std::size_t kept = countOf(flags);
  for (std::size_t i = 0; i < flags.size() && kept < wanted; ++i) {
    if (!flags[i]) {
      flags[i] = 1;
      ++kept;
    }
  }
}

// Keeps the renderer's densely sampled depths what they were unpruned (counted with the stored
// reaches, which pruning leaves as they are): each dense depth at one footprint at least
// kDenseGrowth times its coarser neighbour's kept voxels (a depth whose reach draws it whole is
// dense whatever its count), and the first sparse depth (if any) below that.
void keepDenseDepths(const PreparedModel& model, std::vector<std::vector<std::uint8_t>>& flags) {
  // A depth no eye draws (too coarse for all of them) keeps one voxel: a model's depths are not
  // empty, and it is hidden or not drawn in every eye's frame.
  for (std::vector<std::uint8_t>& level : flags) keepAtLeast(level, 1);
  std::vector<std::uint64_t> counts;
  std::vector<std::int32_t> reaches;
  for (const PreparedLevel& level : model.levels) {
    if (level.depth > kMaxRenderDepth) break;
    counts.push_back(level.leaves.size());
    reaches.push_back(level.sample_reach);
  }
  const std::size_t dense = denseDepthCount(counts, reaches);
  for (std::size_t i = 1; i < dense; ++i) {
    if (reaches[i] == kOneSampleReach) keepAtLeast(flags[i], kDenseGrowth * countOf(flags[i - 1]));
  }
  if (dense < counts.size()) {
    const std::size_t sparse = countOf(flags[dense]);
    keepAtLeast(flags[dense - 1], sparse / kDenseGrowth + 1);
  }
}

void keepFlagged(PreparedLevel& level, const std::vector<std::uint64_t>& keys,
                 const std::vector<std::uint8_t>& flags, const std::string& path) {
  std::vector<std::uint64_t> kept_keys;
  std::vector<std::uint8_t> leaves, normals;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!flags[i]) continue;
    kept_keys.push_back(keys[i]);
    leaves.push_back(level.leaves[i]);
    if (!level.normals.empty()) normals.push_back(level.normals[i]);
  }
  if (kept_keys.empty()) {
    throw PrepareError(path + ": no voxel at depth " + std::to_string(level.depth) +
                       " is visible from the scene's views");
  }
  level.nodes = encodeOctree(kept_keys, level.depth);
  level.leaves = std::move(leaves);
  level.normals = std::move(normals);
}

}  // namespace

void pruneModel(PreparedModel& model, const PrepareOptions& options, const std::string& path) {
  if (model.levels.empty() ||
      (options.visibility_cameras.empty() && options.visibility_eyes.empty()))
    return;
  // The reaches are the scan's sampling, measured on the levels as they are: what pruning leaves
  // out no eye sees, and measured on what is left, an eye-pruned level's missing back looked like
  // samples lying farther apart, which widened every splat of its perspective frames (and so
  // changed the frames the pruning keeps the same). Measured first, so that the eyes and the
  // orthographic views are judged with the splats the pruned model will draw.
  recordSampleReaches(model);
  std::vector<std::vector<std::uint8_t>> flags(model.levels.size());
  double eye_seconds = 0;
  if (!options.visibility_eyes.empty()) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<PerspectiveView> views = eyeViews(model, options, path);
    std::vector<LevelView> levels;
    std::vector<std::int32_t> reaches;
    for (const PreparedLevel& level : model.levels) {
      levels.push_back({level.depth, level.nodes, level.leaves, level.normals, {}});
      reaches.push_back(level.sample_reach);
    }
    flags = visibleFromEyes(levels, reaches, views);
    eye_seconds = secondsSince(start) / static_cast<double>(model.levels.size());
  }
  std::vector<std::vector<std::uint64_t>> keys;
  for (std::size_t k = 0; k < model.levels.size(); ++k) {
    PreparedLevel& level = model.levels[k];
    const auto start = std::chrono::steady_clock::now();
    keys.push_back(decodeLeafKeys(level.nodes, level.depth));
    if (flags[k].empty()) flags[k].assign(keys[k].size(), 0);
    if (!options.visibility_cameras.empty()) {
      const std::vector<std::uint8_t> seen =
          visibleVoxels(keys[k], level.depth, options.visibility_cameras, level.sample_reach);
      for (std::size_t i = 0; i < seen.size(); ++i) flags[k][i] |= seen[i];
    }
    level.voxels_before_pruning = level.leaves.size();
    level.bytes_before_pruning = level.nodes.size() + level.leaves.size();
    // The eyes' time shared evenly: they judge every depth at once.
    level.pruning_seconds = secondsSince(start) + eye_seconds;
  }
  if (!options.visibility_eyes.empty()) keepDenseDepths(model, flags);
  for (std::size_t k = 0; k < model.levels.size(); ++k) {
    const auto start = std::chrono::steady_clock::now();
    keepFlagged(model.levels[k], keys[k], flags[k], path);
    model.levels[k].pruning_seconds += secondsSince(start);
  }
}

}  // namespace octopoint::prepare

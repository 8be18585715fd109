#include "codegen/sample_reach.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "codegen/voxelizer.h"

namespace octopoint::prepare {
namespace {

// A square image of cells, each 0 or 1.
struct CellMask {
  std::size_t side = 0;
  std::vector<std::uint8_t> cells;
};

// A level seen along `axis`: which cells (2^shift cells per voxel edge) some voxel covers.
CellMask viewAlong(std::span<const std::uint64_t> keys, int depth, std::size_t axis, int shift) {
  CellMask view{.side = std::size_t{1} << (depth + shift), .cells = {}};
  view.cells.assign(view.side * view.side, 0);
  const std::size_t u_axis = axis == 0 ? 1 : 0, v_axis = axis == 2 ? 1 : 2;
  const std::size_t cells = std::size_t{1} << shift;
  for (const std::uint64_t key : keys) {
    const std::array<std::uint32_t, 3> at = mortonDecode(key, depth);
    for (std::size_t dv = 0; dv < cells; ++dv) {
      std::uint8_t* row = &view.cells[(at[v_axis] * cells + dv) * view.side + at[u_axis] * cells];
      std::fill(row, row + cells, std::uint8_t{1});
    }
  }
  return view;
}

// Per cell, the Chebyshev distance to the nearest cell whose mask value is `target`, capped at
// `cap` (separable: the distance along each row, then the least max(|dv|, row distance) over the
// rows within the cap).
std::vector<std::uint8_t> distanceTo(const CellMask& mask, std::uint8_t target, int cap) {
  const std::size_t side = mask.side;
  const auto capped = static_cast<std::uint8_t>(cap);
  std::vector<std::uint8_t> along_row(side * side, capped);
  for (std::size_t v = 0; v < side; ++v) {
    const std::uint8_t* in = &mask.cells[v * side];
    std::uint8_t* row = &along_row[v * side];
    std::uint8_t run = capped;
    for (std::size_t u = 0; u < side; ++u) {
      run = in[u] == target ? 0 : static_cast<std::uint8_t>(std::min(cap, run + 1));
      row[u] = run;
    }
    run = capped;
    for (std::size_t u = side; u-- > 0;) {
      run = row[u] == 0 ? 0 : static_cast<std::uint8_t>(std::min(cap, run + 1));
      row[u] = std::min(row[u], run);
    }
  }
  std::vector<std::uint8_t> distance(side * side, capped);
  for (std::size_t v = 0; v < side; ++v) {
    for (std::size_t u = 0; u < side; ++u) {
      std::uint8_t best = along_row[v * side + u];
      for (std::size_t dv = 1; dv < best; ++dv) {
        const auto step = static_cast<std::uint8_t>(dv);
        if (v >= dv) best = std::min(best, std::max(step, along_row[(v - dv) * side + u]));
        if (v + dv < side) best = std::min(best, std::max(step, along_row[(v + dv) * side + u]));
      }
      distance[v * side + u] = best;
    }
  }
  return distance;
}

constexpr int kDistanceCap = 2 * kMaxSampleGap;

}  // namespace

MeasuredReach measureReach(std::span<const std::uint64_t> keys, int depth,
                           std::span<const std::uint64_t> coarse_keys, int coarse_depth,
                           std::int32_t coarse_reach) {
  if (depth > kMaxMeasuredDepth || coarse_depth >= depth || depth - coarse_depth > 6) return {};
  // Cells of half a fine voxel: a coarse voxel is 2^scale of them, its half 2^(scale - 1).
  const int scale = depth + 1 - coarse_depth;
  const int coarse_widening = (coarse_reach / 16 - 1) << (scale - 1);
  const int erosion = 1 << scale;
  std::array<std::uint64_t, 3> surface{};
  std::array<std::array<std::uint64_t, kMaxSampleGap + 1>, 3> missed{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    // The coarse level as it draws: its cells within its own reach, less one coarse voxel.
    CellMask reference = viewAlong(coarse_keys, coarse_depth, axis, scale);
    if (coarse_widening > 0) {
      const std::vector<std::uint8_t> to_coarse =
          distanceTo(reference, 1, std::min(kDistanceCap * 2, 255));
      for (std::size_t i = 0; i < to_coarse.size(); ++i)
        reference.cells[i] = to_coarse[i] <= coarse_widening ? 1 : 0;
    }
    const std::vector<std::uint8_t> to_outside = distanceTo(reference, 0, erosion + 1);
    const std::vector<std::uint8_t> to_fine =
        distanceTo(viewAlong(keys, depth, axis, 1), 1, kDistanceCap);
    const std::size_t side = reference.side;
    for (std::size_t v = 0; v < side; ++v) {
      for (std::size_t u = 0; u < side; ++u) {
        const std::size_t i = v * side + u;
        // Inside: no uncovered cell within one coarse voxel, nor the view's edge.
        if (to_outside[i] <= erosion || u < static_cast<std::size_t>(erosion) ||
            v < static_cast<std::size_t>(erosion) || u + erosion >= side || v + erosion >= side)
          continue;
        ++surface[axis];
        // A reach of R footprints covers the cells within R - 1 of a leaf's own two.
        for (int reach = 1; reach <= kMaxSampleGap && reach - 1 < to_fine[i]; ++reach)
          ++missed[axis][static_cast<std::size_t>(reach)];
      }
    }
  }
  // Judged in the views that see at least half as much of the coarse surface as the one that sees
  // most: a view that sees it edge-on is left out, where the coarse voxels' cubes fill walls an
  // airborne scan never samples (judging all three gave the scan-line grid's depth 7 a reach of 3
  // where it needs 1). The reach is the least that one of them sees whole: a surface a scanner
  // sampled at a grazing angle is sparse only when seen from above it (the default model's table:
  // 8.4% open at depth 8 seen from above, 0.3% seen from the front), which is hole filling's job,
  // not a reason to blur every view.
  const std::uint64_t most = std::max({surface[0], surface[1], surface[2]});
  const auto broad = [&](std::size_t axis) {
    return surface[axis] != 0 && 2 * surface[axis] >= most;
  };
  const auto whole = [&](std::size_t axis, int reach) {
    return missed[axis][static_cast<std::size_t>(reach)] * 1000 <=
           surface[axis] * kHoleShareLimitPerMille;
  };
  for (int reach = 1; reach <= kMaxSampleGap; ++reach) {
    bool some_view = false, every_view = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      if (!broad(axis)) continue;
      some_view = some_view || whole(axis, reach);
      every_view = every_view && whole(axis, reach);
    }
    if (some_view) return {.reach = 16 * reach, .whole_in_every_view = every_view};
  }
  return {.reach = 16 * kMaxSampleGap, .whole_in_every_view = false};
}

std::int32_t measureSampleReach(std::span<const std::uint64_t> keys, int depth,
                                std::span<const std::uint64_t> coarse_keys, int coarse_depth,
                                std::int32_t coarse_reach) {
  return measureReach(keys, depth, coarse_keys, coarse_depth, coarse_reach).reach;
}

std::vector<std::int32_t> measureSampleReaches(std::span<const LevelVoxels> levels) {
  std::vector<std::int32_t> reaches;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    reaches.push_back(i == 0
                          ? 16
                          : measureSampleReach(levels[i].keys, levels[i].depth, levels[i - 1].keys,
                                               levels[i - 1].depth, reaches.back()));
  }
  return reaches;
}

void recordSampleReaches(PreparedModel& model) {
  if (model.sample_reaches_measured) return;
  std::vector<LevelVoxels> levels;
  for (const PreparedLevel& level : model.levels) {
    LevelVoxels voxels = decodeLevel(level);
    voxels.colours = {};  // only the keys are measured
    levels.push_back(std::move(voxels));
  }
  const std::vector<std::int32_t> reaches = measureSampleReaches(levels);
  for (std::size_t i = 0; i < model.levels.size(); ++i)
    model.levels[i].sample_reach = static_cast<std::uint8_t>(reaches[i]);
  model.sample_reaches_measured = true;
}

}  // namespace octopoint::prepare

#pragma once
// Computes a scene's visibility cells (docs/city.md, "Visibility cells"; the file:
// renderer/cell_table.h). The grid covers the instances' extent in x and z in cells of `edge`
// scene edges and the layers `y` (the heights the eye may take); per cell, the instances seen
// from anywhere in it, conservatively:
//  - samples: on the layers' bounds every cell's corners (shared with its neighbours) and centre,
//    and `random_samples` points inside each cell (seeded by `seed` and the cell: deterministic);
//  - from each sample the scene is drawn by octopoint's own integer renderer (SceneRenderer) to the
//    six faces of a cube (90 degrees, face x face pixels); an instance is seen when it submitted a
//    point (its subtrees not all passed over by the frustum or the occlusion tiles: what wins a
//    pixel always does);
//  - widened: instances whose cube lies within `margin` of the cell (so what stands next to the eye
//    is never lost to a sample inside it), then the union of the cell and its eight neighbours in
//    its layer (what a point between samples sees, one of them saw).
// With CellBuildOptions::spacing the samples are a denser lattice and the widening is by distance;
// with CellBuildOptions::winners an instance is seen only where it wins a pixel.
// Cost: (samples) x 6 frames of face x face pixels; memory a byte per cell and instance. Host side.
// With CellBuildOptions::eps above 0 the sets come from eroded occlusion maps instead
// (tools/cell_occlusion.h): conservative for every eye in the cell by construction, without the
// neighbours' union.

#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/scene.h"
#include "renderer/cell_table.h"
#include "renderer/perspective.h"
#include "tools/cell_occlusion.h"

namespace octopoint {

struct CellBuildOptions {
  std::int64_t edge = 2 * kPerspectiveUnit;  // Q.24 scene edges: 64 m in the generated city
  // Layer bounds, increasing (y down), Q.24 scene edges: in the generated city 48 m, 3 m and 0.5 m
  // above the ground (the street, then up to above the roofs; higher, the eye sees everything).
  std::vector<std::int64_t> y = {-3 * kPerspectiveUnit / 2, -3 * kPerspectiveUnit / 32,
                                 -kPerspectiveUnit / 64};
  int face = 64;           // pixels of a cube face
  int random_samples = 1;  // per cell, besides the lattice
  std::uint32_t seed = 1;
  std::int64_t margin = kPerspectiveUnit / 2;  // Q.24 scene edges
  bool neighbours = true;                      // widen by the eight neighbours' sets
  // An instance is seen when it wins a pixel of a sample's face (the word the frame keeps), not
  // when it submits a point: far tighter, and no longer conservative by the tiles' slack.
  bool winners = false;
  // Not empty (Q.24 scene edges, each above 0): the samples are a lattice over the whole grid in x
  // and z on every layer bound, of spacing[k] on bound k (one value: every bound's), with no
  // corners, centres or seeded points; a cell takes what every sample within `reach` of its box
  // saw on its layer's bounds: a widening by distance instead of the neighbours' union.
  std::vector<std::int64_t> spacing;
  std::int64_t reach = 0;
  // Above 0: the eroded occlusion maps instead (tools/cell_occlusion.h): samples covering each
  // cell's layer box so that every point of it lies within `eps` (Q.24 scene edges) of one, each
  // standing for the eyes within eps of it; surfaces nearer than `near_occluder` do not occlude;
  // `face` pixels a cube face without its border; no lattice, no seeded points, no neighbours.
  std::int64_t eps = 0;
  std::int64_t near_occluder = 0;
  int near_steps = 1;  // maps at near_occluder times 1, 2, 4, ...: the set is what all let in
  // The eroded maps' ground plane (OcclusionSampling::ground): y = ground_y, Q.24, y down.
  bool ground = false;
  std::int64_t ground_y = 0;
  bool radii = false;  // OcclusionSampling::radii: the erosion narrower towards a face's centre
  // OcclusionSampling::depth_windows: each window sized by the nearest depth in it.
  bool depth_windows = false;
};

struct CellBuild {
  CellGrid grid;
  std::vector<std::vector<std::uint32_t>> sets;  // per cell, sorted
  std::uint64_t samples = 0, frames = 0;
  int side = 0;         // pixels of a frame's side (a face with the erosion's border)
  int rho = 0;          // the erosion's radius in pixels (0: none)
  OcclusionStats maps;  // the eroded maps' pixels and enclosed samples (eps above 0)
};

// Empty grid (nx 0) when the options are out of their limits (an edge below 1/64 scene edge, layers
// not increasing or more than kMaxCellLayers, a grid past kMaxCellsPerAxis); the tool checks them
// first, with one line each.
CellBuild buildCells(std::span<const ModelView* const> models,
                     std::span<const SceneInstance> instances, const CellBuildOptions& options);

}  // namespace octopoint

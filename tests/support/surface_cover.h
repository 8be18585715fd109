#pragma once
// How much of a surface a frame leaves empty (docs/splats.md, "Samples coarser than the voxel"):
// the pixels a level covers drawn with its sample reach, against the surface the model's coarsest
// depth covers. Shared by the tests of the measured reach and of the default depth cut.

#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/model.h"

namespace octopoint::testing {

// Per pixel, whether `level` of `model`, drawn for `camera` with `reach` (Q4 footprints) in box or
// smooth splats (fixed_fast), covers it; empty when the camera or the drawing is refused. With
// `ppm_path` not empty, the frame is written there (on a white background).
std::vector<bool> levelCover(const ModelView& model, const LevelView& level, const Camera& camera,
                             std::int32_t reach, bool smooth, const std::string& ppm_path = "");

// The reference surface: what `model`'s level of `depth` covers with one footprint, less a border
// as wide as its voxel (whose cubes reach past a ground's edge by up to one).
std::vector<bool> referenceSurface(const ModelView& model, int depth, const Camera& camera);

// Per mille of the `reference` pixels `drawn` leaves empty (1000 when there is no reference, or
// no drawing).
int emptyPerMille(const std::vector<bool>& reference, const std::vector<bool>& drawn);

}  // namespace octopoint::testing

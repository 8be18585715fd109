#pragma once
// The walk-through measurements of docs/perspective.md ("Walk-through views"): one perspective view
// of a model drawn as octopoint-render draws it (PerspectiveRenderer: detail by distance, culled),
// measured against double precision and against the orthographic frame of the same screen.

#include <cstdint>
#include <vector>

#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint::lab {

struct PerspectiveMeasurement {
  // Every leaf the frame's walks hand over (the voxels the frame draws, of whichever stored depth
  // detail by distance chose), against the double-precision projection of its centre.
  std::uint64_t leaves = 0;
  // The largest |x| or |y| difference, pixels, of a leaf that draws: one whose splat (within
  // sqrt(3) half voxels of its centre) reaches the screen. The walk passes over subtrees, not
  // leaves, so it also hands over leaves wholly off the screen, which draw nothing: counted in
  // max_position_all_px (every leaf handed over).
  double max_position_px = 0;
  double max_position_all_px = 0;
  // The same voxels drawn with the double-precision projection of their 8 corners (each covers the
  // pixels whose centres lie in the corners' convex hull): the silhouette. A voxel that reaches
  // behind the near plane is left out of it (counted in near_voxels).
  std::uint64_t silhouette_pixels = 0;
  std::uint64_t silhouette_empty = 0;  // of those, left empty by the frame
  std::uint64_t near_voxels = 0;
  double emptyShare() const {
    return silhouette_pixels == 0
               ? 0
               : static_cast<double>(silhouette_empty) / static_cast<double>(silhouette_pixels);
  }
  // The frame: its covered pixels and the points handed to the plot with and without occlusion
  // culling (the same frame, bit for bit).
  std::uint64_t covered_pixels = 0;
  std::uint64_t points_culled = 0;
  std::uint64_t points_unculled = 0;
  std::uint64_t hidden_subtrees = 0;
  std::vector<int> depths;  // the stored depths the frame chose among
  // Time: median thread CPU time of `rounds` frames each, interleaved, frame clear included: the
  // perspective frame (culled, by distance) and the orthographic frame of the same screen
  // as octopoint-render draws it by default (fixed_fast, yaw 0, pitch 0, zoom 1, depth auto:
  // orthographic_depth, orthographic_leaves leaves). No timing where that frame is refused.
  double perspective_ms = 0;
  double orthographic_ms = 0;
  std::uint64_t orthographic_leaves = 0;
  int orthographic_depth = 0;
};

// Measures `view` of `model` (the view's camera at any size the renderer takes); `rounds` >= 1
// timed frames of each kind (0: no timing). `frame_rgb` (if not null) receives the frame drawn,
// RGB888, and `silhouette` (if not null) the silhouette, one byte a pixel (1: in it).
PerspectiveMeasurement measurePerspective(const ModelView& model, const PerspectiveView& view,
                                          int rounds,
                                          std::vector<std::uint8_t>* frame_rgb = nullptr,
                                          std::vector<std::uint8_t>* silhouette = nullptr);

}  // namespace octopoint::lab

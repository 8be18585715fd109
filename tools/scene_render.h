#pragma once
// octopoint-render --city SCENE.json (docs/city.md): a scene of many models (tools/scene_file.h)
// drawn in perspective from --eye/--look or along --path, in colour, into one z-buffer
// (renderer/scene_renderer.h). The eye is in scene edges (the cube edge of a model at scale 0),
// the scene's own axes (x right, y down, z away), within 128 scene edges of the scene's origin.

#include <string>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "tools/perspective_render.h"

namespace octopoint {

struct CityJob {
  std::string scene;  // --city
  std::string cells;  // --cells: the scene's visibility cells (renderer/cell_table.h), or empty
  Camera camera;      // its size
  std::string output;
  Rgb background;
};

// Throws cli::Error, one line, for options that do not go with --city.
void checkCityOptions(const PerspectiveOptions& options, bool orbit_camera, bool other_source,
                      bool depth, bool fill, bool sheet, bool style);

// Draws and writes what `options` asks for (--eye or --path), prints one line saying what;
// cli::Error, one line, leaving no file, when it cannot.
void runCity(const PerspectiveOptions& options, const CityJob& job);

}  // namespace octopoint

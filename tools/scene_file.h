#pragma once
// A scene file's models loaded (docs/city.md, "Scene files"; its text: tools/scene_text.h): each a
// model file beside the scene (a chunked one spliced back whole) or an embedded model, their
// palettes merged into one (a frame holds one palette index per pixel): together they may hold at
// most 255 distinct colours (index 255 marks an empty pixel). Host side.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/scene.h"
#include "renderer/cell_table.h"
#include "tools/scene_text.h"

namespace octopoint {
// One of a scene's models, its leaves' colours mapped into the scene's palette.
struct SceneModel;

struct LoadedScene {
  LoadedScene();
  ~LoadedScene();
  LoadedScene(const LoadedScene&) = delete;
  LoadedScene& operator=(const LoadedScene&) = delete;

  std::string label;  // the scene file, for messages
  std::vector<std::unique_ptr<SceneModel>> owned;
  std::vector<const ModelView*> models;  // the models as the renderer takes them
  std::vector<SceneInstance> instances;
  std::uint64_t model_bytes = 0;  // the models' files (or embedded arrays)
};

// Reads the scene file and its models; a cli::Error, one line, when any of it is refused.
std::unique_ptr<LoadedScene> loadScene(const std::string& path);

// Reads the scene's visibility cells (octopoint-pvs, renderer/cell_table.h: at most 64 MiB),
// validated against its instances; a cli::Error, one line, when they are refused.
CellTable loadCellTable(const std::string& path, const LoadedScene& scene);

}  // namespace octopoint

#include "tools/scene_file.h"

#include <array>
#include <filesystem>
#include <map>

#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/text.h"
#include "renderer/chunked_assembly.h"
#include "tools/model_source.h"

namespace octopoint {

struct SceneModel {
  std::unique_ptr<LoadedModel> loaded;
  std::unique_ptr<AssembledModel> assembled;  // a chunked file, spliced back whole
  std::array<std::uint8_t, 256 * 3> palette{};
  std::vector<std::vector<std::uint8_t>> leaves;  // per level: the colours in the scene's palette
  std::vector<EmbeddedLevel> levels;
  EmbeddedModel embedded{};
  std::optional<ModelView> view;  // points into the above and the loaded bytes
};

LoadedScene::LoadedScene() = default;
LoadedScene::~LoadedScene() = default;

namespace {

// The model an entry names: an embedded model's name (no '/' or '.'), or a file beside the scene.
std::unique_ptr<SceneModel> loadSceneModel(const std::string& entry,
                                           const std::filesystem::path& folder,
                                           const std::string& where) {
  auto model = std::make_unique<SceneModel>();
  const bool embedded = entry.find_first_of("/.") == std::string::npos;
  try {
    model->loaded =
        embedded ? loadModel(entry, "", false) : loadModel("", (folder / entry).string(), true);
  } catch (const ModelLoadError& error) {
    throw cli::Error(where + ": " + error.what());
  } catch (const cli::Error& error) {  // the file refused before it is read
    throw cli::Error(where + ": " + error.what());
  }
  if (model->loaded->chunked) {
    model->assembled = assembleChunked(*model->loaded->chunked);
    if (model->assembled == nullptr)
      throw cli::Error(where + ": " + model->loaded->label + ": its chunks do not make one model");
  }
  return model;
}

const ModelView& sourceView(const SceneModel& model) {
  return model.assembled ? *model.assembled->view : *model.loaded->view;
}

// Puts every model's leaves in one palette: the first model's as it is (a scene of one model draws
// its own colours, index for index), then each further colour the first time it is seen.
void sharePalette(LoadedScene& scene) {
  std::vector<Rgb> palette;
  std::map<std::array<std::uint8_t, 3>, std::uint8_t> index_of;
  for (std::size_t m = 0; m < scene.owned.size(); ++m) {
    SceneModel& model = *scene.owned[m];
    const ModelView& source = sourceView(model);
    std::array<std::uint8_t, 256> map{};
    for (int c = 0; c < source.paletteCount(); ++c) {
      const Rgb rgb = source.paletteColour(c);
      const std::array<std::uint8_t, 3> key{rgb.r, rgb.g, rgb.b};
      auto found = index_of.find(key);
      if (found == index_of.end() || m == 0) {
        if (palette.size() == 255) {
          throw cli::Error(scene.label + ": key \"models[" + std::to_string(m) +
                           "]\": the models' palettes hold more than 255 colours together (a "
                           "frame holds one palette index a pixel)");
        }
        found = index_of.emplace(key, static_cast<std::uint8_t>(palette.size())).first;
        if (m == 0) found->second = static_cast<std::uint8_t>(palette.size());
        palette.push_back(rgb);
      }
      map[static_cast<std::size_t>(c)] = found->second;
    }
    model.leaves.resize(static_cast<std::size_t>(source.levelCount()));
    for (int i = 0; i < source.levelCount(); ++i) {
      const LevelView& level = source.level(i);
      std::vector<std::uint8_t>& leaves = model.leaves[static_cast<std::size_t>(i)];
      leaves.resize(level.leaves.size());
      for (std::size_t k = 0; k < leaves.size(); ++k) leaves[k] = map[level.leaves[k]];
      // The level's sample reach goes with it: the scene draws its splats as wide as the model
      // alone does.
      model.levels.push_back({static_cast<std::uint8_t>(level.depth), level.nodes.data(),
                              static_cast<std::uint32_t>(level.nodes.size()), leaves.data(),
                              static_cast<std::uint32_t>(leaves.size()), nullptr,
                              static_cast<std::uint8_t>(source.sampleReach(i))});
    }
  }
  for (const std::unique_ptr<SceneModel>& owned : scene.owned) {
    SceneModel& model = *owned;
    for (std::size_t c = 0; c < palette.size(); ++c) {
      model.palette[3 * c] = palette[c].r;
      model.palette[3 * c + 1] = palette[c].g;
      model.palette[3 * c + 2] = palette[c].b;
    }
    const ModelView& source = sourceView(model);
    model.embedded =
        EmbeddedModel{"scene model",
                      format::kVersion6,
                      static_cast<std::uint8_t>(
                          source.colourIsSynthetic() ? format::v2::kFlagSyntheticColour : 0),
                      source.cubeEdgePicometres(),
                      static_cast<std::uint16_t>(palette.size()),
                      model.palette.data(),
                      0,
                      nullptr,
                      static_cast<std::uint8_t>(model.levels.size()),
                      model.levels.data(),
                      source.cubePlacement()};
    ModelIssue issue;
    model.view = ModelView::fromEmbedded(model.embedded, &issue);
    if (!model.view) {
      throw cli::Error(scene.label +
                       ": a model with the scene's palette is refused: " + describe(issue.error));
    }
    scene.models.push_back(&*model.view);
  }
}

}  // namespace

std::unique_ptr<LoadedScene> loadScene(const std::string& path) {
  const SceneText text = parseSceneText(cli::readInputFile(path, kSceneFileInput), path);
  auto scene = std::make_unique<LoadedScene>();
  scene->label = cli::displayPath(path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < text.models.size(); ++i) {
    scene->owned.push_back(loadSceneModel(
        text.models[i], folder, scene->label + ": key \"models[" + std::to_string(i) + "]\""));
    const SceneModel& model = *scene->owned.back();
    scene->model_bytes += model.loaded->file_bytes.size();
  }
  sharePalette(*scene);
  scene->instances = text.instances;
  return scene;
}

CellTable loadCellTable(const std::string& path, const LoadedScene& scene) {
  CellTableError why;
  CellTable table =
      CellTable::parse(cli::readInputBytes(path, cli::InputKind{"cell table", kMaxCellTableBytes}),
                       static_cast<std::uint32_t>(scene.instances.size()), &why);
  if (why != CellTableError::kNone)
    throw cli::Error(cli::displayPath(path) + ": cell table " + describe(why));
  return table;
}

}  // namespace octopoint

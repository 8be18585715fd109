#include "tools/scene_text.h"

#include "cli/error.h"
#include "cli/strict_json.h"

namespace octopoint {
namespace {

using nlohmann::json;

class SceneReader : public cli::JsonReader<cli::Error> {
 public:
  using JsonReader::JsonReader;

  std::int64_t integer(const json& value, const std::string& key, std::int64_t low,
                       std::int64_t high) const {
    if (!value.is_number_integer()) fail(key, "expected an integer");
    // A uint64 past INT64_MAX is out of every range here.
    if (value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t{INT64_MAX})
      fail(key, "out of range " + std::to_string(low) + ".." + std::to_string(high));
    const auto x = value.get<std::int64_t>();
    if (x < low || x > high)
      fail(key,
           std::to_string(x) + " is outside " + std::to_string(low) + ".." + std::to_string(high));
    return x;
  }
};

SceneInstance readInstance(const SceneReader& reader, const json& item, std::size_t index,
                           std::size_t models) {
  const std::string where = "instances[" + std::to_string(index) + "]";
  if (!item.is_array() || item.size() != 6)
    reader.fail(where, "expected [model, x, y, z, turn, scale]");
  SceneInstance instance;
  instance.model = static_cast<std::uint32_t>(
      reader.integer(item[0], where + ".model", 0, static_cast<std::int64_t>(models) - 1));
  std::int64_t at[3];
  const char* axes[3] = {".x", ".y", ".z"};
  for (std::size_t a = 0; a < 3; ++a) {
    at[a] = reader.integer(item[a + 1], where + axes[a], -kMaxSceneCoordinate, kMaxSceneCoordinate);
  }
  instance.transform.at = {at[0], at[1], at[2]};
  instance.transform.turn =
      Angle::fromTurns16(reader.integer(item[4], where + ".turn", 0, Angle::kUnitsPerTurn - 1));
  instance.transform.scale =
      static_cast<int>(reader.integer(item[5], where + ".scale", kMinSceneScale, kMaxSceneScale));
  return instance;
}

}  // namespace

SceneText parseSceneText(const std::string& text, const std::string& path) {
  const SceneReader reader(path);
  const json root = cli::parseStrictJson(text, path, "a scene file");
  reader.onlyKeys(root, "", {"models", "instances"});
  SceneText scene;
  if (!root.contains("models") || !root["models"].is_array() || root["models"].empty() ||
      root["models"].size() > kMaxSceneModels) {
    reader.fail("models",
                "expected a list of 1 to " + std::to_string(kMaxSceneModels) + " model names");
  }
  for (std::size_t i = 0; i < root["models"].size(); ++i) {
    const json& name = root["models"][i];
    const std::string key = "models[" + std::to_string(i) + "]";
    if (!name.is_string() || name.get<std::string>().empty())
      reader.fail(key, "expected a model file or an embedded model's name");
    scene.models.push_back(name.get<std::string>());
  }
  if (!root.contains("instances") || !root["instances"].is_array() || root["instances"].empty() ||
      root["instances"].size() > kMaxSceneInstances) {
    reader.fail("instances",
                "expected a list of 1 to " + std::to_string(kMaxSceneInstances) + " instances");
  }
  const json& instances = root["instances"];
  scene.instances.reserve(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i)
    scene.instances.push_back(readInstance(reader, instances[i], i, scene.models.size()));
  return scene;
}

}  // namespace octopoint

#pragma once
// The text of a scene file (docs/city.md, "Scene files"): a few models and many instances of them,
// read strictly (cli/strict_json.h) and validated as the renderer will take them, each failure one
// line naming the file and the field. Host side: the renderer gets the integer instances of
// octopoint/scene.h; tools/scene_file.h loads the models.
//
//   {"models": ["house.oct", "tree.oct"],
//    "instances": [[0, 0, 0, 0, 0, 0], [1, 33554432, 0, -16777216, 16384, -2]]}
//
// An instance is [model, x, y, z, turn, scale]: the model's index, where its cube's centre goes in
// Q.24 scene edges (integers, |x| <= 2^44), the turn about the vertical axis in 1/65536 turn
// (0..65535) and the scale (the cube edge is 2^scale scene edges, -8..8). A model is a file path
// (relative to the scene file's folder; a chunked file is spliced back whole) or the name of a
// model embedded in this binary. The models' palettes are merged into one (a frame holds one
// palette index per pixel): together they may hold at most 255 distinct colours (index 255 marks an
// empty pixel).

#include <cstdint>
#include <string>
#include <vector>

#include "cli/input_file.h"
#include "octopoint/scene.h"

namespace octopoint {

// JSON at about 30 bytes an instance: a million instances and their models' names.
inline constexpr cli::InputKind kSceneFileInput{"scene file", std::uint64_t{64} << 20};

struct SceneText {
  std::vector<std::string> models;  // as written
  std::vector<SceneInstance> instances;
};

// Reads and checks the text of a scene file: a cli::Error "PATH: key K: what" otherwise.
SceneText parseSceneText(const std::string& text, const std::string& path);

}  // namespace octopoint

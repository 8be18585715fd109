// city_walk: 10,000 seeded random walk steps through a generated city (docs/city.md,
// "Collision"), flying and with gravity, with collision against its instances
// (renderer/scene_collision.h). After every step the eye must be outside every building (the
// box of the building model's voxels, carried by its instance's transform in double precision)
// and above the ground (the street and pavement tiles' top), and the walk must have slid along
// walls (a step stopped by a wall whose eye still moved across it). Exit 1 with one line on the
// first failure. Run by ctest city.walk_collision (tests/city_walk.cmake) on a small city.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "renderer/collision_move.h"
#include "renderer/scene_collision.h"
#include "tools/scene_file.h"
#include "tools/scene_text.h"

namespace octopoint {
namespace {

constexpr const char* kUsage =
    R"(usage: city_walk SCENE.json [--steps N] [--seed N] --solid NAME[,NAME...] --ground NAME[,NAME...]

Walks N random steps (default 10000) through the scene flying, then N with gravity, and checks
that the eye never enters the box of a --solid model's instance nor goes under the top of a
--ground model's instance (models named as the scene file names them).
)";

struct Box {
  double lo[3] = {1e300, 1e300, 1e300};
  double hi[3] = {-1e300, -1e300, -1e300};
};

// The box of a level's voxels, Q.24 model units.
Box voxelBox(const LevelView& level) {
  Box box;
  const std::uint8_t* cursor = level.nodes.data();
  auto visit = [&](auto& self, int tree_level, ModelPoint lo) -> void {
    const unsigned mask = *cursor++;
    const std::int64_t edge = kPerspectiveUnit >> (tree_level + 1);
    for (unsigned child = 0; child < 8; ++child) {
      if ((mask >> child & 1u) == 0) continue;
      const ModelPoint c{lo.x + ((child >> 2) & 1) * edge, lo.y + ((child >> 1) & 1) * edge,
                         lo.z + (child & 1) * edge};
      if (tree_level + 1 < level.depth) {
        self(self, tree_level + 1, c);
        continue;
      }
      const std::int64_t corner[3] = {c.x, c.y, c.z};
      for (int a = 0; a < 3; ++a) {
        box.lo[a] = std::min(box.lo[a], static_cast<double>(corner[a]));
        box.hi[a] = std::max(box.hi[a], static_cast<double>(corner[a] + edge));
      }
    }
  };
  const std::int64_t half = kPerspectiveUnit / 2;
  visit(visit, 0, {-half, -half, -half});
  return box;
}

// The eye in the instance's model units (the inverse of at + 2^s Ry(turn) p), in doubles.
void toModel(const InstanceTransform& t, const ModelPoint& eye, double m[3]) {
  const double turn = t.turn.turns16() * 2 * M_PI / Angle::kUnitsPerTurn;
  const double scale = std::ldexp(1.0, t.scale);
  const double dx = static_cast<double>(eye.x - t.at.x), dy = static_cast<double>(eye.y - t.at.y),
               dz = static_cast<double>(eye.z - t.at.z);
  m[0] = (std::cos(turn) * dx - std::sin(turn) * dz) / scale;
  m[1] = dy / scale;
  m[2] = (std::sin(turn) * dx + std::cos(turn) * dz) / scale;
}

std::set<std::string> names(const std::string& list) {
  std::set<std::string> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) out.insert(name);
  return out;
}

struct City {
  std::vector<SceneInstance> instances;
  std::vector<bool> solid, ground;  // per model
  std::vector<Box> boxes;           // per model
  double ground_top = 1e300;        // the ground tiles' highest top (smallest y), Q.24
  double min_x = 1e300, max_x = -1e300, min_z = 1e300, max_z = -1e300;  // the ground's extent
};

// The first instance of a solid model whose box holds the eye strictly, or -1.
long insideSolid(const City& city, const ModelPoint& eye) {
  for (std::size_t i = 0; i < city.instances.size(); ++i) {
    const SceneInstance& instance = city.instances[i];
    if (!city.solid[instance.model]) continue;
    double m[3];
    toModel(instance.transform, eye, m);
    const Box& box = city.boxes[instance.model];
    if (m[0] > box.lo[0] && m[0] < box.hi[0] && m[1] > box.lo[1] && m[1] < box.hi[1] &&
        m[2] > box.lo[2] && m[2] < box.hi[2]) {
      return static_cast<long>(i);
    }
  }
  return -1;
}

struct WalkCount {
  int blocked = 0, slid = 0;
};

WalkCount walk(const City& city, const SceneCollision& world, const WalkBody& body, int steps,
               unsigned seed, const char* label) {
  std::mt19937_64 random(seed);
  constexpr double kMetre = kPerspectiveUnit / 32.0;  // one scene edge is 32 m
  const double margin = 2 * kMetre;
  // Start over the middle of the first ground tile (a crossing in a generated city).
  ModelPoint eye{std::llround(city.min_x + 16 * kMetre),
                 std::llround(city.ground_top) - body.eye_height - 2 * body.radius,
                 std::llround(city.min_z + 16 * kMetre)};
  if (body.eye_height == 0) eye.y = std::llround(city.ground_top - 1.7 * kMetre);
  WalkCount count;
  for (int step = 0; step < steps; ++step) {
    const double yaw = static_cast<double>(random() % 65536) * 2 * M_PI / 65536;
    const double length = static_cast<double>(random() % 4096) / 4096 * 4 * kMetre;
    double dx = length * std::sin(yaw), dz = length * std::cos(yaw);
    // Back towards the middle near the city's edge.
    if (eye.x + dx < city.min_x + margin || eye.x + dx > city.max_x - margin) dx = -dx;
    if (eye.z + dz < city.min_z + margin || eye.z + dz > city.max_z - margin) dz = -dz;
    double dy = 0;
    if (random() % 5 == 0) dy = (static_cast<double>(random() % 4096) / 2048 - 1) * 3 * kMetre;
    if (eye.y + dy < city.ground_top - 40 * kMetre) dy = std::fabs(dy);  // above the towers
    const ModelPoint to{eye.x + std::llround(dx), eye.y + std::llround(dy),
                        eye.z + std::llround(dz)};
    const CollisionMove move = moveWithCollision(world, body, eye, to);
    if (move.blocked) {
      ++count.blocked;
      // Moved across the line asked for by more than a tenth of the step: slid along a wall.
      const double mx = static_cast<double>(move.eye.x - eye.x),
                   mz = static_cast<double>(move.eye.z - eye.z);
      const double across = std::fabs(mx * dz - mz * dx) / std::max(length, 1.0);
      if (across > length / 10 && length > kMetre) ++count.slid;
    }
    eye = move.eye;
    if (const long i = insideSolid(city, eye); i >= 0) {
      throw cli::Error(std::string(label) + ": step " + std::to_string(step) +
                       ": the eye is inside instance " + std::to_string(i));
    }
    if (static_cast<double>(eye.y) >= city.ground_top) {
      throw cli::Error(std::string(label) + ": step " + std::to_string(step) +
                       ": the eye is under the ground");
    }
  }
  std::printf("%s: %d steps, %d stopped by a wall or the ground, %d slid along one\n", label, steps,
              count.blocked, count.slid);
  if (count.slid < steps / 200) {
    throw cli::Error(std::string(label) + ": only " + std::to_string(count.slid) +
                     " steps slid along a wall (at least 0.5%)");
  }
  return count;
}

int run(int argc, char** argv) {
  cli::ArgumentReader args(argc, argv);
  std::string scene_path, solid_list, ground_list;
  int steps = 10000;
  unsigned seed = 1;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (args.is("--steps")) {
      steps = cli::parseInt(args.name(), args.value(), 1, 1'000'000);
    } else if (args.is("--seed")) {
      seed = static_cast<unsigned>(cli::parseInt(args.name(), args.value(), 0, 1'000'000'000));
    } else if (args.is("--solid")) {
      solid_list = args.value();
    } else if (args.is("--ground")) {
      ground_list = args.value();
    } else if (args.isPlain() && scene_path.empty()) {
      scene_path = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (scene_path.empty() || solid_list.empty() || ground_list.empty())
    throw cli::Error("give SCENE.json, --solid and --ground");
  const std::unique_ptr<LoadedScene> scene = loadScene(scene_path);
  std::ifstream file(scene_path);
  std::stringstream text;
  text << file.rdbuf();
  const SceneText parsed = parseSceneText(text.str(), scene_path);
  const std::set<std::string> solid = names(solid_list), ground = names(ground_list);
  City city;
  city.instances = scene->instances;
  for (std::size_t m = 0; m < scene->models.size(); ++m) {
    city.solid.push_back(solid.contains(parsed.models[m]));
    city.ground.push_back(ground.contains(parsed.models[m]));
    city.boxes.push_back(voxelBox(scene->models[m]->finestLevel()));
  }
  for (const SceneInstance& instance : city.instances) {
    if (!city.ground[instance.model]) continue;
    const InstanceTransform& t = instance.transform;
    const Box& box = city.boxes[instance.model];
    const double scale = std::ldexp(1.0, t.scale), half = kPerspectiveUnit / 2.0 * scale;
    city.ground_top = std::min(city.ground_top, static_cast<double>(t.at.y) + box.lo[1] * scale);
    city.min_x = std::min(city.min_x, static_cast<double>(t.at.x) - half);
    city.max_x = std::max(city.max_x, static_cast<double>(t.at.x) + half);
    city.min_z = std::min(city.min_z, static_cast<double>(t.at.z) - half);
    city.max_z = std::max(city.max_z, static_cast<double>(t.at.z) + half);
  }
  if (city.ground_top == 1e300) throw cli::Error("no instance of a --ground model");
  SceneError error;
  const SceneCollision world(scene->models, scene->instances, &error);
  if (error != SceneError::kNone || world.unindexedModel())
    throw cli::Error(scene_path + ": cannot collide with this scene");
  const WalkBody flying{kPerspectiveUnit / 128, 0};
  const WalkBody walking{kPerspectiveUnit / 128, std::llround(1.7 / 32 * kPerspectiveUnit)};
  walk(city, world, flying, steps, seed, "flying");
  walk(city, world, walking, steps, seed + 1, "gravity");
  return 0;
}

}  // namespace
}  // namespace octopoint

int main(int argc, char** argv) {
  return octopoint::cli::runTool("city_walk", argc, argv, octopoint::run);
}

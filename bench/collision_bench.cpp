// Collision queries (renderer/collision.h, docs/perspective.md "Collision"): spheres about the eye
// at the table's edge of the default model (the view of the perspective benchmarks), against its
// finest level (depth 8, 62,502 leaves). Queries per second (items_per_second) and the boxes each
// tests, per radius; and walk steps (renderer/collision_move.h) per second. And a scene of 10^4
// instances (docs/city.md, "Collision"): scene_bench's 100 x 100 instances of the default model,
// one scene edge apart, quarter turns, scale -1; spheres of 1/128 scene edge (25 cm in the
// generated city) about the middle of it, through the grid (renderer/scene_collision.h) and by
// testing every instance, side by side; and walk steps of 1/8 scene edge (4 m) with gravity.
// With OCTOPOINT_CITY=DIR/city.json (scripts/make-city), the same on that city: `collision/city/`,
// its spheres at eye height (1.7 m) over the ground anywhere in it.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench/instance_grid.h"
#include "bench/register_benchmarks.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "renderer/collision.h"
#include "renderer/collision_move.h"
#include "renderer/scene_collision.h"
#ifdef OCTOPOINT_COLLISION_BENCH_CITY
#include "tools/scene_file.h"
#endif

namespace octopoint {
namespace {

const ModelView& collisionBenchModel() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

// 4,096 centres within 1/8 cube edge of the eye at the table's edge, (0, 0.28, -0.46) cube edges
// from the centre (tests/core/perspective_cull_test.cpp's view), seeded.
std::vector<ModelPoint> tableEdgeCentres() {
  std::mt19937_64 random(33);
  const ModelPoint eye{0, kPerspectiveUnit * 28 / 100, -kPerspectiveUnit * 46 / 100};
  const std::int64_t span = kPerspectiveUnit / 4;
  std::vector<ModelPoint> centres(4096);
  for (ModelPoint& c : centres) {
    auto near = [&](std::int64_t v) {
      return v - span / 2 + static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(span));
    };
    c = {near(eye.x), near(eye.y), near(eye.z)};
  }
  return centres;
}

void sphereQueries(benchmark::State& state, std::int64_t radius) {
  const std::optional<CollisionModel> collision = CollisionModel::of(collisionBenchModel());
  if (!collision) {
    state.SkipWithError("no collision model");
    return;
  }
  const std::vector<ModelPoint> centres = tableEdgeCentres();
  CollisionStats stats;
  std::uint64_t met = 0;
  for (const ModelPoint& c : centres) met += collision->meets({c, radius}, &stats) ? 1 : 0;
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(collision->meets({centres[next], radius}));
    next = (next + 1) % centres.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["boxes_per_query"] =
      static_cast<double>(stats.boxes_tested) / static_cast<double>(centres.size());
  state.counters["met_share"] = static_cast<double>(met) / static_cast<double>(centres.size());
}

// Walk steps of `step` along x from free centres, each toward the next centre.
void timeWalkSteps(benchmark::State& state, const CollisionWorld& world, const WalkBody& body,
                   const std::vector<ModelPoint>& centres, std::int64_t step) {
  std::vector<ModelPoint> starts;
  for (const ModelPoint& c : centres) {
    if (!world.meets({c, body.radius})) starts.push_back(c);
  }
  std::size_t next = 0;
  std::uint64_t blocked = 0, steps = 0;
  for (auto _ : state) {
    const ModelPoint& from = starts[next];
    const ModelPoint& toward = starts[(next + 1) % starts.size()];
    const ModelPoint to{from.x + (toward.x > from.x ? step : -step), from.y, from.z};
    const CollisionMove move = moveWithCollision(world, body, from, to);
    benchmark::DoNotOptimize(move.eye);
    blocked += move.blocked ? 1 : 0;
    ++steps;
    next = (next + 1) % starts.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["blocked_share"] = static_cast<double>(blocked) / static_cast<double>(steps);
}

// Walk steps of 1/16 cube edge (16 sub-steps of the radius, 1/256 edge) from free centres about
// the table's edge, flying or with gravity (eye height 1/16 edge).
void walkSteps(benchmark::State& state, std::int64_t eye_height) {
  const std::optional<CollisionModel> collision = CollisionModel::of(collisionBenchModel());
  if (!collision) {
    state.SkipWithError("no collision model");
    return;
  }
  const CollisionInstance instance{&*collision, {}};
  timeWalkSteps(state, CollisionInstances({&instance, 1}), {kPerspectiveUnit / 256, eye_height},
                tableEdgeCentres(), kPerspectiveUnit / 16);
}

struct CollisionBenchScene {
#ifdef OCTOPOINT_COLLISION_BENCH_CITY
  std::unique_ptr<LoadedScene> loaded;  // a city's models, when loaded
#endif
  std::vector<SceneInstance> instances;
  std::optional<SceneCollision> collision;
  std::vector<ModelPoint> centres;  // 4,096 within 2 scene edges of the middle, seeded
};

const CollisionBenchScene& collisionBenchScene() {
  static const CollisionBenchScene* built = [] {
    auto* s = new CollisionBenchScene;
    constexpr std::int64_t kEdge = kPerspectiveUnit;
    s->instances = bench::instanceGrid();
    const ModelView* models[] = {&collisionBenchModel()};
    SceneError error;
    s->collision.emplace(models, s->instances, &error);
    std::mt19937_64 random(34);
    for (int k = 0; k < 4096; ++k) {
      auto within = [&random](std::int64_t half) {
        return static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(2 * half)) - half;
      };
      s->centres.push_back({within(2 * kEdge), within(kEdge / 4), within(2 * kEdge)});
    }
    return s;
  }();
  return *built;
}

#ifdef OCTOPOINT_COLLISION_BENCH_CITY
// The city OCTOPOINT_CITY names (ground at y = 0, one scene edge 32 m), or null.
const CollisionBenchScene* collisionBenchCity() {
  static const CollisionBenchScene* built = []() -> const CollisionBenchScene* {
    const char* path = std::getenv("OCTOPOINT_CITY");
    if (path == nullptr) return nullptr;
    auto* s = new CollisionBenchScene;
    try {
      s->loaded = loadScene(path);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "collision_bench: OCTOPOINT_CITY: %s\n", error.what());
      std::exit(1);
    }
    s->instances = s->loaded->instances;
    SceneError error;
    s->collision.emplace(s->loaded->models, s->instances, &error);
    if (error != SceneError::kNone || s->collision->unindexedModel()) {
      std::fprintf(stderr, "collision_bench: OCTOPOINT_CITY: %s: cannot collide with it\n", path);
      std::exit(1);
    }
    std::int64_t low = 0, high = 0;
    for (const SceneInstance& instance : s->instances) {
      low = std::min(low, instance.transform.at.x);
      high = std::max(high, instance.transform.at.x);
    }
    std::mt19937_64 random(35);
    const std::int64_t eye_y = -kPerspectiveUnit * 17 / 320;  // 1.7 m over the ground
    for (int k = 0; k < 4096; ++k) {
      auto across = [&] {
        return low + static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(high - low));
      };
      s->centres.push_back({across(), eye_y, across()});
    }
    return s;
  }();
  return built;
}

#endif

void sceneQueries(benchmark::State& state, const CollisionBenchScene& s, bool through_grid) {
  const std::int64_t radius = kPerspectiveUnit / 128;
  const auto meets = [&](const ModelPoint& c, CollisionStats* stats) {
    return through_grid ? s.collision->meets({c, radius}, stats)
                        : sphereMeets(s.collision->instances(), {c, radius}, stats);
  };
  CollisionStats stats;
  std::uint64_t met = 0;
  for (const ModelPoint& c : s.centres) met += meets(c, &stats) ? 1 : 0;
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(meets(s.centres[next], nullptr));
    next = (next + 1) % s.centres.size();
  }
  state.SetItemsProcessed(state.iterations());
  const auto per_query = [&s](std::uint64_t n) {
    return static_cast<double>(n) / static_cast<double>(s.centres.size());
  };
  state.counters["instances_per_query"] =
      through_grid ? per_query(stats.instances_tested) : static_cast<double>(s.instances.size());
  state.counters["boxes_per_query"] = per_query(stats.boxes_tested);
  state.counters["met_share"] = per_query(met);
}

// Steps of 1/8 scene edge with gravity (eye height 1.7/32 scene edge) through the grid.
void sceneWalkSteps(benchmark::State& state, const CollisionBenchScene& s) {
  timeWalkSteps(state, *s.collision, {kPerspectiveUnit / 128, kPerspectiveUnit * 17 / 320},
                s.centres, kPerspectiveUnit / 8);
}

}  // namespace

void registerAll() {
  const auto scenes = [](const std::string& name, const CollisionBenchScene& (*scene)()) {
    benchmark::RegisterBenchmark(
        ("collision/" + name + "/sphere_grid").c_str(),
        [scene](benchmark::State& state) { sceneQueries(state, scene(), true); });
    benchmark::RegisterBenchmark(
        ("collision/" + name + "/sphere_every_instance").c_str(),
        [scene](benchmark::State& state) { sceneQueries(state, scene(), false); });
    benchmark::RegisterBenchmark(
        ("collision/" + name + "/walk_step_gravity").c_str(),
        [scene](benchmark::State& state) { sceneWalkSteps(state, scene()); });
  };
  scenes("scene_10000", collisionBenchScene);
#ifdef OCTOPOINT_COLLISION_BENCH_CITY
  if (std::getenv("OCTOPOINT_CITY") != nullptr)
    scenes("city", []() -> const CollisionBenchScene& { return *collisionBenchCity(); });
#endif
  benchmark::RegisterBenchmark("collision/table_edge/walk_step_flying", walkSteps, 0);
  benchmark::RegisterBenchmark("collision/table_edge/walk_step_gravity", walkSteps,
                               kPerspectiveUnit / 16);
  // Radii of 1/256, 1/64 and 1/16 cube edge (1, 4 and 16 depth-8 voxels).
  for (const int divisor : {256, 64, 16}) {
    benchmark::RegisterBenchmark(
        ("collision/table_edge/sphere_edge_over_" + std::to_string(divisor)).c_str(), sphereQueries,
        kPerspectiveUnit / divisor);
  }
}

}  // namespace octopoint

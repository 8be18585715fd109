#pragma once
// The benchmarks' scene of 10^4 instances (scene_bench, collision_bench): one model placed on a
// 100 x 100 grid of one model cube edge (kPerspectiveUnit, Q.24) about the origin, each turned by
// a quarter turn picked from its place, at scale -1 (half a cube edge: streets between them).

#include <cstdint>
#include <vector>

#include "octopoint/scene.h"
#include "renderer/perspective.h"

namespace octopoint::bench {

inline std::vector<SceneInstance> instanceGrid() {
  constexpr std::int64_t kEdge = kPerspectiveUnit;
  std::vector<SceneInstance> instances;
  instances.reserve(100 * 100);
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      instances.push_back({0,
                           {{(i - 50) * kEdge, 0, (j - 50) * kEdge},
                            Angle::fromTurns16(((i * 7 + j) & 3) * 16384),
                            -1}});
    }
  }
  return instances;
}

}  // namespace octopoint::bench

#pragma once
// The generated city's streets (tests/support/make_city.cpp: its street tiles found as the
// instances of the model named street.oct), for the lab's city tools (octopoint-city-measure,
// octopoint-city-walk): seeded positions on a street, on a crossing or above the roofs, and random
// walks through the streets. Host side: doubles.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "cli/error.h"
#include "renderer/perspective.h"
#include "tools/scene_file.h"
#include "tools/scene_text.h"

namespace octopoint::city_streets {

constexpr std::int64_t kEdge = kPerspectiveUnit;  // one scene edge, Q.24
constexpr double kMetre = 1.0 / 32;               // the generated city's scene edge is 32 m

inline std::int64_t q24(double edges) {
  return std::llround(std::ldexp(edges, kPerspectiveUnitBits));
}

struct Pose {
  Point3<std::int64_t> eye;
  double yaw = 0, pitch = 0;  // degrees
};

// The street tiles by their grid position (tile centres lie on whole scene edges).
class Streets {
 public:
  Streets(const LoadedScene& scene, const SceneText& text) {
    for (std::size_t m = 0; m < text.models.size(); ++m)
      if (text.models[m].ends_with("street.oct")) street_model_ = static_cast<std::int64_t>(m);
    if (street_model_ < 0)
      throw cli::Error(scene.label + ": no street.oct model: not a generated city");
    for (const SceneInstance& instance : scene.instances) {
      const auto& at = instance.transform.at;
      low_x_ = std::min(low_x_, at.x);
      high_x_ = std::max(high_x_, at.x);
      low_z_ = std::min(low_z_, at.z);
      high_z_ = std::max(high_z_, at.z);
      if (static_cast<std::int64_t>(instance.model) == street_model_) tiles_[key(at.x, at.z)] = 1;
    }
    for (const auto& [k, unused] : tiles_) {
      const auto [i, j] = k;
      const bool along_z = street(i, j - 1) && street(i, j + 1);
      const bool along_x = street(i - 1, j) && street(i + 1, j);
      (along_z && along_x ? crossings_ : streets_).push_back(k);
    }
    if (streets_.empty() || crossings_.empty()) throw cli::Error(scene.label + ": no streets");
  }

  bool street(std::int64_t i, std::int64_t j) const {
    if (i < key(low_x_, 0).first || i > key(high_x_, 0).first || j < key(0, low_z_).second ||
        j > key(0, high_z_).second) {
      return true;  // outside the city: open
    }
    return tiles_.count({i, j}) != 0;
  }
  bool streetAt(std::int64_t x, std::int64_t z) const {
    const auto [i, j] = key(x, z);
    return tiles_.count({i, j}) != 0;
  }
  Pose onStreet(std::mt19937& random, bool crossing) const {
    const auto& list = crossing ? crossings_ : streets_;
    const auto [i, j] = list[random() % list.size()];
    std::uniform_real_distribution<double> along(-0.5, 0.5), across(-0.25, 0.25), turn(0, 360);
    const bool along_z = street(i, j - 1) && street(i, j + 1);
    // Along the street up to half a tile, across it a quarter (8 m: the lanes); a crossing either
    // way.
    double dx = across(random);
    double dz = crossing ? across(random) : along(random);
    if (!crossing && !along_z) std::swap(dx, dz);
    return {{i * kEdge + q24(dx), q24(-1.6 * kMetre), j * kEdge + q24(dz)}, turn(random), 0};
  }
  Pose above(std::mt19937& random, double metres, double pitch) const {
    std::uniform_int_distribution<std::int64_t> x(low_x_, high_x_), z(low_z_, high_z_);
    std::uniform_real_distribution<double> turn(0, 360);
    return {{x(random), q24(-metres * kMetre), z(random)}, turn(random), pitch};
  }
  // A walk through the streets, 2 m a step, turning at random at crossings.
  std::vector<Pose> walk(std::mt19937& random, std::size_t steps) const {
    Pose pose = onStreet(random, true);
    const auto [ci, cj] = key(pose.eye.x, pose.eye.z);
    pose.eye.x = ci * kEdge;
    pose.eye.z = cj * kEdge;
    static constexpr int kDirections[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    int direction = static_cast<int>(random() % 4);
    const std::int64_t step = q24(2 * kMetre);
    std::uniform_real_distribution<double> look(-40, 40), tilt(-10, 10);
    std::vector<Pose> poses;
    while (poses.size() < steps) {
      const auto [i, j] = key(pose.eye.x, pose.eye.z);
      const bool at_centre = std::llabs(pose.eye.x - i * kEdge) < step / 2 &&
                             std::llabs(pose.eye.z - j * kEdge) < step / 2;
      if (at_centre) {
        for (int tries = 0; tries < 8; ++tries) {
          const int d = tries < 4 ? static_cast<int>(random() % 4) : tries - 4;
          if (streetAt((i + kDirections[d][0]) * kEdge, (j + kDirections[d][1]) * kEdge)) {
            direction = d;
            break;
          }
        }
        pose.eye.x = i * kEdge;
        pose.eye.z = j * kEdge;
      }
      pose.eye.x += kDirections[direction][0] * step;
      pose.eye.z += kDirections[direction][1] * step;
      const double heading = direction == 0 ? 90 : direction == 1 ? 0 : direction == 2 ? 270 : 180;
      poses.push_back({pose.eye, heading + look(random), tilt(random)});
    }
    return poses;
  }

 private:
  static std::pair<std::int64_t, std::int64_t> key(std::int64_t x, std::int64_t z) {
    return {(x + (x >= 0 ? kEdge / 2 : -kEdge / 2)) / kEdge,
            (z + (z >= 0 ? kEdge / 2 : -kEdge / 2)) / kEdge};
  }
  std::int64_t street_model_ = -1;
  std::int64_t low_x_ = INT64_MAX, high_x_ = INT64_MIN, low_z_ = INT64_MAX, high_z_ = INT64_MIN;
  std::map<std::pair<std::int64_t, std::int64_t>, int> tiles_;
  std::vector<std::pair<std::int64_t, std::int64_t>> streets_, crossings_;
};

}  // namespace octopoint::city_streets

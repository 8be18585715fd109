#pragma once
// Scenes of many models (docs/city.md): a few distinct models, each placed many times by an
// integer transform. The bytes follow the models, not the instances: an instance is a model index
// and its transform, 32 bytes.
//
// Units: a scene position is in Q.24 scene edges (int64): one scene edge is the cube edge of a
// model drawn at scale 0. An instance's transform maps a model point p (Q.24 cube edges about the
// model cube's centre, the model's own axes: x right, y down, z away) to the scene point
//   at + 2^scale * Ry(turn) * p,
// Ry the turn about the vertical (y) axis as octopoint/fixed.h writes it ([[c, 0, s], [0, 1, 0],
// [-s, 0, c]]): an instance turned by T looks, from a camera of yaw Y, as the model does from yaw
// Y - T. Integer only.

#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/fixed.h"

namespace octopoint {

inline constexpr std::uint32_t kMaxSceneModels = 256;
inline constexpr std::uint32_t kMaxSceneInstances = std::uint32_t{1} << 20;
inline constexpr int kMinSceneScale = -8;  // a model's cube edge 1/256 of a scene edge
inline constexpr int kMaxSceneScale = 8;   // to 256 scene edges
// |at| on every axis: 2^20 scene edges, so that differences of positions fit int64 with room.
inline constexpr std::int64_t kMaxSceneCoordinate = std::int64_t{1} << 44;

struct InstanceTransform {
  Point3<std::int64_t> at{};  // where the model cube's centre goes, Q.24 scene edges
  Angle turn;                 // about the vertical axis, 1/65536 turn
  int scale = 0;              // the model's cube edge is 2^scale scene edges
};

struct SceneInstance {
  std::uint32_t model = 0;  // index into the scene's models
  InstanceTransform transform;
};

enum class SceneError : std::uint8_t {
  kNone,
  kNoModels,            // no model, or more than kMaxSceneModels
  kNoInstances,         // no instance, or more than kMaxSceneInstances
  kBadModelIndex,       // an instance names a model the scene does not have
  kBadScale,            // outside kMinSceneScale..kMaxSceneScale
  kScaleAboveScene,     // a move to a scale larger than any the scene was made with
  kCoordinateTooLarge,  // |at| beyond kMaxSceneCoordinate on some axis
  kBadInstanceIndex,    // a move of an instance the scene does not have
};

const char* describe(SceneError error);

// The transform's own checks (scale and coordinates).
SceneError checkTransform(const InstanceTransform& transform);

}  // namespace octopoint

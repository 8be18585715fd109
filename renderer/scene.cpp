#include "octopoint/scene.h"

namespace octopoint {

const char* describe(SceneError error) {
  switch (error) {
    case SceneError::kNone:
      return "ok";
    case SceneError::kNoModels:
      return "a scene holds 1 to 256 models";
    case SceneError::kNoInstances:
      return "a scene holds 1 to 1048576 instances";
    case SceneError::kBadModelIndex:
      return "an instance names a model the scene does not hold";
    case SceneError::kBadScale:
      return "scale outside -8..8";
    case SceneError::kScaleAboveScene:
      return "scale larger than any the scene was made with";
    case SceneError::kCoordinateTooLarge:
      return "coordinate beyond 2^44 (2^20 scene edges)";
    case SceneError::kBadInstanceIndex:
      return "no such instance";
  }
  return "unknown error";
}

SceneError checkTransform(const InstanceTransform& transform) {
  if (transform.scale < kMinSceneScale || transform.scale > kMaxSceneScale)
    return SceneError::kBadScale;
  for (const std::int64_t a : {transform.at.x, transform.at.y, transform.at.z}) {
    if (a < -kMaxSceneCoordinate || a > kMaxSceneCoordinate) return SceneError::kCoordinateTooLarge;
  }
  return SceneError::kNone;
}

}  // namespace octopoint

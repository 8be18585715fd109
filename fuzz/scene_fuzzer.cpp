// libFuzzer harness for scene files (tools/scene_text.h, docs/city.md): any bytes either parse into
// a scene the renderer accepts or end in cli::Error with one line, nothing else. A scene that
// parses (its models named, but the default model stands in for each, every name the same) is
// made into a SceneRenderer, which must accept it, and, when small, drawn from two eyes and every
// instance moved: no crash, no sanitizer report, whatever the transforms (|at| up to 2^44, scales
// -8..8, any turn). A small scene is also made into a SceneCollision (renderer/scene_collision.h),
// which must accept it and answer spheres about every instance as testing every instance answers
// them, and walk a step with gravity.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/error.h"
#include "octopoint/framebuffer.h"
#include "octopoint/models.h"
#include "renderer/collision_move.h"
#include "renderer/scene_collision.h"
#include "renderer/scene_renderer.h"
#include "tools/scene_text.h"

namespace {

using namespace octopoint;

const ModelView& standIn() {
  static const ModelView model = [] {
    ModelIssue issue;
    return *ModelView::fromEmbedded(*models::defaultModel(), &issue);
  }();
  return model;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  SceneText scene;
  try {
    scene = parseSceneText(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const cli::Error& error) {
    if (std::string(error.what()).find('\n') != std::string::npos) std::abort();
    return 0;
  }
  const std::vector<const ModelView*> models(scene.models.size(), &standIn());
  SceneError error;
  SceneRenderer renderer(models, scene.instances, &error);
  if (error != SceneError::kNone) std::abort();  // the file's checks are the renderer's
  if (scene.instances.size() > 16) return 0;     // drawing: small scenes only, for speed
  Framebuffer frame(32, 24);
  for (const ModelPoint eye : {ModelPoint{0, 0, -2 * kPerspectiveUnit},
                               ModelPoint{100 * kPerspectiveUnit, -kPerspectiveUnit, 7}}) {
    PerspectiveCamera camera;
    camera.eye = eye;
    camera.width = 32;
    camera.height = 24;
    PerspectiveView view;
    if (buildPerspectiveView(camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
      std::abort();
    frame.clear();
    if (!renderer.draw(view, frame)) std::abort();
  }
  if (scene.models.size() <= 4) {  // each model indexed for collision: few, for speed
    SceneCollision collision(models, scene.instances, &error);
    if (error != SceneError::kNone || collision.unindexedModel()) std::abort();
    for (const SceneInstance& instance : scene.instances) {
      for (const std::int64_t radius :
           {std::int64_t{1}, kPerspectiveUnit / 128, kMaxCollisionRadius}) {
        const CollisionSphere sphere{instance.transform.at, radius};
        if (collision.meets(sphere) != sphereMeets(collision.instances(), sphere)) std::abort();
      }
    }
    const WalkBody body{kPerspectiveUnit / 128, kPerspectiveUnit / 16};
    const ModelPoint from = scene.instances.front().transform.at;
    static_cast<void>(moveWithCollision(collision, body, from,
                                        {from.x + kPerspectiveUnit, from.y, from.z - 12345}));
    // Every other instance moved (out of the grid): still met exactly where it is now.
    for (std::size_t i = 0; i < scene.instances.size(); i += 2) {
      InstanceTransform moved = scene.instances[i].transform;
      moved.at.z = moved.at.z / 2 - kPerspectiveUnit;
      moved.turn = moved.turn + Angle::fromDegrees(71);
      if (collision.place(i, moved) != SceneError::kNone) std::abort();
      const CollisionSphere sphere{moved.at, kPerspectiveUnit / 128};
      if (collision.meets(sphere) != sphereMeets(collision.instances(), sphere)) std::abort();
    }
  }
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    InstanceTransform moved = scene.instances[i].transform;
    moved.at.x /= 2;
    moved.turn = moved.turn + Angle::fromDegrees(33);
    if (renderer.place(i, moved) != SceneError::kNone) std::abort();
  }
  return 0;
}

// libFuzzer harness for the preparer's scene files (codegen/scene.h, docs/scene.md): any bytes
// either parse into a Scene or end in PrepareError with one line, nothing else. A scene that
// parses has its work within the bounds parseScene promised (views and view pixels), and when its
// views are few they are made into cameras and its depths are chosen, as octopoint-prepare does
// before it reads the scan: no crash, no sanitizer report, whatever the angles, zooms and eyes.
// "paths" name files relative to a folder that does not exist, so no run reads the disk.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "codegen/prepare_error.h"
#include "codegen/scene.h"
#include "codegen/scene_views.h"

namespace {

using namespace octopoint::prepare;

// Few enough sampled views to make into cameras on every run without slowing the fuzzer.
constexpr double kViewsToSample = 2'000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Scene scene;
  try {
    scene = parseScene(std::string(reinterpret_cast<const char*>(data), size),
                       "/nonexistent-octopoint-fuzz/scene.json");
  } catch (const PrepareError& error) {
    const std::string message = error.what();
    if (message.empty() || message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  const SceneWork work = sceneWork(scene);
  if (work.views > kMaxSceneViews || work.view_pixels > kMaxSceneViewPixels) std::abort();
  if (scene.eyes.size() > kMaxSceneEyes) std::abort();
  if (work.views <= kViewsToSample) {
    if (scene.orthographic_views && sceneCameras(scene).empty()) std::abort();
    const DepthChoice depths = chooseDepths(scene);
    if (depths.depths.empty()) std::abort();
  }
  return 0;
}

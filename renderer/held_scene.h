#pragma once
// A scene whose models stream in (docs/city.md, "Walking over a slow link"; net/scene_stream.h
// feeds them), drawn from what is held: each model as the parts it holds
// (renderer/chunked_assembly.h, assembleHeldParts: every region at the depth its distance asks
// for, or at the finest depth held there where that is coarser, so never a hole where a coarser
// level is held), each instance drawn as one instance per part of its model, all into one z-buffer
// by SceneRenderer. A model is re-assembled only when it has taken something new (update), and
// the renderer made again only then (rebuild), not per frame.
//
// One palette: the scene's colours in the order the models' heads arrived (the scene file's
// reader, tools/scene_file.h, takes them in the file's order), so a frame's palette indices are
// this scene's own; resolve() turns them into colours. Held whole, each model is one part, the
// model assembleChunked gives: the frame is the complete scene's, colour for colour. Not on a
// bare-metal build (it keeps the parts on the heap). Integer only.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/progressive.h"
#include "octopoint/scene.h"
#include "renderer/chunked_assembly.h"
#include "renderer/scene_renderer.h"

namespace octopoint {

class HeldScene {
 public:
  HeldScene(std::span<const SceneInstance> instances, std::size_t model_count);
  HeldScene(const HeldScene&) = delete;  // the parts point into palette_
  HeldScene& operator=(const HeldScene&) = delete;

  // Model m's parts again from what `model` holds now (under the feeder's lock). False, and model
  // m left as it was, when its colours would take the scene's palette past 255.
  bool update(std::size_t m, const ProgressiveModel& model);
  // The renderer of the parts held now: after updates, before the next frame.
  void rebuild();

  bool holds(std::size_t m) const { return m < models_.size() && models_[m].known; }
  // Parts drawn in all (for the tools' lines).
  std::size_t partCount() const { return part_views_.size(); }

  // Only the instances `ids` (the eye's cell's set; ids into the scene's instances) from now on;
  // copied.
  void setVisibleSet(std::span<const std::uint32_t> ids);
  void clearVisibleSet() { restricted_ = false; }

  // Draws what is held as `view` sees it into `frame` (cleared by the caller). False when nothing
  // is held yet (the frame untouched).
  bool draw(const PerspectiveView& view, FrameView& frame, SceneDrawStats* stats = nullptr);

  // The scene's palette (RGB888 per index; indices past paletteCount() unused): the colour of a
  // frame's pixel is that of FrameView::colourIndexOf(word), 255 marking an empty pixel.
  std::span<const std::uint8_t, 256 * 3> palette() const { return palette_; }
  int paletteCount() const { return palette_count_; }

 private:
  struct Held {
    bool known = false;                   // its head has arrived
    std::array<std::uint8_t, 256> map{};  // its palette into the scene's
    HeldParts parts;                      // its leaves in the scene's palette
    std::vector<int> detail;              // parts.detailDepths()
  };
  std::vector<SceneInstance> instances_;
  std::vector<Held> models_;
  std::array<std::uint8_t, 256 * 3> palette_{};
  int palette_count_ = 0;
  // The renderer's models (every part of every held model) and instances (per scene instance, one
  // per part of its model, consecutive: first_[i], first_[i + 1]).
  std::vector<const ModelView*> part_views_;
  std::vector<std::vector<int>> part_detail_;
  std::vector<SceneInstance> part_instances_;
  std::vector<std::uint32_t> first_;
  std::optional<SceneRenderer> renderer_;
  bool restricted_ = false;
  std::vector<std::uint32_t> visible_, part_visible_;
};

}  // namespace octopoint

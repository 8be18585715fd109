#pragma once
// Walk mode's frame of a chunked model held in part (docs/web.md, "Walk mode"): the held parts
// (renderer/chunked_assembly.h, assembleHeldParts) drawn one after another into one frame, each by
// PerspectiveRenderer with the detail depths of the levels known, so that every region is drawn at
// the depth its distance asks for or at the finest depth held there: the frame octopoint-render
// --url --eye draws from the same parts (tools/perspective_render.cpp, renderPerspectiveParts).
// The parts and their renderers are made again only when the model took something new.

#include <cstdint>
#include <memory>
#include <vector>

#include "octopoint/framebuffer.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"

namespace octopoint::web {

class HeldPartsFrame {
 public:
  // Draws `view` of `model` into `frame` (cleared by the caller), each part a depth coarser when
  // `coarse`; `taken` counts what the model took: a count other than the last draw's assembles the
  // held parts again. Adds what the parts that drew drew to `stats` (as octopoint-render --url
  // --eye counts them). False when nothing could be drawn (no part holds anything yet).
  bool draw(const ProgressiveModel& model, std::uint64_t taken, const PerspectiveView& view,
            bool coarse, Framebuffer& frame, PerspectiveDrawStats* stats);

 private:
  HeldParts parts_;
  std::vector<std::unique_ptr<PerspectiveRenderer>> renderers_;  // one a part, in its order
  std::uint64_t taken_ = 0;
  bool assembled_ = false;
};

}  // namespace octopoint::web

// Walk mode's frame of a chunked model held in part (web/held_parts_frame.h).

#include "web/held_parts_frame.h"

namespace octopoint::web {

bool HeldPartsFrame::draw(const ProgressiveModel& model, std::uint64_t taken,
                          const PerspectiveView& view, bool coarse, Framebuffer& frame,
                          PerspectiveDrawStats* stats) {
  if (!assembled_ || taken != taken_) {
    renderers_.clear();
    parts_ = assembleHeldParts(model);
    for (const std::unique_ptr<AssembledModel>& part : parts_.parts)
      renderers_.push_back(
          std::make_unique<PerspectiveRenderer>(*part->view, parts_.detailDepths()));
    taken_ = taken;
    assembled_ = true;
  }
  PerspectiveRenderer::Options options;  // detail by distance, culled: octopoint-render --eye's
  options.coarser = coarse ? 1 : 0;      // while a key is held: octopoint-view's coarse frames
  bool drew = false;
  // A part that holds none of the depths asked for draws nothing (false): the others do. Only
  // the parts that drew count (tools/perspective_render.cpp's renderPerspectiveParts).
  for (const std::unique_ptr<PerspectiveRenderer>& renderer : renderers_) {
    PerspectiveDrawStats drawn;
    if (!renderer->draw(view, options, frame, &drawn)) continue;
    drew = true;
    stats->leaves += drawn.leaves;
    stats->hidden_subtrees += drawn.hidden_subtrees;
  }
  return drew;
}

}  // namespace octopoint::web

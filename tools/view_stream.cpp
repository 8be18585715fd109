#include "tools/view_stream.h"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective_renderer.h"

namespace octopoint {
namespace {

// A render thread's parts of the model held, and a renderer for each (its indexes built once per
// assembly, its occlusion tiles once per size).
struct HeldWalkParts {
  std::uint64_t content = std::numeric_limits<std::uint64_t>::max();  // assembled at; max: never
  HeldParts parts;
  std::vector<std::unique_ptr<PerspectiveRenderer>> renderers;  // one per part
};

void assemble(net::ModelStream& stream, std::uint64_t content, HeldWalkParts& held) {
  held.renderers.clear();  // before the parts they point into
  held.parts = HeldParts{};
  stream.withModel([&held](ProgressiveModel* model) {
    if (model != nullptr) held.parts = assembleHeldParts(*model);
  });
  for (const std::unique_ptr<AssembledModel>& part : held.parts.parts) {
    held.renderers.push_back(
        std::make_unique<PerspectiveRenderer>(*part->view, held.parts.detailDepths()));
  }
  held.content = content;
}

}  // namespace

ViewDrawFunction streamDrawer(net::ModelStream& stream, std::uint64_t point_budget) {
  const Variant variant = InteractiveConfig{}.variant;
  // One per render thread (FrameSource: L draws kCoarse, H kFine), kept across frames.
  auto snapshots = std::make_shared<std::array<ProgressiveFrame, 2>>();
  for (ProgressiveFrame& snapshot : *snapshots) snapshot.setPointBudget(point_budget);
  return [&stream, variant, snapshots](FrameSource source, const Camera& camera, Framebuffer& frame,
                                       const std::atomic<bool>* abort, int* depth) {
    ProgressiveFrame& snapshot = (*snapshots)[source == FrameSource::kFine ? 1 : 0];
    const ProgressiveModel* model = stream.snapshot(snapshot);
    if (model == nullptr) return true;
    ProgressiveDrawStats stats;
    const int coarser = source == FrameSource::kCoarse ? 1 : 0;
    const bool complete = model->draw(snapshot, camera, variant, frame, &stats, abort, coarser) ||
                          abort == nullptr || !abort->load();
    *depth = stats.drawn_depth;
    return complete;
  };
}

WalkDrawFunction streamWalkDrawer(net::ModelStream& stream,
                                  const std::atomic<std::uint64_t>& content) {
  auto held = std::make_shared<std::array<HeldWalkParts, 2>>();  // one per render thread
  return [&stream, &content, held](FrameSource source, const PerspectiveView& view,
                                   Framebuffer& frame, const std::atomic<bool>* abort,
                                   int* finest_depth) {
    HeldWalkParts& mine = (*held)[source == FrameSource::kFine ? 1 : 0];
    if (const std::uint64_t now = content.load(); now != mine.content) assemble(stream, now, mine);
    *finest_depth = 0;
    const std::span<const int> depths = mine.parts.detailDepths();
    if (depths.empty()) return true;
    PerspectiveRenderer::Options options;  // detail by distance, culled: --url --eye's
    options.coarser = source == FrameSource::kCoarse ? 1 : 0;
    for (const std::unique_ptr<PerspectiveRenderer>& renderer : mine.renderers) {
      // A part that cannot draw the frame (false) leaves it to the others, as --url --eye does.
      static_cast<void>(renderer->draw(view, options, frame, nullptr, abort));
    }
    if (abort != nullptr && abort->load()) return false;
    *finest_depth = depths[depths.size() - 1 -
                           std::min(static_cast<std::size_t>(options.coarser), depths.size() - 1)];
    return true;
  };
}

}  // namespace octopoint

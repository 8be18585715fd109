#pragma once
// Visibility cells applied to a scene's frames (docs/city.md, "Visibility cells"): before each
// frame, a SceneRenderer is restricted to the set of the cell the eye stands in (all of the
// scene when the eye lies outside the cells' grid). One per renderer, and so per thread: it holds
// its own decoding scratch and room for the largest set, made once, so a frame allocates nothing.
// Not on a bare-metal build (as SceneRenderer).

#include <cstdint>
#include <vector>

#include "renderer/cell_table.h"
#include "renderer/scene_renderer.h"

namespace octopoint {

class SceneCells {
 public:
  // `table` (validated against the scene's instance count) must outlive this.
  explicit SceneCells(const CellTable& table)
      : table_(table), visible_(table.largestSet()), scratch_(table.scratch()) {}

  // Restricts `renderer` to what the cell at `eye` (Q.24 scene edges) sees, until the next call;
  // the set is held here, so this must outlive the frames drawn with it.
  void apply(SceneRenderer& renderer, const Point3<std::int64_t>& eye) {
    const std::int64_t cell = table_.cellAt(eye);
    if (cell < 0) {
      renderer.clearVisibleSet();
      return;
    }
    const std::size_t count = table_.decode(static_cast<std::uint32_t>(cell), visible_, scratch_);
    renderer.setVisibleSet(std::span<const std::uint32_t>(visible_).first(count));
  }

 private:
  const CellTable& table_;
  std::vector<std::uint32_t> visible_;  // the eye's cell's set, room for the largest
  CellTable::Scratch scratch_;
};

}  // namespace octopoint

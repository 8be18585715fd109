#pragma once
// The order in which a scene's streamed models are fetched for a walk (docs/city.md, "Walking
// over a slow link"): one list over every distinct model, most urgent first. The caller gives
// tiers, most urgent first (the instances the eye's cell sees, or those in view; then the cells
// ahead in the direction of motion; ...), each a view and the instances it considers. Per tier,
// each instance in reach (and in view, unless the tier takes what its view does not show) is seen
// through its own model view (renderer/scene_view.h), and that model's order for it is
// PerspectiveFetchOrder's (record tables, then chunks, each only as fine as its distance asks).
// The lists merge by key: the tier (at most four: the later ones share the fourth's rank), then
// the level, coarse first (a coarse chunk serves every instance of its model: measured better than
// largest on screen first, docs/city.md), then nearest first: the region's nearest depth over its
// edge, both in the model's units (so the instance's scale drops out); then its place in its
// instance's order. A record table counts as a region of its level at the instance's nearest
// point, a head as the whole cube there, at level 0. An item several instances want takes its most
// urgent key. Transport-free.

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "octopoint/progressive.h"
#include "octopoint/scene.h"
#include "renderer/perspective.h"
#include "renderer/perspective_fetch.h"

namespace octopoint::net {

// One tier of the order: a view and the instances it considers.
struct SceneFetchTier {
  PerspectiveView view;
  bool every_instance = true;            // else only `instances`
  std::vector<std::uint32_t> instances;  // ids into the scene's instances
  bool include_invisible = false;        // also what the view does not show (around the eye)
};

struct SceneFetchEntry {
  std::uint32_t model = 0;
  bool head = false;  // the model's head (item unused)
  FetchItem item;
  std::uint64_t key = 0;  // smaller is more urgent
};

class SceneFetchOrder {
 public:
  // `models[m]`: model m, or null while its head has not arrived. Fills `out` with every wanted
  // item (each once), most urgent first.
  void order(std::span<ProgressiveModel* const> models, std::span<const SceneInstance> instances,
             std::span<const SceneFetchTier> tiers, std::vector<SceneFetchEntry>& out);

 private:
  void addInstance(std::span<ProgressiveModel* const> models, const SceneInstance& instance,
                   const SceneFetchTier& tier, std::uint64_t rank);
  void want(const SceneFetchEntry& entry);

  PerspectiveFetchOrder perspective_order_;
  std::vector<FetchItem> items_;                       // one instance's order
  std::vector<std::uint32_t> nearest_;                 // its chunks' nearest depths
  std::unordered_map<std::uint64_t, std::size_t> at_;  // an item's entry in wanted_
  std::vector<SceneFetchEntry> wanted_;
};

}  // namespace octopoint::net

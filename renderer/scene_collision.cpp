#include "renderer/scene_collision.h"

#include <algorithm>

namespace octopoint {
namespace {

// The grid holds at most this many cells per instance, and at least kMinCells may be had.
constexpr std::int64_t kCellsPerInstance = 4;
constexpr std::int64_t kMinCells = 4096;

// A point past the scene's coordinates (2^44) plus the widest box (2^32) is off the grid;
// clamping it here keeps every difference within 64 bits.
constexpr std::int64_t kOffGrid = std::int64_t{1} << 46;

// The bit length of v > 0: the smallest b with v < 2^b.
int bitLength(std::int64_t v) {
  int bits = 0;
  while (bits < 62 && (std::int64_t{1} << bits) <= v) ++bits;
  return bits;
}

}  // namespace

SceneCollision::SceneCollision(std::span<const ModelView* const> models,
                               std::span<const SceneInstance> instances, SceneError* error) {
  *error = SceneError::kNone;
  if (models.empty() || models.size() > kMaxSceneModels) {
    *error = SceneError::kNoModels;
  } else if (instances.empty() || instances.size() > kMaxSceneInstances) {
    *error = SceneError::kNoInstances;
  }
  for (std::size_t i = 0; i < instances.size() && *error == SceneError::kNone; ++i) {
    *error = instances[i].model >= models.size() ? SceneError::kBadModelIndex
                                                 : checkTransform(instances[i].transform);
  }
  if (*error != SceneError::kNone) return;
  models_.reserve(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    std::optional<CollisionModel> model = CollisionModel::of(*models[m]);
    if (!model) {
      unindexed_model_ = m;
      return;
    }
    models_.push_back(std::move(*model));
  }
  // The instances' boxes on the ground plane, and the widest.
  std::int64_t max_x = 0, max_z = 0, widest = 1;
  instances_.reserve(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const InstanceTransform& t = instances[i].transform;
    instances_.push_back({&models_[instances[i].model], t});
    const std::int64_t across = instanceReach(t.scale).across;
    widest = std::max(widest, 2 * across);
    if (i == 0) {
      min_x_ = t.at.x - across, min_z_ = t.at.z - across;
      max_x = t.at.x + across, max_z = t.at.z + across;
    }
    min_x_ = std::min(min_x_, t.at.x - across), min_z_ = std::min(min_z_, t.at.z - across);
    max_x = std::max(max_x, t.at.x + across), max_z = std::max(max_z, t.at.z + across);
  }
  // Cells at least as wide as the widest box, and few enough.
  const std::int64_t most_cells =
      std::max(kMinCells, kCellsPerInstance * static_cast<std::int64_t>(instances.size()));
  for (cell_shift_ = bitLength(widest);; ++cell_shift_) {
    cells_x_ = ((max_x - min_x_) >> cell_shift_) + 1;
    cells_z_ = ((max_z - min_z_) >> cell_shift_) + 1;
    if (cells_x_ * cells_z_ <= most_cells) break;
  }
  // Counted, then filled (a run per cell).
  const auto cellsOf = [this](const InstanceTransform& t, auto visit) {
    const std::int64_t across = instanceReach(t.scale).across;
    const std::int64_t x0 = (t.at.x - across - min_x_) >> cell_shift_,
                       x1 = (t.at.x + across - min_x_) >> cell_shift_,
                       z0 = (t.at.z - across - min_z_) >> cell_shift_,
                       z1 = (t.at.z + across - min_z_) >> cell_shift_;
    for (std::int64_t x = x0; x <= x1; ++x) {
      for (std::int64_t z = z0; z <= z1; ++z) visit(static_cast<std::size_t>(x * cells_z_ + z));
    }
  };
  cell_start_.assign(static_cast<std::size_t>(cells_x_ * cells_z_) + 1, 0);
  for (const CollisionInstance& instance : instances_)
    cellsOf(instance.transform, [this](std::size_t cell) { ++cell_start_[cell + 1]; });
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_items_.resize(cell_start_.back());
  std::vector<std::uint32_t> filled(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    cellsOf(instances_[i].transform,
            [&](std::size_t cell) { cell_items_[filled[cell]++] = static_cast<std::uint32_t>(i); });
  }
  moved_.assign(instances_.size(), 0);
  moving_.reserve(instances_.size());
  valid_ = true;
}

SceneError SceneCollision::place(std::size_t i, const InstanceTransform& transform) {
  if (!valid_ || i >= instances_.size()) return SceneError::kBadInstanceIndex;
  if (const SceneError error = checkTransform(transform); error != SceneError::kNone) return error;
  instances_[i].transform = transform;
  if (moved_[i] == 0) {
    moved_[i] = 1;
    moving_.push_back(static_cast<std::uint32_t>(i));  // within the reserved capacity
  }
  return SceneError::kNone;
}

bool SceneCollision::meets(const CollisionSphere& sphere, CollisionStats* stats) const {
  if (!valid_ || sphere.radius < 1 || sphere.radius > kMaxCollisionRadius) return false;
  const std::int64_t cx = std::clamp(sphere.centre.x, -kOffGrid, kOffGrid),
                     cz = std::clamp(sphere.centre.z, -kOffGrid, kOffGrid);
  // The cells the sphere's box covers, clipped to the grid.
  const std::int64_t x0 = std::max<std::int64_t>(0, (cx - sphere.radius - min_x_) >> cell_shift_),
                     x1 = std::min(cells_x_ - 1, (cx + sphere.radius - min_x_) >> cell_shift_),
                     z0 = std::max<std::int64_t>(0, (cz - sphere.radius - min_z_) >> cell_shift_),
                     z1 = std::min(cells_z_ - 1, (cz + sphere.radius - min_z_) >> cell_shift_);
  for (std::int64_t x = x0; x <= x1; ++x) {
    for (std::int64_t z = z0; z <= z1; ++z) {
      const auto cell = static_cast<std::size_t>(x * cells_z_ + z);
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const std::uint32_t i = cell_items_[k];
        if (moved_[i] != 0) continue;  // tested below, where it is now
        if (stats != nullptr) ++stats->instances_tested;
        if (instanceMeets(instances_[i], sphere, stats)) return true;
      }
    }
  }
  for (const std::uint32_t i : moving_) {
    if (stats != nullptr) ++stats->instances_tested;
    if (instanceMeets(instances_[i], sphere, stats)) return true;
  }
  return false;
}

}  // namespace octopoint

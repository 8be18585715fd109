#include "tools/cell_build.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "octopoint/framebuffer.h"
#include "renderer/scene_renderer.h"
#include "tools/cell_occlusion.h"

namespace octopoint {
namespace {

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// Half an instance's cube edge times 3/2 (its cube turned about y, and some room), Q.24 scene
// edges.
std::int64_t cubeReach(int scale) {
  return scale >= -1 ? (3 * kPerspectiveUnit / 4) << (scale + 1)
                     : (3 * kPerspectiveUnit / 4) >> -(scale + 1);
}

// The grid over the instances' cubes in x and z (each cube's half edge times 3/2 covers it turned).
bool gridOf(std::span<const SceneInstance> instances, const CellBuildOptions& options,
            CellGrid* grid) {
  if (options.edge < kPerspectiveUnit / 64 || options.y.size() < 2 ||
      options.y.size() > kMaxCellLayers + 1 ||
      !std::is_sorted(options.y.begin(), options.y.end()) ||
      std::adjacent_find(options.y.begin(), options.y.end()) != options.y.end()) {
    return false;
  }
  std::int64_t low[2] = {kMaxSceneCoordinate, kMaxSceneCoordinate};
  std::int64_t high[2] = {-kMaxSceneCoordinate, -kMaxSceneCoordinate};
  for (const SceneInstance& instance : instances) {
    const InstanceTransform& t = instance.transform;
    const std::int64_t reach = cubeReach(t.scale);
    low[0] = std::min(low[0], t.at.x - reach);
    high[0] = std::max(high[0], t.at.x + reach);
    low[1] = std::min(low[1], t.at.z - reach);
    high[1] = std::max(high[1], t.at.z + reach);
  }
  grid->origin_x = floorDiv(low[0], options.edge) * options.edge;
  grid->origin_z = floorDiv(low[1], options.edge) * options.edge;
  const std::int64_t nx = floorDiv(high[0] - grid->origin_x, options.edge) + 1;
  const std::int64_t nz = floorDiv(high[1] - grid->origin_z, options.edge) + 1;
  const std::int64_t ny = static_cast<std::int64_t>(options.y.size()) - 1;
  if (nx > kMaxCellsPerAxis || nz > kMaxCellsPerAxis || nx * nz * ny > kMaxCells) return false;
  grid->instances = static_cast<std::uint32_t>(instances.size());
  grid->nx = static_cast<std::uint32_t>(nx);
  grid->nz = static_cast<std::uint32_t>(nz);
  grid->ny = static_cast<std::uint32_t>(ny);
  grid->edge = options.edge;
  grid->y = options.y;
  return true;
}

class SampleViews {
 public:
  // `winners`: an instance is seen when it wins a pixel (SceneRenderer::setPixelWinners) rather
  // than when it submits a point.
  SampleViews(SceneRenderer& renderer, int face, std::size_t instances, bool winners)
      : renderer_(renderer), face_(face), frame_(face, face), marks_(instances) {
    if (winners) {
      winners_.resize(static_cast<std::size_t>(face) * static_cast<std::size_t>(face));
      renderer_.setPixelWinners(winners_);
    } else {
      renderer_.setSubmittedMarks(marks_);
    }
  }
  ~SampleViews() {
    renderer_.setSubmittedMarks({});
    renderer_.setPixelWinners({});
  }
  SampleViews(const SampleViews&) = delete;
  SampleViews& operator=(const SampleViews&) = delete;

  // The instances seen from `eye` in any direction: marks() after it.
  void look(const Point3<std::int64_t>& eye, std::uint64_t* frames) {
    std::fill(marks_.begin(), marks_.end(), std::uint8_t{0});
    static constexpr int kFaces[6][2] = {{0, 0}, {90, 0}, {180, 0}, {270, 0}, {0, 90}, {0, -90}};
    for (const auto& [yaw, pitch] : kFaces) {
      PerspectiveCamera camera;
      camera.eye = eye;
      camera.yaw = Angle::fromDegrees(yaw);
      camera.pitch = Angle::fromDegrees(pitch);
      camera.fov = Angle::fromDegrees(90);
      camera.width = face_;
      camera.height = face_;
      PerspectiveView view;
      if (buildPerspectiveView(camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
        continue;  // an eye beyond the camera's reach: the margin's instances stand for it
      frame_.clear();
      std::fill(winners_.begin(), winners_.end(), kNoWinner);
      static_cast<void>(renderer_.draw(view, frame_));
      for (const std::uint32_t id : winners_)
        if (id < marks_.size()) marks_[id] = 1;
      ++*frames;
    }
  }
  std::span<const std::uint8_t> marks() const { return marks_; }

 private:
  static constexpr std::uint32_t kNoWinner = 0xFFFFFFFFu;
  SceneRenderer& renderer_;
  int face_;
  Framebuffer frame_;
  std::vector<std::uint8_t> marks_;
  std::vector<std::uint32_t> winners_;  // per pixel of a face: the instance whose word it keeps
};

void orInto(std::span<std::uint8_t> into, std::span<const std::uint8_t> marks) {
  for (std::size_t i = 0; i < into.size(); ++i) into[i] |= marks[i];
}

// The sub-boxes of a cell's layer box (n x n across, m up) whose half-diagonal is at most eps,
// fewest first: their centres cover the box within eps.
struct Cover {
  std::int64_t across = 1, up = 1;
};
Cover coverOf(std::int64_t edge, std::int64_t height, std::int64_t eps) {
  Cover best{kMaxCellsPerAxis, 1};
  const double e = static_cast<double>(eps);
  for (std::int64_t up = 1; up <= 4096; ++up) {
    const double half_up = static_cast<double>(height) / static_cast<double>(up) / 2;
    const double room = e * e - half_up * half_up;  // for the two horizontal halves, squared
    if (room <= 0) continue;
    // The sub-box's edge across: at most 2 sqrt(room / 2), less a unit for the rounding below.
    const double across_edge = 2 * std::sqrt(room / 2) - 1;
    if (across_edge < 1) continue;
    const auto across =
        static_cast<std::int64_t>(std::ceil(static_cast<double>(edge) / across_edge));
    if (across * across * up < best.across * best.across * best.up) best = {across, up};
    if (best.across == 1) break;
  }
  return best;
}

void sampleCovering(const CellGrid& g, const CellBuildOptions& options, SceneRenderer& renderer,
                    std::vector<std::uint8_t>& seen, CellBuild* build) {
  const std::size_t n = g.instances;
  OcclusionSampling sampling{options.eps, options.near_occluder, options.face, options.near_steps};
  sampling.ground = options.ground;
  sampling.ground_y = options.ground_y;
  sampling.radii = options.radii;
  sampling.depth_windows = options.depth_windows;
  OcclusionSampler sampler(renderer, sampling);
  build->side = sampler.side();
  build->rho = sampler.rho();
  for (std::size_t cell = 0; cell < g.cellCount(); ++cell) {
    const std::int64_t x = static_cast<std::int64_t>(cell % g.nx);
    const std::int64_t z = static_cast<std::int64_t>(cell / g.nx % g.nz);
    const std::size_t layer = cell / (std::size_t{g.nx} * g.nz);
    const std::int64_t height = g.y[layer + 1] - g.y[layer];
    const Cover cover = coverOf(g.edge, height, options.eps);
    std::uint8_t* const row = seen.data() + cell * n;
    for (std::int64_t k = 0; k < cover.up; ++k) {
      for (std::int64_t j = 0; j < cover.across; ++j) {
        for (std::int64_t i = 0; i < cover.across; ++i) {
          const Point3<std::int64_t> eye{
              g.origin_x + x * g.edge + (2 * i + 1) * g.edge / (2 * cover.across),
              g.y[layer] + (2 * k + 1) * height / (2 * cover.up),
              g.origin_z + z * g.edge + (2 * j + 1) * g.edge / (2 * cover.across)};
          sampler.look(eye, &build->frames, {g.y[layer], g.y[layer + 1]});
          ++build->samples;
          const std::span<const std::uint8_t> marks = sampler.marks();
          for (std::size_t m = 0; m < n; ++m) row[m] |= marks[m];
        }
      }
    }
  }
  build->maps = sampler.stats();
}

// The first way: the lattice on the layers' bounds and seeded points inside each cell, an
// instance seen when it submitted a point (widened afterwards by the neighbours' sets).
void sampleLattice(const CellGrid& g, const CellBuildOptions& options, SceneRenderer& renderer,
                   std::vector<std::uint8_t>& seen, CellBuild* build) {
  const std::size_t n = g.instances, cells = g.cellCount();
  const auto row = [&](std::size_t cell) {
    return std::span<std::uint8_t>(seen).subspan(cell * n, n);
  };
  const auto cellIndex = [&](std::int64_t x, std::int64_t z, std::int64_t layer) {
    return static_cast<std::size_t>((layer * g.nz + z) * g.nx + x);
  };
  SampleViews views(renderer, options.face, n, options.winners);
  build->side = options.face;
  // The lattice on the layers' bounds: the cells' corners, each every touching cell's, and their
  // centres.
  for (std::int64_t k = 0; k <= g.ny; ++k) {
    const std::int64_t y = g.y[static_cast<std::size_t>(k)];
    for (std::int64_t j = 0; j <= g.nz; ++j) {
      for (std::int64_t i = 0; i <= g.nx; ++i) {
        views.look({g.origin_x + i * g.edge, y, g.origin_z + j * g.edge}, &build->frames);
        ++build->samples;
        for (std::int64_t layer = k - 1; layer <= k; ++layer) {
          for (std::int64_t z = j - 1; z <= j; ++z) {
            for (std::int64_t x = i - 1; x <= i; ++x) {
              if (layer < 0 || layer >= g.ny || z < 0 || z >= g.nz || x < 0 || x >= g.nx) continue;
              orInto(row(cellIndex(x, z, layer)), views.marks());
            }
          }
        }
        if (i == g.nx || j == g.nz) continue;
        views.look({g.origin_x + i * g.edge + g.edge / 2, y, g.origin_z + j * g.edge + g.edge / 2},
                   &build->frames);
        ++build->samples;
        for (std::int64_t layer = k - 1; layer <= k; ++layer)
          if (layer >= 0 && layer < g.ny) orInto(row(cellIndex(i, j, layer)), views.marks());
      }
    }
  }
  // Seeded points inside each cell.
  for (std::size_t cell = 0; cell < cells; ++cell) {
    const std::int64_t x = static_cast<std::int64_t>(cell % g.nx);
    const std::int64_t z = static_cast<std::int64_t>(cell / g.nx % g.nz);
    const std::size_t layer = cell / (std::size_t{g.nx} * g.nz);
    std::mt19937_64 random(options.seed * 0x9E3779B97F4A7C15ull + cell);
    for (int s = 0; s < options.random_samples; ++s) {
      const std::int64_t height = g.y[layer + 1] - g.y[layer];
      const Point3<std::int64_t> eye{
          g.origin_x + x * g.edge +
              static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(g.edge)),
          g.y[layer] + static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(height)),
          g.origin_z + z * g.edge +
              static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(g.edge))};
      views.look(eye, &build->frames);
      ++build->samples;
      orInto(row(cell), views.marks());
    }
  }
}

// Samples on a lattice over the grid on every layer bound (spacing[k] on bound k); each cell takes
// what every sample within `reach` of its box (in x and z, on its layer's bounds) saw.
void sampleSpaced(const CellGrid& g, const CellBuildOptions& options, SceneRenderer& renderer,
                  std::vector<std::uint8_t>& seen, CellBuild* build) {
  const std::size_t n = g.instances;
  SampleViews views(renderer, options.face, n, options.winners);
  build->side = options.face;
  const auto span = [&](std::int64_t at, std::int64_t origin, std::int64_t count) {
    // The cells along one axis whose box (its bounds included) widened by reach holds `at`.
    const std::int64_t first = -floorDiv(origin + options.reach - at, g.edge) - 1;
    const std::int64_t last = floorDiv(at + options.reach - origin, g.edge);
    return std::pair{std::max<std::int64_t>(first, 0), std::min<std::int64_t>(last, count - 1)};
  };
  for (std::int64_t k = 0; k <= g.ny; ++k) {
    const std::int64_t y = g.y[static_cast<std::size_t>(k)];
    const std::int64_t spacing =
        options.spacing[options.spacing.size() == 1 ? 0 : static_cast<std::size_t>(k)];
    const std::int64_t steps_x = (g.nx * g.edge + spacing - 1) / spacing;
    const std::int64_t steps_z = (g.nz * g.edge + spacing - 1) / spacing;
    for (std::int64_t j = 0; j <= steps_z; ++j) {
      for (std::int64_t i = 0; i <= steps_x; ++i) {
        const Point3<std::int64_t> eye{g.origin_x + i * spacing, y, g.origin_z + j * spacing};
        views.look(eye, &build->frames);
        ++build->samples;
        const auto [x0, x1] = span(eye.x, g.origin_x, g.nx);
        const auto [z0, z1] = span(eye.z, g.origin_z, g.nz);
        for (std::int64_t layer = k - 1; layer <= k; ++layer) {
          if (layer < 0 || layer >= g.ny) continue;
          for (std::int64_t z = z0; z <= z1; ++z) {
            for (std::int64_t x = x0; x <= x1; ++x) {
              const std::size_t cell = static_cast<std::size_t>((layer * g.nz + z) * g.nx + x);
              orInto(std::span<std::uint8_t>(seen).subspan(cell * n, n), views.marks());
            }
          }
        }
      }
    }
  }
}

}  // namespace

CellBuild buildCells(std::span<const ModelView* const> models,
                     std::span<const SceneInstance> instances, const CellBuildOptions& options) {
  CellBuild build;
  SceneError error;
  SceneRenderer renderer(models, instances, &error);
  if (error != SceneError::kNone || !gridOf(instances, options, &build.grid)) return {};
  OcclusionSampling fitting{options.eps, options.near_occluder, options.face};
  fitting.depth_windows = options.depth_windows;
  if (options.eps > 0 && !erosionFits(fitting)) return {};
  if (!options.spacing.empty() &&
      ((options.spacing.size() != 1 && options.spacing.size() != options.y.size()) ||
       *std::min_element(options.spacing.begin(), options.spacing.end()) <= 0)) {
    return {};
  }
  const CellGrid& g = build.grid;
  const std::size_t n = instances.size(), cells = g.cellCount();
  std::vector<std::uint8_t> seen(cells * n);  // per cell, per instance
  const auto row = [&](std::size_t cell) {
    return std::span<std::uint8_t>(seen).subspan(cell * n, n);
  };
  const auto cellIndex = [&](std::int64_t x, std::int64_t z, std::int64_t layer) {
    return static_cast<std::size_t>((layer * g.nz + z) * g.nx + x);
  };
  if (options.eps > 0) {
    sampleCovering(g, options, renderer, seen, &build);
  } else if (!options.spacing.empty()) {
    sampleSpaced(g, options, renderer, seen, &build);
  } else {
    sampleLattice(g, options, renderer, seen, &build);
  }
  // The margin: instances whose (turned) cube comes within `margin` of the cell's box.
  for (std::size_t i = 0; i < n; ++i) {
    const InstanceTransform& t = instances[i].transform;
    const std::int64_t reach = cubeReach(t.scale) + options.margin;
    const std::int64_t x0 =
        std::max<std::int64_t>(0, floorDiv(t.at.x - reach - g.origin_x, g.edge));
    const std::int64_t x1 =
        std::min<std::int64_t>(g.nx - 1, floorDiv(t.at.x + reach - g.origin_x, g.edge));
    const std::int64_t z0 =
        std::max<std::int64_t>(0, floorDiv(t.at.z - reach - g.origin_z, g.edge));
    const std::int64_t z1 =
        std::min<std::int64_t>(g.nz - 1, floorDiv(t.at.z + reach - g.origin_z, g.edge));
    for (std::int64_t layer = 0; layer < g.ny; ++layer) {
      const std::size_t l = static_cast<std::size_t>(layer);
      if (t.at.y + reach < g.y[l] || t.at.y - reach > g.y[l + 1]) continue;
      for (std::int64_t z = z0; z <= z1; ++z)
        for (std::int64_t x = x0; x <= x1; ++x) seen[cellIndex(x, z, layer) * n + i] = 1;
    }
  }
  build.sets.resize(cells);
  std::vector<std::uint8_t> widened(n);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    const std::int64_t x = static_cast<std::int64_t>(cell % g.nx);
    const std::int64_t z = static_cast<std::int64_t>(cell / g.nx % g.nz);
    const std::int64_t layer = static_cast<std::int64_t>(cell / (std::size_t{g.nx} * g.nz));
    std::copy(row(cell).begin(), row(cell).end(), widened.begin());
    for (std::int64_t dz = -1;
         options.neighbours && options.eps == 0 && options.spacing.empty() && dz <= 1; ++dz) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        if (x + dx < 0 || x + dx >= g.nx || z + dz < 0 || z + dz >= g.nz) continue;
        orInto(widened, row(cellIndex(x + dx, z + dz, layer)));
      }
    }
    for (std::size_t i = 0; i < n; ++i)
      if (widened[i] != 0) build.sets[cell].push_back(static_cast<std::uint32_t>(i));
  }
  return build;
}

}  // namespace octopoint

// octopoint-city-measure: what a scene's visibility cells buy and cost (docs/city.md, "Visibility
// cells"; run by scripts/measure-city). For the generated city (tests/support/make_city.cpp: its
// street tiles found as the instances of the model named street.oct) it draws, from seeded
// positions of four classes (street, crossing, above the roofs, sky), the frame with the eye's
// cell's set and the frame with everything, and prints the share of instances culled by the
// cells and the frustum together per class, the worst share of pixels by which the two frames
// differ along random walks through the streets, the street-level frame time and points with and
// without cells, and the cell table's bytes against the city's.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "octopoint/framebuffer.h"
#include "renderer/cell_table.h"
#include "renderer/scene_renderer.h"
#include "tools/scene_file.h"
#include "tools/scene_text.h"

namespace {

using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-city-measure SCENE.json CELLS [--positions N] [--walk N] [--seed N] [--cut]

Measures visibility cells (docs/city.md) on the generated city (scripts/make-city): per class of
position (street, crossing, roofs at 40 m, sky at 160 m; N seeded positions each, default 100) the
share of instances culled by the cells and the frustum together, and the frustum alone; over N
positions of random walks through the streets (default 1000) the worst share of pixels by which a
frame drawn with the cells differs from the frame drawing everything (320x240, 60 degrees); the
street-level frame time and points submitted with and without cells; the cell table's bytes.
--cut drops from every position's set the instance nearest the eye (a check that the comparison
sees a set cut short).
)";

constexpr std::int64_t kEdge = kPerspectiveUnit;  // one scene edge, Q.24
constexpr double kMetre = 1.0 / 32;               // the generated city's scene edge is 32 m

std::int64_t q24(double edges) { return std::llround(std::ldexp(edges, kPerspectiveUnitBits)); }

struct Pose {
  Point3<std::int64_t> eye;
  double yaw = 0, pitch = 0;  // degrees
};

// The street tiles by their grid position (tile centres lie on whole scene edges).
class Streets {
 public:
  Streets(const LoadedScene& scene, const SceneText& text) {
    for (std::size_t m = 0; m < text.models.size(); ++m)
      if (text.models[m].ends_with("street.oct")) street_model_ = static_cast<std::int64_t>(m);
    if (street_model_ < 0)
      throw cli::Error(scene.label + ": no street.oct model: not a generated city");
    for (const SceneInstance& instance : scene.instances) {
      const auto& at = instance.transform.at;
      low_x_ = std::min(low_x_, at.x);
      high_x_ = std::max(high_x_, at.x);
      low_z_ = std::min(low_z_, at.z);
      high_z_ = std::max(high_z_, at.z);
      if (static_cast<std::int64_t>(instance.model) == street_model_) tiles_[key(at.x, at.z)] = 1;
    }
    for (const auto& [k, unused] : tiles_) {
      const auto [i, j] = k;
      const bool along_z = street(i, j - 1) && street(i, j + 1);
      const bool along_x = street(i - 1, j) && street(i + 1, j);
      (along_z && along_x ? crossings_ : streets_).push_back(k);
    }
    if (streets_.empty() || crossings_.empty()) throw cli::Error(scene.label + ": no streets");
  }

  bool street(std::int64_t i, std::int64_t j) const {
    if (i < key(low_x_, 0).first || i > key(high_x_, 0).first || j < key(0, low_z_).second ||
        j > key(0, high_z_).second) {
      return true;  // outside the city: open
    }
    return tiles_.count({i, j}) != 0;
  }
  bool streetAt(std::int64_t x, std::int64_t z) const {
    const auto [i, j] = key(x, z);
    return tiles_.count({i, j}) != 0;
  }
  Pose onStreet(std::mt19937& random, bool crossing) const {
    const auto& list = crossing ? crossings_ : streets_;
    const auto [i, j] = list[random() % list.size()];
    std::uniform_real_distribution<double> along(-0.5, 0.5), across(-0.25, 0.25), turn(0, 360);
    const bool along_z = street(i, j - 1) && street(i, j + 1);
    // Along the street up to half a tile, across it a quarter (8 m: the lanes); a crossing either
    // way.
    double dx = across(random);
    double dz = crossing ? across(random) : along(random);
    if (!crossing && !along_z) std::swap(dx, dz);
    return {{i * kEdge + q24(dx), q24(-1.6 * kMetre), j * kEdge + q24(dz)}, turn(random), 0};
  }
  Pose above(std::mt19937& random, double metres, double pitch) const {
    std::uniform_int_distribution<std::int64_t> x(low_x_, high_x_), z(low_z_, high_z_);
    std::uniform_real_distribution<double> turn(0, 360);
    return {{x(random), q24(-metres * kMetre), z(random)}, turn(random), pitch};
  }
  // A walk through the streets, 2 m a step, turning at random at crossings.
  std::vector<Pose> walk(std::mt19937& random, std::size_t steps) const {
    Pose pose = onStreet(random, true);
    const auto [ci, cj] = key(pose.eye.x, pose.eye.z);
    pose.eye.x = ci * kEdge;
    pose.eye.z = cj * kEdge;
    static constexpr int kDirections[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    int direction = static_cast<int>(random() % 4);
    const std::int64_t step = q24(2 * kMetre);
    std::uniform_real_distribution<double> look(-40, 40), tilt(-10, 10);
    std::vector<Pose> poses;
    while (poses.size() < steps) {
      const auto [i, j] = key(pose.eye.x, pose.eye.z);
      const bool at_centre = std::llabs(pose.eye.x - i * kEdge) < step / 2 &&
                             std::llabs(pose.eye.z - j * kEdge) < step / 2;
      if (at_centre) {
        for (int tries = 0; tries < 8; ++tries) {
          const int d = tries < 4 ? static_cast<int>(random() % 4) : tries - 4;
          if (streetAt((i + kDirections[d][0]) * kEdge, (j + kDirections[d][1]) * kEdge)) {
            direction = d;
            break;
          }
        }
        pose.eye.x = i * kEdge;
        pose.eye.z = j * kEdge;
      }
      pose.eye.x += kDirections[direction][0] * step;
      pose.eye.z += kDirections[direction][1] * step;
      const double heading = direction == 0 ? 90 : direction == 1 ? 0 : direction == 2 ? 270 : 180;
      poses.push_back({pose.eye, heading + look(random), tilt(random)});
    }
    return poses;
  }

 private:
  static std::pair<std::int64_t, std::int64_t> key(std::int64_t x, std::int64_t z) {
    return {(x + (x >= 0 ? kEdge / 2 : -kEdge / 2)) / kEdge,
            (z + (z >= 0 ? kEdge / 2 : -kEdge / 2)) / kEdge};
  }
  std::int64_t street_model_ = -1;
  std::int64_t low_x_ = INT64_MAX, high_x_ = INT64_MIN, low_z_ = INT64_MAX, high_z_ = INT64_MIN;
  std::map<std::pair<std::int64_t, std::int64_t>, int> tiles_;
  std::vector<std::pair<std::int64_t, std::int64_t>> streets_, crossings_;
};

class Frames {
 public:
  Frames(const LoadedScene& scene, const CellTable& cells, bool cut)
      : scene_(scene),
        cells_(cells),
        cut_(cut),
        all_(320, 240),
        with_(320, 240),
        visible_(scene.instances.size()),
        scratch_(cells.scratch()) {
    SceneError error;
    renderer_.emplace(scene.models, scene.instances, &error);
    if (error != SceneError::kNone) throw cli::Error(scene.label + ": " + describe(error));
  }

  struct Result {
    std::uint64_t passed_all = 0, passed_cells = 0;  // instances through set, frustum and reach
    std::uint64_t points_all = 0, points_cells = 0;
    double seconds_all = 0, seconds_cells = 0;
    double differing = 0;  // share of pixels
  };

  Result draw(const Pose& pose) {
    const PerspectiveView view = viewOf(pose);
    Result result;
    renderer_->clearVisibleSet();
    drawOne(view, all_, &result.passed_all, &result.points_all, &result.seconds_all);
    const std::int64_t cell = cells_.cellAt(pose.eye);
    std::size_t count =
        cell < 0 ? 0 : cells_.decode(static_cast<std::uint32_t>(cell), visible_, scratch_);
    if (cut_ && count > 0) dropNearest(pose.eye, count);
    if (cell >= 0) renderer_->setVisibleSet(std::span<const std::uint32_t>(visible_).first(count));
    drawOne(view, with_, &result.passed_cells, &result.points_cells, &result.seconds_cells);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < all_.pixels().size(); ++i)
      differ +=
          FrameView::colourIndexOf(all_.pixels()[i]) != FrameView::colourIndexOf(with_.pixels()[i]);
    result.differing = static_cast<double>(differ) / static_cast<double>(all_.pixels().size());
    return result;
  }

  // The instances that win pixels of the frame drawing everything at `pose` and are not in the
  // eye's cell's set (what the cells left out there): id and pixels won, most pixels first.
  std::vector<std::pair<std::uint32_t, std::size_t>> missing(const Pose& pose) {
    const PerspectiveView view = viewOf(pose);
    std::vector<std::uint32_t> winners(all_.pixels().size(), 0xFFFFFFFFu);
    renderer_->clearVisibleSet();
    renderer_->setPixelWinners(winners);
    all_.clear();
    static_cast<void>(renderer_->draw(view, all_));
    renderer_->setPixelWinners({});
    const std::int64_t cell = cells_.cellAt(pose.eye);
    const std::size_t count =
        cell < 0 ? 0 : cells_.decode(static_cast<std::uint32_t>(cell), visible_, scratch_);
    std::vector<std::uint8_t> in_set(scene_.instances.size());
    for (std::size_t k = 0; k < count; ++k) in_set[visible_[k]] = 1;
    std::map<std::uint32_t, std::size_t> won;
    for (const std::uint32_t id : winners)
      if (id < in_set.size() && in_set[id] == 0 && cell >= 0) ++won[id];
    std::vector<std::pair<std::uint32_t, std::size_t>> list(won.begin(), won.end());
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    return list;
  }

 private:
  static PerspectiveView viewOf(const Pose& pose) {
    PerspectiveCamera camera;
    camera.eye = pose.eye;
    camera.yaw = Angle::fromMilliDegrees(std::llround(pose.yaw * 1000));
    camera.pitch = Angle::fromMilliDegrees(std::llround(pose.pitch * 1000));
    camera.width = 320;
    camera.height = 240;
    PerspectiveView view;
    if (buildPerspectiveView(camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
      throw cli::Error("an eye beyond the camera's reach");
    return view;
  }
  void drawOne(const PerspectiveView& view, Framebuffer& frame, std::uint64_t* passed,
               std::uint64_t* points, double* seconds) {
    frame.clear();
    SceneDrawStats stats;
    const auto start = std::chrono::steady_clock::now();
    static_cast<void>(renderer_->draw(view, frame, &stats));
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    *passed = stats.instances_drawn + stats.occluded;
    *points = stats.points.leaves;
  }
  void dropNearest(const Point3<std::int64_t>& eye, std::size_t& count) {
    std::size_t nearest = 0;
    double best = 1e300;
    for (std::size_t k = 0; k < count; ++k) {
      const auto& at = scene_.instances[visible_[k]].transform.at;
      const double d =
          std::hypot(static_cast<double>(at.x - eye.x), static_cast<double>(at.y - eye.y),
                     static_cast<double>(at.z - eye.z));
      if (d < best) best = d, nearest = k;
    }
    std::copy(visible_.begin() + static_cast<std::ptrdiff_t>(nearest) + 1,
              visible_.begin() + static_cast<std::ptrdiff_t>(count),
              visible_.begin() + static_cast<std::ptrdiff_t>(nearest));
    --count;
  }

  const LoadedScene& scene_;
  const CellTable& cells_;
  bool cut_;
  std::optional<SceneRenderer> renderer_;
  Framebuffer all_, with_;
  std::vector<std::uint32_t> visible_;
  CellTable::Scratch scratch_;
};

int run(int argc, char** argv) {
  cli::ArgumentReader args(argc, argv);
  std::vector<std::string> files;
  int positions = 100, walk = 1000;
  std::uint32_t seed = 1;
  bool cut = false;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (args.is("--positions")) {
      positions = cli::parseInt(args.name(), args.value(), 1, 100000);
    } else if (args.is("--walk")) {
      walk = cli::parseInt(args.name(), args.value(), 1, 1000000);
    } else if (args.is("--seed")) {
      seed = static_cast<std::uint32_t>(cli::parseInt(args.name(), args.value(), 0, 1'000'000'000));
    } else if (args.is("--cut")) {
      args.noValue();
      cut = true;
    } else if (args.isPlain() && files.size() < 2) {
      files.push_back(args.current());
    } else {
      args.refuseUnknown();
    }
  }
  if (files.size() != 2) throw cli::Error("give SCENE.json and CELLS (see --help)");
  const std::unique_ptr<LoadedScene> scene = loadScene(files[0]);
  const SceneText text = parseSceneText(cli::readInputFile(files[0], kSceneFileInput), files[0]);
  const std::vector<std::uint8_t> bytes =
      cli::readInputBytes(files[1], cli::InputKind{"cell table", kMaxCellTableBytes});
  CellTableError why;
  const CellTable cells =
      CellTable::parse(bytes, static_cast<std::uint32_t>(scene->instances.size()), &why);
  if (why != CellTableError::kNone) throw cli::Error(files[1] + ": " + describe(why));
  const Streets streets(*scene, text);
  Frames frames(*scene, cells, cut);
  const double total = static_cast<double>(scene->instances.size());
  std::mt19937 random(seed);
  Frames::Result street_sum;
  for (const char* name : {"street", "crossing", "roofs", "sky"}) {
    const std::string kind = name;
    double culled = 0, frustum = 0;
    for (int p = 0; p < positions; ++p) {
      const Pose pose = kind == "street"     ? streets.onStreet(random, false)
                        : kind == "crossing" ? streets.onStreet(random, true)
                        : kind == "roofs"    ? streets.above(random, 40, -20)
                                             : streets.above(random, 160, -45);
      const Frames::Result r = frames.draw(pose);
      culled += 1 - static_cast<double>(r.passed_cells) / total;
      frustum += 1 - static_cast<double>(r.passed_all) / total;
      if (kind == "street") {
        street_sum.points_all += r.points_all;
        street_sum.points_cells += r.points_cells;
        street_sum.seconds_all += r.seconds_all;
        street_sum.seconds_cells += r.seconds_cells;
      }
    }
    std::printf("%s culled %.1f%% (frustum alone %.1f%%; %d positions)\n", name,
                100 * culled / positions, 100 * frustum / positions, positions);
  }
  double worst = 0, sum = 0;
  std::size_t done = 0, above = 0;
  Pose worst_pose{};
  while (done < static_cast<std::size_t>(walk)) {
    for (const Pose& pose : streets.walk(random, std::min<std::size_t>(100, walk - done))) {
      const double differing = frames.draw(pose).differing;
      if (differing > worst) worst = differing, worst_pose = pose;
      above += differing > 0.001;
      sum += differing;
      ++done;
    }
  }
  // The worst position (the eye in scene edges, the heading in degrees), to look at what the cells
  // left out there.
  std::printf(
      "conservative: worst %.2f%% (mean %.4f%% over %d random-walk positions; %zu above 0.1%%; "
      "worst at eye %.4f,%.4f,%.4f, yaw %.1f, pitch %.1f)\n",
      100 * worst, 100 * sum / walk, walk, above,
      std::ldexp(static_cast<double>(worst_pose.eye.x), -kPerspectiveUnitBits),
      std::ldexp(static_cast<double>(worst_pose.eye.y), -kPerspectiveUnitBits),
      std::ldexp(static_cast<double>(worst_pose.eye.z), -kPerspectiveUnitBits), worst_pose.yaw,
      worst_pose.pitch);
  if (worst > 0) {
    // What the worst position's cell left out: the model, the pixels it wins, its distance.
    std::printf("left out there:");
    int shown = 0;
    for (const auto& [id, pixels] : frames.missing(worst_pose)) {
      if (++shown > 6) break;
      const SceneInstance& instance = scene->instances[id];
      const double metres =
          std::hypot(static_cast<double>(instance.transform.at.x - worst_pose.eye.x),
                     static_cast<double>(instance.transform.at.z - worst_pose.eye.z)) /
          static_cast<double>(kEdge) / kMetre;
      std::printf(" %s %zu px at %.0f m;",
                  std::filesystem::path(text.models[instance.model]).stem().c_str(), pixels,
                  metres);
    }
    std::printf("\n");
  }
  std::printf(
      "street frame: %.1f ms and %.0f points submitted without cells, %.1f ms and %.0f with "
      "(320x240, means of %d; wall clock)\n",
      1000 * street_sum.seconds_all / positions,
      static_cast<double>(street_sum.points_all) / positions,
      1000 * street_sum.seconds_cells / positions,
      static_cast<double>(street_sum.points_cells) / positions, positions);
  std::uint64_t city_bytes = scene->model_bytes + std::filesystem::file_size(files[0]);
  std::printf("cell table: %zu bytes, %.2f%% of the city's %llu bytes\n", bytes.size(),
              100.0 * static_cast<double>(bytes.size()) / static_cast<double>(city_bytes),
              static_cast<unsigned long long>(city_bytes));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-city-measure", argc, argv, run);
}

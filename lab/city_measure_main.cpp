// octopoint-city-measure: what a scene's visibility cells buy and cost (docs/city.md, "Visibility
// cells"; run by scripts/measure-city). For the generated city (tests/support/make_city.cpp: its
// street tiles found as the instances of the model named street.oct) it draws, from seeded
// positions of four classes (street, crossing, above the roofs, sky), the frame with the eye's
// cell's set and the frame with everything, and prints the share of instances culled by the
// cells and the frustum together per class, the worst share of pixels by which the two frames
// differ along random walks through the streets (and at the worst position, the instances its cell
// left out that win pixels of the whole frame), the street-level frame time and points with and
// without cells, and the cell table's bytes against the city's.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "lab/city_streets.h"
#include "octopoint/framebuffer.h"
#include "renderer/cell_table.h"
#include "renderer/scene_renderer.h"
#include "tools/scene_file.h"
#include "tools/scene_text.h"

namespace {

using namespace octopoint;
using namespace octopoint::city_streets;

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

// octopoint-city-walk: a walk through a city streamed over a shaped link (docs/city.md, "Walking
// over a slow link"). It starts octopoint-serve on the city's folder (its models chunked:
// scripts/make-city --chunked) shaped to a rate and a latency, streams the models with
// net::SceneStream (the eye's cell's set or the instances in view first, nearest first, then what
// lies ahead on the path) while it walks a scripted path in real time (a camera path, or a street
// walk of the generated city at 1.4 m/s), draws what is held at 320x240 (renderer/held_scene.h)
// about ten times a second, and scores every frame against the complete city's frame of the same
// eye (lab/city_walk_score.h).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "lab/city_streets.h"
#include "lab/city_walk_score.h"
#include "lab/stream_run.h"
#include "net/scene_stream.h"
#include "renderer/held_scene.h"
#include "tools/camera_path.h"
#include "tools/png_file.h"

namespace {

using namespace octopoint;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    R"(usage: octopoint-city-walk SCENE.json [options]

Walks a city whose models are chunked files (scripts/make-city --chunked) while they stream from
octopoint-serve over a shaped link, and scores every frame against the complete city's frame of
the same eye (docs/city.md, "Walking over a slow link").
  --rate BYTES/S     the link's rate (default 50000), shared by the connections
  --latency MS       before each response (default 100)
  --connections K    requests in flight (default 2; each connection is shaped to rate / K)
  --seconds S        the walk's length (default 60; a path's own length when shorter)
  --path P.json      a camera path (keys' times in seconds, eyes in scene edges); default: a
                     seeded street walk of the generated city at 1.4 m/s (2 m steps)
  --seed N           the street walk's seed (default 1)
  --cells CELLS      the scene's visibility cells: fetch and draw the eye's cell's set
  --ahead S          what lies this far ahead on the path is fetched next (default 10)
  --truth-scale N    the truth is drawn N times wider and higher (default 4)
  --settle S         after the walk, wait up to S seconds for the last view's every chunk, then
                     compare the last frame with the complete city's
  --check            exit 1 unless the settled last frame is the complete city's, colour for
                     colour, and no frame has a hole (inside a surface the complete city's frame
                     of the models that had arrived covers)
  --worst-hole PNG   writes the frame missing most pixels, the holes and outline pixels in red,
                     and the complete city's frame of the models that had arrived beside it
  --serve PATH       octopoint-serve (default: build/release/tools/ beside this tool)
)";

constexpr int kPosesPerSecond = 20;
constexpr double kWalkSpeed = 1.4;  // metres a second

struct Options {
  std::string scene, path, cells, serve, worst_png;
  std::uint64_t rate = 50000;
  std::uint32_t latency = 100;
  int connections = 2, seed = 1, truth_scale = 4;
  double seconds = 60, ahead = 10, settle = 0;
  bool check = false;
};

struct TimedPose {
  Point3<std::int64_t> eye;
  Angle yaw, pitch;
};

Angle degrees(double value) { return Angle::fromMilliDegrees(std::llround(value * 1000)); }

// The path's poses, kPosesPerSecond of them a second.
std::vector<TimedPose> timeline(const Options& options, const LoadedScene& scene,
                                const SceneText& text) {
  std::vector<TimedPose> poses;
  if (!options.path.empty()) {
    const CameraPath path = loadCameraPath(options.path);
    const double length = path.keys.back().time - path.keys.front().time;
    const double seconds = std::min(options.seconds, length);
    const int frames = std::max(2, static_cast<int>(length * kPosesPerSecond) + 1);
    for (const PathPose& pose : samplePath(path, frames)) {
      if (poses.size() > static_cast<std::size_t>(seconds * kPosesPerSecond)) break;
      poses.push_back({{city_streets::q24(pose.eye[0]), city_streets::q24(pose.eye[1]),
                        city_streets::q24(pose.eye[2])},
                       pose.look.yaw,
                       pose.look.pitch});
    }
    return poses;
  }
  const city_streets::Streets streets(scene, text);
  std::mt19937 random(static_cast<std::uint32_t>(options.seed));
  const double step_seconds = 2 / kWalkSpeed;  // the street walk's steps are 2 m
  const auto steps = static_cast<std::size_t>(options.seconds / step_seconds) + 2;
  const std::vector<city_streets::Pose> walk = streets.walk(random, steps);
  for (int k = 0; k <= static_cast<int>(options.seconds * kPosesPerSecond); ++k) {
    const double at = k / (kPosesPerSecond * step_seconds);
    const auto i = std::min(static_cast<std::size_t>(at), walk.size() - 2);
    const double f = at - static_cast<double>(i);
    const city_streets::Pose& a = walk[i];
    const city_streets::Pose& b = walk[i + 1];
    const auto mix = [f](std::int64_t p, std::int64_t q) {
      return p + std::llround(f * static_cast<double>(q - p));
    };
    // The yaw turns the short way.
    const double turn = std::remainder(b.yaw - a.yaw, 360.0);
    poses.push_back({{mix(a.eye.x, b.eye.x), mix(a.eye.y, b.eye.y), mix(a.eye.z, b.eye.z)},
                     degrees(a.yaw + f * turn),
                     degrees(a.pitch + f * (b.pitch - a.pitch))});
  }
  return poses;
}

PerspectiveView viewOf(const TimedPose& pose) {
  PerspectiveCamera camera;
  camera.eye = pose.eye;
  camera.yaw = pose.yaw;
  camera.pitch = pose.pitch;
  camera.fov = Angle::fromDegrees(60);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  if (buildPerspectiveView(camera, kDefaultFractionBits, &view) != PerspectiveError::kNone)
    throw cli::Error("an eye of the path lies beyond the camera's reach");
  return view;
}

// The fetch order's tiers at pose k: what the eye sees (its cell's set, or every instance in
// view), then what the path's pose `ahead` seconds on sees (with cells: the first pose in another
// cell, its set), then everything around the eye its distance asks for.
class Tiers {
 public:
  Tiers(const std::vector<TimedPose>& poses, const CellTable* cells, double ahead)
      : poses_(poses), cells_(cells), ahead_(static_cast<std::size_t>(ahead * kPosesPerSecond)) {
    if (cells_ != nullptr) {
      scratch_.emplace(cells_->scratch());
      set_.resize(cells_->largestSet());
    }
  }

  std::vector<net::SceneFetchTier> at(std::size_t k) {
    std::vector<net::SceneFetchTier> tiers(3);
    std::size_t next = std::min(k + ahead_, poses_.size() - 1);
    if (cells_ != nullptr) {
      const std::int64_t cell = cells_->cellAt(poses_[k].eye);
      for (std::size_t j = k + 1; j < poses_.size(); ++j) {
        if (cells_->cellAt(poses_[j].eye) != cell) {
          next = j;
          break;
        }
      }
    }
    fill(tiers[0], poses_[k], false);
    fill(tiers[1], poses_[next], false);
    fill(tiers[2], poses_[k], true);
    return tiers;
  }

 private:
  void fill(net::SceneFetchTier& tier, const TimedPose& pose, bool around) {
    tier.view = viewOf(pose);
    tier.include_invisible = around;
    if (cells_ == nullptr) return;
    const std::int64_t cell = cells_->cellAt(pose.eye);
    if (cell < 0) return;  // outside the grid: everything
    const std::size_t count = cells_->decode(static_cast<std::uint32_t>(cell), set_, *scratch_);
    tier.every_instance = false;
    tier.instances.assign(set_.begin(), set_.begin() + static_cast<std::ptrdiff_t>(count));
  }

  const std::vector<TimedPose>& poses_;
  const CellTable* cells_;
  std::size_t ahead_;
  std::optional<CellTable::Scratch> scratch_;
  std::vector<std::uint32_t> set_;
};

// The models held, assembled again when the stream has taken something new.
class Held {
 public:
  Held(const LoadedScene& scene, const CellTable* cells)
      : scene_(scene.instances, scene.models.size()),
        signature_(scene.models.size(), 0),
        known_(scene.models.size(), 0),
        cells_(cells),
        frame_(320, 240) {
    if (cells_ != nullptr) {
      scratch_.emplace(cells_->scratch());
      set_.resize(cells_->largestSet());
    }
  }

  void update(net::SceneStream& stream) {
    stream.withModels([this](std::span<ProgressiveModel* const> models) {
      for (std::size_t m = 0; m < models.size(); ++m) {
        if (models[m] == nullptr) continue;
        std::uint64_t tables = 0;
        for (int level = 1; level < models[m]->levelCount(); ++level)
          tables += models[m]->hasRecordTable(level) ? 1 : 0;
        const std::uint64_t signature = 1 + tables + 64 * models[m]->chunksIn(ChunkState::kHeld);
        if (signature == signature_[m]) continue;
        if (!scene_.update(m, *models[m]))
          throw cli::Error("the models' palettes hold more than 255 colours together");
        signature_[m] = signature;
        known_[m] = 1;
      }
    });
    scene_.rebuild();
  }

  WalkFrame draw(const PerspectiveView& view, double seconds, std::uint64_t bytes) {
    frame_.clear();
    if (cells_ != nullptr) {
      const std::int64_t cell = cells_->cellAt(view.camera.eye);
      if (cell < 0) {
        scene_.clearVisibleSet();
      } else {
        const std::size_t count = cells_->decode(static_cast<std::uint32_t>(cell), set_, *scratch_);
        scene_.setVisibleSet(std::span<const std::uint32_t>(set_).first(count));
      }
    }
    static_cast<void>(scene_.draw(view, frame_));
    WalkFrame walk;
    walk.seconds = seconds;
    walk.view = view;
    walk.bytes = bytes;
    walk.models = known_;
    walk.colours.resize(frame_.pixels().size());
    for (std::size_t i = 0; i < walk.colours.size(); ++i) {
      const std::uint32_t word = frame_.pixels()[i];
      walk.colours[i] = word == FrameView::kEmpty ? 255 : FrameView::colourIndexOf(word);
    }
    return walk;
  }

  std::span<const std::uint8_t> palette() const { return scene_.palette(); }

 private:
  HeldScene scene_;
  std::vector<std::uint64_t> signature_;
  std::vector<std::uint8_t> known_;
  const CellTable* cells_;
  std::optional<CellTable::Scratch> scratch_;
  std::vector<std::uint32_t> set_;
  Framebuffer frame_;
};

Options parseOptions(int argc, char** argv, bool* help) {
  cli::ArgumentReader args(argc, argv);
  Options options;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      *help = true;
      return options;
    } else if (args.is("--rate")) {
      options.rate =
          static_cast<std::uint64_t>(cli::parseInt(args.name(), args.value(), 1, 1 << 30));
    } else if (args.is("--latency")) {
      options.latency =
          static_cast<std::uint32_t>(cli::parseInt(args.name(), args.value(), 0, 60000));
    } else if (args.is("--connections")) {
      options.connections = cli::parseInt(args.name(), args.value(), 1, 8);
    } else if (args.is("--seconds")) {
      options.seconds = cli::parseInt(args.name(), args.value(), 1, 3600);
    } else if (args.is("--ahead")) {
      options.ahead = cli::parseInt(args.name(), args.value(), 0, 600);
    } else if (args.is("--settle")) {
      options.settle = cli::parseInt(args.name(), args.value(), 0, 3600);
    } else if (args.is("--truth-scale")) {
      options.truth_scale = cli::parseInt(args.name(), args.value(), 1, 8);
    } else if (args.is("--seed")) {
      options.seed = cli::parseInt(args.name(), args.value(), 0, 1'000'000'000);
    } else if (args.is("--path")) {
      options.path = args.value();
    } else if (args.is("--worst-hole")) {
      options.worst_png = args.value();
    } else if (args.is("--cells")) {
      options.cells = args.value();
    } else if (args.is("--serve")) {
      options.serve = args.value();
    } else if (args.is("--check")) {
      args.noValue();
      options.check = true;
    } else if (args.isPlain() && options.scene.empty()) {
      options.scene = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (options.scene.empty()) throw cli::Error("give SCENE.json (see --help)");
  if (options.check && options.settle == 0) throw cli::Error("--check needs --settle");
  if (options.serve.empty()) {
    options.serve = (std::filesystem::canonical("/proc/self/exe").parent_path().parent_path() /
                     "tools" / "octopoint-serve")
                        .string();
  }
  return options;
}

int run(int argc, char** argv) {
  bool help = false;
  const Options options = parseOptions(argc, argv, &help);
  if (help) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  const std::unique_ptr<LoadedScene> scene = loadScene(options.scene);
  const SceneText text =
      parseSceneText(cli::readInputFile(options.scene, kSceneFileInput), options.scene);
  std::optional<CellTable> cells;
  if (!options.cells.empty()) cells.emplace(loadCellTable(options.cells, *scene));
  const CellTable* table = cells ? &*cells : nullptr;
  const std::vector<TimedPose> poses = timeline(options, *scene, text);
  const std::string folder = std::filesystem::path(options.scene).parent_path().string();
  const std::uint64_t per_connection =
      std::max<std::uint64_t>(1, options.rate / static_cast<std::uint64_t>(options.connections));
  const Link link{
      std::to_string(options.rate) + " B/s + " + std::to_string(options.latency) + " ms",
      per_connection, options.latency};
  ServeProcess server(options.serve, folder.empty() ? "." : folder, link);
  net::SceneStreamOptions stream_options;
  stream_options.connections = options.connections;
  net::HttpUrl url{"127.0.0.1", server.port(), "/"};
  net::SceneStream stream(url, text.models, scene->instances, stream_options);
  Tiers tiers(poses, table, options.ahead);
  Held held(*scene, table);
  std::vector<WalkFrame> frames;
  double first_picture = -1;
  std::uint64_t seen = UINT64_MAX;
  std::size_t tier_pose = SIZE_MAX;
  const double length = static_cast<double>(poses.size() - 1) / kPosesPerSecond;
  stream.setTiers(tiers.at(0));
  const Clock::time_point start = Clock::now();
  stream.start();
  for (double last = -1;;) {
    const double t = std::chrono::duration<double>(Clock::now() - start).count();
    if (t >= length) break;
    const std::size_t k = std::min(poses.size() - 1, static_cast<std::size_t>(t * kPosesPerSecond));
    if (k != tier_pose) {
      stream.setTiers(tiers.at(k));
      tier_pose = k;
    }
    const std::uint64_t content = stream.content();
    if (t - last < 0.1 && (first_picture >= 0 || content == seen)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    if (content != seen) held.update(stream);
    seen = content;
    frames.push_back(held.draw(viewOf(poses[k]), t, stream.bytesReceived()));
    last = t;
    const std::vector<std::uint8_t>& colours = frames.back().colours;
    if (first_picture < 0 && std::find_if(colours.begin(), colours.end(), [](std::uint8_t c) {
                               return c != 255;
                             }) != colours.end()) {
      first_picture = t;
    }
  }
  const PerspectiveView last_view = viewOf(poses.back());
  std::optional<WalkFrame> settled;
  double settle_seconds = 0;
  if (options.settle > 0) {
    // Only what the last view needs.
    std::vector<net::SceneFetchTier> last_tiers = tiers.at(poses.size() - 1);
    last_tiers.resize(1);
    stream.setTiers(std::move(last_tiers));
    const Clock::time_point before = Clock::now();
    const net::SceneStreamStatus status = stream.waitUntilSettled(
        std::chrono::milliseconds(static_cast<std::int64_t>(options.settle * 1000)));
    settle_seconds = std::chrono::duration<double>(Clock::now() - before).count();
    if (!status.settled)
      std::printf("the last view did not settle within %.0f s\n", options.settle);
    held.update(stream);
    settled = held.draw(last_view, length + settle_seconds, status.bytes_received);
  }
  const net::SceneStreamStatus status = stream.status();
  stream.stop();
  std::uint64_t file_bytes = scene->model_bytes;
  std::printf("%s over %s (%d connections of %llu B/s): a %.1f s walk, %zu frames at 320x240\n",
              scene->label.c_str(), link.name.c_str(), options.connections,
              static_cast<unsigned long long>(per_connection), length, frames.size());
  std::printf("first picture: %.2f s\n", first_picture);
  std::printf(
      "bytes received: %llu during the walk, %llu in all (the models' files: %llu), "
      "%u requests (%u failed)\n",
      static_cast<unsigned long long>(frames.empty() ? 0 : frames.back().bytes),
      static_cast<unsigned long long>(status.bytes_received),
      static_cast<unsigned long long>(file_bytes), status.requests, status.failed_requests);
  WalkScorer scorer(*scene, table, options.truth_scale);
  std::size_t within = 0, identical = 0, holey = 0, outlined = 0;
  std::uint64_t worst_missing = 0, worst_holes = 0, worst_outline = 0;
  WalkScore worst;
  double worst_at = 0;
  std::vector<double> against_complete, complete_truth;
  std::vector<std::size_t> window_frames, window_within;  // per 10 s of the walk
  for (const WalkFrame& frame : frames) {
    const WalkScore score = scorer.score(frame, held.palette());
    within += score.within_1db ? 1 : 0;
    const auto window = static_cast<std::size_t>(frame.seconds / 10);
    window_frames.resize(std::max(window_frames.size(), window + 1), 0);
    window_within.resize(window_frames.size(), 0);
    ++window_frames[window];
    window_within[window] += score.within_1db ? 1 : 0;
    identical += std::isinf(score.psnr_complete) ? 1 : 0;
    holey += score.holes > 0 ? 1 : 0;
    outlined += score.outline > 0 ? 1 : 0;
    worst_holes = std::max(worst_holes, score.holes);
    worst_outline = std::max(worst_outline, score.outline);
    if (score.holes + score.outline > worst_missing) {
      worst_missing = score.holes + score.outline;
      worst = score;
      worst_at = frame.seconds;
      if (!options.worst_png.empty())
        writePng(options.worst_png, scorer.holes(frame, held.palette()));
    }
    against_complete.push_back(score.psnr_complete);
    complete_truth.push_back(score.complete_truth);
  }
  const auto median = [](std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(),
                     values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
    return values[values.size() / 2];
  };
  const double count = std::max<double>(1, static_cast<double>(frames.size()));
  std::printf(
      "within 1 dB: %.1f%% of frames (PSNR against the truth drawn %dx wider and higher, "
      "averaged down; the complete frames' median %.1f dB)\n",
      100 * static_cast<double>(within) / count, options.truth_scale, median(complete_truth));
  std::printf("within 1 dB per 10 s of the walk:");
  for (std::size_t w = 0; w < window_frames.size(); ++w) {
    std::printf(" %.0f%%", 100 * static_cast<double>(window_within[w]) /
                               static_cast<double>(std::max<std::size_t>(1, window_frames[w])));
  }
  std::printf("\n");
  std::printf("against the complete city's frame: median %.1f dB, %.1f%% identical\n",
              median(against_complete), 100 * static_cast<double>(identical) / count);
  std::printf(
      "holes: %zu frames with a hole inside a surface (worst %llu pixels); %zu with outline "
      "pixels missed (worst %llu)",
      holey, static_cast<unsigned long long>(worst_holes), outlined,
      static_cast<unsigned long long>(worst_outline));
  if (worst_missing > 0)
    std::printf("; the worst frame at %.1f s, rows %d to %d", worst_at, worst.hole_top,
                worst.hole_bottom);
  std::printf("\n");
  bool same = true;
  if (settled) {
    const cv::Mat whole = scorer.complete(last_view);
    cv::Mat differ;
    cv::compare(whole, WalkScorer::streamed(*settled, held.palette()), differ, cv::CMP_NE);
    cv::Mat any;
    cv::reduce(differ.reshape(1, static_cast<int>(whole.total())), any, 1, cv::REDUCE_MAX);
    const int pixels = cv::countNonZero(any);
    same = pixels == 0;
    std::printf("last frame, settled after %.1f s more: %s\n", settle_seconds,
                same
                    ? "the complete city's, colour for colour"
                    : (std::to_string(pixels) + " pixels differ from the complete city's").c_str());
  }
  return options.check && (!same || holey > 0) ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-city-walk", argc, argv, run);
}

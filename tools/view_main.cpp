// octopoint-view: an interactive window on a model. The window (SDL2, tools/view_window.h) drives
// the dual-resolution renderer: an arrow key's press and release start and stop thread L's coarse
// frames, thread H's fine frame follows at the next 100 ms tick after the last release, and the
// frames follow the window's size. This file: the command line; the window is tools/viewer.h.

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "octopoint/http.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "tools/model_source.h"
#include "tools/scene_file.h"
#include "tools/view_window.h"
#include "tools/viewer.h"

namespace {

using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-view [--model NAME | --file M.oct | --url URL [--point-budget N] | )"
    R"(--city SCENE.json [--cells CELLS]] [--size WxH] [--scale N]
                     [--speed DEG] [--eye X,Y,Z [--look YAW,PITCH[,ROLL]]] [--fov DEG] [--near D]
                     [--walk-speed S] [--eye-radius R] [--eye-height H]

Shows an octopoint model in a resizable window. While an arrow key is held the view turns at a
fixed speed, drawn coarse (thread L); once the last key is let go the fine frame is drawn at the
next 100 ms tick (thread H), and a key press aborts it at once. The frame follows the window's
size. Tab switches to walk mode: the eye stands in the scan and looks in perspective (each part
at the depth its distance asks for, as octopoint-render --eye draws it); w a s d or the arrows
walk, e and q (PgUp, PgDn) rise and sink, a drag with the left mouse button turns the eye, all at a
speed that does not depend on the frame rate; the eye enters where the orbit view's would be in
perspective (docs/perspective.md, "The viewer's walk mode").

  --model NAME   an embedded model (default: the default model)
  --file M.oct   a model file written by octopoint-prepare; it is validated first
  --url URL      a chunked model (octopoint-prepare --chunked) on an HTTP server with Range
                 requests, http://HOST:PORT/NAME.oct (octopoint-serve, nginx, ...): the view
                 sharpens as its chunks arrive, those it shows first, coarse before fine; turning
                 or zooming asks for what the new view needs (docs/streaming.md). The window opens
                 once the model's head is in (at most 30 s); walk mode fetches for the walk's
                 view, and draws what is held as octopoint-render --url --eye does
  --city SCENE.json  walk through a scene of many models (octopoint-render --city's file;
                 docs/city.md): walk mode only, from --eye (required, in scene edges, within 128
                 of the scene's origin), each instance at the depth its distance asks for, nearer
                 instances hiding farther ones; the eye collides with the instances (n turns it
                 off; --eye-radius default 1/128 scene edge) and --eye-height keeps it above the
                 ground; --walk-speed and --near in scene edges
  --cells CELLS  with --city: the scene's visibility cells (octopoint-pvs, docs/city.md): each
                 frame draws only the instances the eye's cell sees (all of them when the eye
                 lies outside the cells' grid), as octopoint-render --city --cells does
  --point-budget N  with --url: draw at most about N points a frame, 1..2^40 (default: no
                 budget). When the view's visible chunks hold more at the depth it needs, those
                 largest on screen, then nearest, keep it and the rest are drawn one depth
                 coarser (docs/streaming.md, "Point budget")
  --size WxH     the initial frame, each side 16..4096 (default 640x480)
  --scale N      each frame pixel is shown as NxN window pixels, 1..8 (default 1): the frame is
                 the window's size divided by N
  --speed DEG    how fast a held arrow key turns the view, degrees per second, 1..720 (default 90)
  --eye X,Y,Z    start in walk mode with the eye at X,Y,Z in the scan's own units and axes, as
                 octopoint-render --eye takes it (octopoint-render --info prints the model's cube)
  --look YAW,PITCH[,ROLL]  with --eye: where the eye looks, in degrees (default 0,0,0: the way
                 the sensor looked; yaw turns right, pitch up)
  --fov DEG      walk mode's vertical field of view, 10..120 degrees (default 60)
  --walk-speed S how fast a held key walks, in scan units per second (default a quarter of the
                 model's cube edge; the wheel and + - change it by steps of 5/4)
  --eye-radius R walk mode's collision (on at start, n turns it off and on): the eye's sphere of
                 radius R scan units stops short of the model and slides along it (default 1/128
                 of the cube's edge; docs/perspective.md, "Collision")
  --eye-height H gravity in walk mode: the eye stays H scan units above the ground under it
                 (above R, at most one cube edge); none by default
  --near D       walk mode's near plane, in scan units: nothing nearer the eye is drawn (default
                 half the voxel edge of the model's finest depth; docs/perspective.md)
  -h, --help     show this help

keys:
)";

constexpr const char* kUsageEnd =
    R"(
The overlay shows which thread drew the frame (L or H), its drawing time, the frame's size and
zoom, and two rates over the last second: frames drawn (complete frames the render threads handed
over) and frames shown (new frames put on the screen; a frame superseded before the window was
drawn is drawn but not shown). With --url it also shows the bytes received of the file's, and the
chunks the view still waits for. `s` prints the frame's view as octopoint-render options. In walk
mode it shows the eye and the look in the scan's units, and the speed; `p` prints them exactly,
as octopoint-render options (--eye X,Y,Z --look YAW,PITCH,ROLL --fov DEG).
The window needs a display (DISPLAY or WAYLAND_DISPLAY); SDL_VIDEODRIVER picks another SDL video
driver, e.g. kmsdrm on a panel without a window system.
)";

ViewerOptions parseOptions(int argc, char** argv) {
  ViewerOptions options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage << Viewer::keyTable(nullptr).helpText() << kUsageEnd;
      std::exit(0);
    } else if (args.is("--city")) {
      options.city = args.value();
    } else if (args.is("--cells")) {
      options.cells = args.value();
    } else if (parseModelSourceOption(args, options.source)) {
      continue;
    } else if (args.is("--size")) {
      const cli::FrameSize size =
          cli::parseFrameSize(args.name(), args.value(), kMinFrameSide, kMaxFrameSide);
      options.width = size.width;
      options.height = size.height;
    } else if (args.is("--scale")) {
      options.scale = cli::parseInt(args.name(), args.value(), 1, 8);
    } else if (args.is("--speed")) {
      options.degrees_per_second = cli::parseInt(args.name(), args.value(), 1, 720);
    } else if (args.is("--eye")) {
      options.eye = parseScanPoint(args.name(), args.value());
    } else if (args.is("--look")) {
      options.look = parseLook(args.name(), args.value());
    } else if (args.is("--fov")) {
      options.fov = Angle::fromMilliDegrees(
          std::llround(cli::parseReal(args.name(), args.value(), kMinFieldOfViewDegrees,
                                      kMaxFieldOfViewDegrees) *
                       1000));
    } else if (args.is("--walk-speed")) {
      options.walk_speed = cli::parseReal(args.name(), args.value(), 1e-12, kMaxEyeCoordinate);
    } else if (args.is("--near")) {
      options.near = cli::parseReal(args.name(), args.value(), 1e-12, kMaxEyeCoordinate);
    } else if (parseCollisionOption(args, options.collision)) {
      // --collide is walk mode's default; --eye-radius and --eye-height set the body.
    } else {
      args.refuseUnknown();
    }
  }
  checkOneModelSource(options.source);
  if (!options.city.empty() && (!options.source.model_name.empty() ||
                                !options.source.model_file.empty() || !options.source.url.empty()))
    throw cli::Error("give one of --model, --file, --url and --city");
  if (!options.cells.empty() && options.city.empty()) throw cli::Error("--cells needs --city");
  if (options.source.point_budget > 0 && options.source.url.empty())
    throw cli::Error("--point-budget needs --url");
  if (options.look && !options.eye) throw cli::Error("--look needs --eye");
  if (!options.source.url.empty() && options.collision.any()) {
    throw cli::Error(
        "--collide, --eye-radius and --eye-height: walk mode on a streamed model (--url) does not "
        "collide (the model is not all held)");
  }
  return options;
}

// Waits until the stream has the model's head (or refuses, one line, when it fails or takes more
// than kHeadTimeoutSeconds) and returns it assembled (its base): a model with the cube's placement
// and the base's depth, as octopoint-render --url takes them for --eye and --near.
constexpr int kHeadTimeoutSeconds = 30;
HeldParts waitForHead(net::ModelStream& stream, const std::string& url) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(kHeadTimeoutSeconds);
  while (true) {
    const net::StreamStatus status = stream.status();
    if (status.failed) throw cli::Error("--url: " + cli::inQuotes(url) + ": " + status.error);
    if (status.head_known) break;
    if (std::chrono::steady_clock::now() > deadline) {
      throw cli::Error("--url: " + cli::inQuotes(url) + ": no model head within " +
                       std::to_string(kHeadTimeoutSeconds) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  HeldParts head;
  stream.withModel([&head](ProgressiveModel* model) { head = assembleHeldParts(*model); });
  if (head.parts.empty()) throw cli::Error("--url: " + cli::inQuotes(url) + ": a bad head");
  return head;
}

int run(int argc, char** argv) {
  const ViewerOptions options = parseOptions(argc, argv);
  if (!options.source.url.empty()) {
    std::string why;
    const std::optional<net::HttpUrl> url = net::parseHttpUrl(options.source.url, &why);
    if (!url) throw cli::Error("--url: " + cli::inQuotes(options.source.url) + ": " + why);
    chooseVideoDriver();  // no display: refused before waiting for the head
    net::ModelStream stream(*url, net::StreamOptions{});  // prefetches the rest once the view is in
    // The head first, alone (no view until the viewer's first frame sets it): walk mode needs the
    // cube's placement (--eye in scan units, the overlay, p) and the base's depth for its near
    // plane, as octopoint-render --url --eye takes them.
    stream.clearView();
    std::atomic<Viewer*> shown{nullptr};
    stream.onAccepted([&shown](ProgressiveModel&, std::uint64_t) {
      if (Viewer* viewer = shown.load(); viewer != nullptr) viewer->contentChanged();
    });
    stream.start();
    const HeldParts head = waitForHead(stream, options.source.url);
    Viewer viewer(options, walkStart(options, &*head.parts.front()->view), nullptr, &stream);
    shown.store(&viewer);
    viewer.contentChanged();  // what arrived with the head or since
    viewer.run();
    stream.onAccepted({});
    stream.stop();
    return 0;
  }
  if (!options.city.empty()) {
    const WalkStart walk = cityWalkStart(options);  // a bad eye refused before the scene is read
    const std::unique_ptr<LoadedScene> scene = loadScene(options.city);
    std::optional<CellTable> cells;
    if (!options.cells.empty()) cells.emplace(loadCellTable(options.cells, *scene));
    SceneError error;
    SceneWalk scene_walk(scene->models, scene->instances, &error, cells ? &*cells : nullptr);
    if (error != SceneError::kNone) throw cli::Error(scene->label + ": " + describe(error));
    WalkStart start = walk;
    if (const std::optional<std::size_t> model = scene_walk.collision().unindexedModel()) {
      const std::string why = scene->label + ": model " + std::to_string(*model) +
                              "'s finest level is too large to collide with";
      if (options.collision.any()) throw cli::Error(why);
      cli::printError("octopoint-view", (why + ": walking without collision").c_str());
      start.body = {};
    }
    Viewer viewer(options, start, nullptr, nullptr, &scene_walk);
    viewer.run();
    return 0;
  }
  const std::unique_ptr<LoadedModel> loaded =
      loadModel(options.source.model_name, options.source.model_file);
  Viewer viewer(options, walkStart(options, &*loaded->view), &*loaded->view, nullptr);
  viewer.run();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-view", argc, argv, run);
}

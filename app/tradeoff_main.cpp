// octopoint-tradeoff: measures the speed/accuracy trade of octopoint on one scan
// (docs/tradeoff.md), either over depths and variants at one view or, with --sweep-views, over
// sizes and zooms.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/tradeoff.h"
#include "codegen/prepare_error.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;
using prepare::PrepareError;

constexpr const char* kUsage = R"(usage: octopoint-tradeoff SCAN [options]
       octopoint-tradeoff SCAN --sweep-views [options]

Measures the speed/accuracy trade of octopoint on one scan against a dense double precision
render of the scan's own surface (docs/tradeoff.md defines it).

Without --sweep-views: for every depth, decoder variant, fraction bits and hole filling on/off it
renders one view and records the time per frame, the model size and the quality. Writes
OUTDIR/tradeoff.csv, OUTDIR/tradeoff.png and OUTDIR/tradeoff_reference.png.

With --sweep-views: for every frame size and zoom it draws today's renderer (the finest depth of
the 7,8 model, one pixel per voxel, hole filling off and on) and octopoint's current one (depth
auto, footprint splats), and records time, depth, splat size, empty share of the silhouette, PSNR
and SSIM. Writes OUTDIR/sweep.csv and OUTDIR/sweep.md (the table and the issue's targets).

  --axes y-down|y-up     the scan's axes (as octopoint-prepare; default y-down)
  --crop X0,Y0,Z0,X1,Y1,Z1  keep the points inside this box (as octopoint-prepare)
  --yaw DEG, --pitch DEG the view (default 0, 0)
  --size WxH             framebuffer size (default 320x240)
  --zoom X               magnification, > 0 (default 1: the model cube spans the shorter side)
  --depths LIST          octree depths (default 6,7,8,9,10)
  --fraction-bits LIST   fixed-point fraction bits of the positions (default 8,12,15,20)
  --sweep-views          sweep sizes and zooms instead (the options below)
  --sizes LIST           WxH,WxH,... (default 176x208,320x240,640x480,1280x960,1920x1080)
  --zooms LIST           X,X,... (default 0.25,0.5,1,2,4,8)
  --label NAME           names the scan in the sweep's outputs (default: the file's stem)
  --pictures             also write OUTDIR/pictures/WxH_zoomX.png: reference | before | after,
                         and WxH_zoomX_empty.png: after's misses of the silhouette in red, its
                         pixels outside it in blue
  --rounds N             timing rounds over all cells, 1..100 (default 3): a cell's time is the
                         median of its rounds, each the median of at least 9 frames and 0.05 s
  -o, --output OUTDIR    where to write (default out)
  -h, --help             show this help
)";

struct Options {
  std::string scan;
  prepare::PrepareOptions prepare;
  tradeoff::DepthSweepOptions depth_sweep;
  tradeoff::ViewSweepOptions view_sweep;
  bool sweep_views = false;
  bool label_given = false;
  fs::path output = "out";
};

// Splits "a,b,c" and parses each item with `parse`, which throws on a bad one.
template <typename Parse>
auto parseEach(const std::string& flag, const std::string& text, Parse parse) {
  std::vector<decltype(parse(std::string()))> values;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    if (item.empty()) throw PrepareError(flag + ": '" + text + "' has an empty item");
    values.push_back(parse(item));
    at = comma + 1;
  }
  return values;
}

int parseInteger(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || value < -1000000 || value > 1000000) {
    throw PrepareError(flag + ": '" + text + "' is not an integer");
  }
  return static_cast<int>(value);
}

double parseZoom(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double zoom = std::strtod(text.c_str(), &end);
  const double raw = std::round(zoom * Q16::kOneRaw);
  if (text.empty() || *end != '\0' || !std::isfinite(zoom) || raw < 1 || raw > 0x7fffffff) {
    throw PrepareError(flag + ": '" + text + "' is not a zoom in 2^-16 .. 32767");
  }
  return zoom;
}

std::pair<int, int> parseSize(const std::string& flag, const std::string& text) {
  int width = 0, height = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 1 ||
      height < 1 || width > kMaxViewportSide || height > kMaxViewportSide) {
    throw PrepareError(flag + ": '" + text + "' is not WxH with sides 1.." +
                       std::to_string(kMaxViewportSide));
  }
  return {width, height};
}

Options parseOptions(int argc, char** argv) {
  Options options;
  Camera& camera = options.depth_sweep.camera;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw PrepareError(arg + ": missing value (see --help)");
      return argv[++i];
    };
    auto integers = [&](const std::string& text) {
      return parseEach(arg, text, [&](const std::string& item) { return parseInteger(arg, item); });
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--axes") {
      const std::string axes = value();
      if (axes != "y-down" && axes != "y-up")
        throw PrepareError("--axes: '" + axes + "' is not y-down or y-up");
      options.prepare.axes = axes == "y-up" ? prepare::ScanAxes::kYUp : prepare::ScanAxes::kYDown;
    } else if (arg == "--crop") {
      options.prepare.crop = prepare::parseCropBox(arg, value());
    } else if (arg == "--yaw") {
      camera.yaw = Angle::fromDegrees(parseInteger(arg, value()));
    } else if (arg == "--pitch") {
      camera.pitch = Angle::fromDegrees(parseInteger(arg, value()));
    } else if (arg == "--size") {
      std::tie(camera.width, camera.height) = parseSize(arg, value());
    } else if (arg == "--zoom") {
      camera.zoom = Q16::fromRaw(
          static_cast<std::int32_t>(std::round(parseZoom(arg, value()) * Q16::kOneRaw)));
    } else if (arg == "--depths") {
      options.depth_sweep.depths = integers(value());
    } else if (arg == "--fraction-bits") {
      options.depth_sweep.fraction_bits = integers(value());
    } else if (arg == "--sweep-views") {
      options.sweep_views = true;
    } else if (arg == "--sizes") {
      options.view_sweep.sizes =
          parseEach(arg, value(), [&](const std::string& item) { return parseSize(arg, item); });
    } else if (arg == "--zooms") {
      options.view_sweep.zooms =
          parseEach(arg, value(), [&](const std::string& item) { return parseZoom(arg, item); });
    } else if (arg == "--label") {
      options.view_sweep.label = value();
      options.label_given = true;
    } else if (arg == "--rounds") {
      options.view_sweep.rounds = parseInteger(arg, value());
      if (options.view_sweep.rounds < 1 || options.view_sweep.rounds > 100) {
        throw PrepareError("--rounds: " + std::to_string(options.view_sweep.rounds) +
                           " is outside 1..100");
      }
    } else if (arg == "--pictures") {
      options.view_sweep.pictures = true;
    } else if (arg == "-o" || arg == "--output") {
      options.output = value();
    } else if (!arg.empty() && arg[0] == '-') {
      throw PrepareError("unknown option '" + arg + "' (see --help)");
    } else if (!options.scan.empty()) {
      throw PrepareError("more than one SCAN given: '" + options.scan + "' and '" + arg + "'");
    } else {
      options.scan = arg;
    }
  }
  if (options.scan.empty()) throw PrepareError("no SCAN given (see --help)");
  options.view_sweep.camera = camera;
  if (!options.label_given) options.view_sweep.label = fs::path(options.scan).stem().string();
  return options;
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const tradeoff::Scene scene = tradeoff::loadScene(options.scan, options.prepare);
  std::error_code error;
  fs::create_directories(options.output, error);
  if (error)
    throw PrepareError(options.output.string() +
                       ": cannot create the output directory: " + error.message());
  if (options.sweep_views)
    tradeoff::runViewSweep(scene, options.view_sweep, options.output);
  else
    tradeoff::runDepthSweep(scene, options.depth_sweep, options.output);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "octopoint-tradeoff: %s\n", error.what());
  }
  return 1;
}

// octopoint-prepare: a range scan in, a model out (C++ sources to compile in, and a `.oct` file).
#include <chrono>
#include <cstdio>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_loader.h"
#include "codegen/scene.h"
#include "codegen/scene_views.h"
#include "renderer/model_format.h"

namespace {

using octopoint::prepare::PrepareError;

constexpr const char* kUsage = R"(usage: octopoint-prepare SCAN -o OUTDIR --name NAME [options]
       octopoint-prepare SCAN --scene SCENE.json -o OUTDIR --name NAME

Turns a range scan (.pcd or .ply: XYZ, XYZRGB/RGBA or XYZI, organized or not) into an octopoint
model: OUTDIR/NAME.h, OUTDIR/NAME.cpp and OUTDIR/NAME_depthD.cpp (const arrays an app compiles in)
and OUTDIR/NAME.oct (the same model as one binary file, for octopoint-render --file).

  SCAN                  the scan to read; points with a NaN or infinite coordinate are dropped
  -o, --output OUTDIR   where to write (created if missing); all files appear or none do
  --name NAME           the model's name: a C++ identifier, e.g. milk_carton
  --depths LIST         comma-separated octree depths, ascending, each 1..16 (default 7,8):
                        depth d cuts the fitted cube into 2^d voxels per axis
  --colours N           palette size, 1..256 (default 256)
  --crop X0,Y0,Z0,X1,Y1,Z1
                        keep only the points inside this box (scan units, inclusive) before
                        fitting: cuts away the background and far-away junk of a range scan
  --axes y-down|y-up    the scan's axis convention (default y-down): y-down is x right, y down,
                        z away from the sensor (PCL/OpenNI, OpenCV); y-up is x right, y up,
                        z toward the viewer (OpenGL). Models are stored y-down, so that the
                        default view is the sensor's
  --scan-unit UNIT      unit of the scan's coordinates: m, cm or mm (default m); only recorded
                        as the model's metric size
  --scene SCENE.json    the views the app will show (docs/scene.md): yaw/pitch ranges or
                        viewpoints, zoom range, framebuffer size, depths (or "auto"), palette,
                        crop box, outlier removal, axes. Voxels no view can see are pruned.
                        Replaces --depths, --colours, --crop, --axes and --scan-unit
  --emit strings|bytes  how the generated sources spell the arrays (default strings): string
                        literals in pieces MSVC accepts, or decimal initialiser lists; strings
                        compile ~10x faster in a quarter of the memory (docs/embedding.md)
  --single-source       write only NAME.h and NAME.cpp (all depths in one source), so that a
                        build rule can name its outputs before the depths are known
  -h, --help            show this help

Prints, per depth: voxels, node bytes, colour bytes and bits per point; with a scene also the
voxels and bytes before pruning and the time it took. On any error prints one
line on stderr and exits with status 1, leaving no output files.
)";

struct Arguments {
  std::string scan;
  std::string output_dir;
  std::string scene;
  octopoint::prepare::EmitOptions emit;
  std::vector<std::string> model_flags;  // flags a scene file replaces, to refuse them beside --scene
  octopoint::prepare::PrepareOptions options;
};

bool isIdentifier(const std::string& name) {
  if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return name.find("__") == std::string::npos && name[0] != '_';  // reserved identifiers
}

std::vector<int> parseDepths(const std::string& text) {
  std::vector<int> depths;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    char* end = nullptr;
    const long depth = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || depth < 1 || depth > octopoint::format::kMaxDepth) {
      throw PrepareError("--depths: '" + item + "' is not a depth in 1.." +
                         std::to_string(octopoint::format::kMaxDepth));
    }
    if (!depths.empty() && depth <= depths.back()) {
      throw PrepareError("--depths: depths must be strictly ascending, got '" + text + "'");
    }
    depths.push_back(static_cast<int>(depth));
    at = comma + 1;
  }
  if (static_cast<int>(depths.size()) > octopoint::format::kMaxLevels) {
    throw PrepareError("--depths: at most " + std::to_string(octopoint::format::kMaxLevels) + " depths");
  }
  return depths;
}

// Returns nullopt when --help was asked for.
std::optional<Arguments> parseArguments(int argc, char** argv) {
  Arguments args;
  bool have_name = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw PrepareError(arg + ": missing value (see --help)");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") return std::nullopt;
    if (arg == "-o" || arg == "--output") {
      args.output_dir = value();
    } else if (arg == "--name") {
      args.options.name = value();
      have_name = true;
    } else if (arg == "--scene") {
      args.scene = value();
    } else if (arg == "--emit") {
      const std::string style = value();
      if (style == "bytes") args.emit.style = octopoint::prepare::EmitStyle::kBytes;
      else if (style == "strings") args.emit.style = octopoint::prepare::EmitStyle::kStrings;
      else throw PrepareError("--emit: '" + style + "' is not bytes or strings");
    } else if (arg == "--single-source") {
      args.emit.single_source = true;
    } else if (arg == "--depths") {
      args.model_flags.push_back(arg);
      args.options.depths = parseDepths(value());
    } else if (arg == "--colours") {
      args.model_flags.push_back(arg);
      const std::string text = value();
      char* end = nullptr;
      const long colours = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || colours < 1 || colours > 256) {
        throw PrepareError("--colours: '" + text + "' is not a palette size in 1..256");
      }
      args.options.palette_colours = static_cast<int>(colours);
    } else if (arg == "--crop") {
      args.model_flags.push_back(arg);
      args.options.crop = octopoint::prepare::parseCropBox("--crop", value());
    } else if (arg == "--axes") {
      args.model_flags.push_back(arg);
      const std::string axes = value();
      if (axes == "y-down") args.options.axes = octopoint::prepare::ScanAxes::kYDown;
      else if (axes == "y-up") args.options.axes = octopoint::prepare::ScanAxes::kYUp;
      else throw PrepareError("--axes: '" + axes + "' is not y-down or y-up");
    } else if (arg == "--scan-unit") {
      args.model_flags.push_back(arg);
      const std::string unit = value();
      if (unit == "m") args.options.metres_per_scan_unit = 1.0;
      else if (unit == "cm") args.options.metres_per_scan_unit = 0.01;
      else if (unit == "mm") args.options.metres_per_scan_unit = 0.001;
      else throw PrepareError("--scan-unit: '" + unit + "' is not one of m, cm, mm");
    } else if (!arg.empty() && arg[0] == '-') {
      throw PrepareError("unknown option '" + arg + "' (see --help)");
    } else if (args.scan.empty()) {
      args.scan = arg;
    } else {
      throw PrepareError("unexpected argument '" + arg + "': only one SCAN is read (see --help)");
    }
  }
  if (args.scan.empty()) throw PrepareError("no SCAN given (see --help)");
  if (args.output_dir.empty()) throw PrepareError("no output directory given: use -o OUTDIR (see --help)");
  if (!have_name) throw PrepareError("no model name given: use --name NAME (see --help)");
  if (!args.scene.empty() && !args.model_flags.empty()) {
    throw PrepareError(args.model_flags.front() + ": not allowed with --scene (set it in the scene file)");
  }
  if (!isIdentifier(args.options.name)) {
    throw PrepareError("--name: '" + args.options.name +
                       "' is not a plain C++ identifier (letters, digits, single underscores)");
  }
  return args;
}

const char* shadingName(octopoint::prepare::ScanShading shading) {
  switch (shading) {
    case octopoint::prepare::ScanShading::kColour: return "colour";
    case octopoint::prepare::ScanShading::kIntensity: return "intensity as grey";
    case octopoint::prepare::ScanShading::kNone: return "no colour: depth shade";
  }
  return "?";
}

// Takes the model settings from a scene file; returns why the depths were chosen ("" when the
// scene lists them).
std::string applyScene(const octopoint::prepare::Scene& scene, octopoint::prepare::PrepareOptions& options) {
  using namespace octopoint::prepare;
  std::string reason;
  if (scene.auto_depths) {
    DepthChoice choice = chooseDepths(scene);
    options.depths = choice.depths;
    reason = choice.reason;
  } else {
    options.depths = scene.depths;
  }
  options.palette_colours = scene.palette_colours;
  options.greyscale = scene.greyscale;
  options.crop = scene.crop;
  options.outliers = scene.outliers;
  options.axes = scene.axes;
  options.metres_per_scan_unit = scene.metres_per_scan_unit;
  if (scene.prune) options.visibility_cameras = sceneCameras(scene);
  return reason;
}

int run(int argc, char** argv) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<Arguments> args = parseArguments(argc, argv);
  if (!args) {
    std::cout << kUsage;
    return 0;
  }
  using namespace octopoint::prepare;
  PrepareOptions options = args->options;
  std::string depth_reason;
  if (!args->scene.empty()) depth_reason = applyScene(loadScene(args->scene), options);
  const Scan scan = loadScan(args->scan);
  // The generated files name the exact command that made them, so anyone can regenerate them.
  options.source_description = std::filesystem::path(args->scan).filename().string() + " by: octopoint-prepare";
  for (int i = 1; i < argc; ++i) options.source_description += std::string(" ") + argv[i];
  const PreparedModel model = prepareModel(scan, args->scan, options);

  std::vector<OutputFile> files = emitSources(model, args->emit);
  const std::vector<std::uint8_t> image = serializeModel(model);
  files.push_back({model.name + ".oct", std::string(image.begin(), image.end())});
  writeFilesAtomically(args->output_dir, files);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %zu points (%zu dropped as non-finite), %s, %zu palette colours, cube edge %.3f m\n",
              args->scan.c_str(), scan.positions.size(), scan.dropped_non_finite,
              shadingName(scan.shading), model.palette.size(), model.cube_edge_um / 1e6);
  if (!depth_reason.empty()) std::printf("%s\n", depth_reason.c_str());
  for (const PreparedLevel& level : model.levels) {
    if (level.voxels_before_pruning == 0) continue;
    std::printf("  depth %2d pruned from %zu views: %zu -> %zu voxels, %zu -> %zu bytes (-%.1f%%) in %.2f s\n",
                level.depth, options.visibility_cameras.size(), level.voxels_before_pruning, level.leaves.size(),
                level.bytes_before_pruning, level.nodes.size() + level.leaves.size(),
                100.0 - 100.0 * static_cast<double>(level.nodes.size() + level.leaves.size()) /
                            static_cast<double>(level.bytes_before_pruning),
                level.pruning_seconds);
  }
  for (const PreparedLevel& level : model.levels) {
    const double voxels = static_cast<double>(level.leaves.size());
    std::printf("  depth %2d: %8zu voxels, %8zu node bytes + %8zu colour bytes = %9zu bytes, "
                "%.2f bits/point geometry, %.2f with colour\n",
                level.depth, level.leaves.size(), level.nodes.size(), level.leaves.size(),
                level.nodes.size() + level.leaves.size(), 8.0 * static_cast<double>(level.nodes.size()) / voxels,
                8.0 * static_cast<double>(level.nodes.size() + level.leaves.size()) / voxels);
  }
  std::printf("wrote %s/%s.{h,cpp,oct} (%zu bytes .oct) in %.2f s\n", args->output_dir.c_str(),
              model.name.c_str(), image.size(), seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const PrepareError& error) {
    std::fprintf(stderr, "octopoint-prepare: %s\n", error.what());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "octopoint-prepare: out of memory\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "octopoint-prepare: unexpected error: %s\n", error.what());
  }
  return 1;
}

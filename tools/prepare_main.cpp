// octopoint-prepare: a range scan in, a model out (C++ sources to compile in, and a `.oct` file).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "codegen/chunked_writer.h"
#include "codegen/depth_range.h"
#include "codegen/huge_pages.h"
#include "codegen/level_voxels.h"
#include "codegen/model_name.h"
#include "codegen/model_writer.h"
#include "codegen/point_source.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "codegen/scan_loader.h"
#include "codegen/scene.h"
#include "codegen/scene_views.h"
#include "codegen/streamed_prepare.h"
#include "codegen/whole_scan.h"
#include "octopoint/model.h"

namespace {

using octopoint::prepare::PrepareError;

constexpr std::int64_t kMaxMemoryMegabytes = std::int64_t{1} << 20;  // a terabyte
constexpr int kMaxThreads = 1024;

constexpr const char* kUsage = R"(usage: octopoint-prepare SCAN -o OUTDIR --name NAME [options]
       octopoint-prepare SCAN --scene SCENE.json -o OUTDIR --name NAME

Turns a range scan (.las, .pcd or .ply: XYZ, XYZRGB/RGBA or XYZI, organized or not) into an
octopoint model: OUTDIR/NAME.h, OUTDIR/NAME.cpp and OUTDIR/NAME_depthD.cpp (const arrays an app
compiles in) and OUTDIR/NAME.oct (the same model as one binary file, for octopoint-render --file).
LAS (1.0 to 1.4, point formats 0 to 10), LAZ (LASzip-compressed LAS, point formats 0 to 10, read
natively; COPC too) and binary PCD/PLY (PLY of either byte order) are streamed: any number of
points in bounded memory, on every core (LAZ chunks decoded in parallel); other PCD/PLY files are
loaded whole through PCL. The output is the same byte for byte whatever --memory and --threads
(docs/preparer.md).

  SCAN                  the scan to read (.las, .laz, .pcd, .ply): a regular file, streamed ones
                        of at most 4 TiB, those PCL loads of at most 1 GiB; points with a NaN or
                        infinite coordinate are dropped. LAS/LAZ colour is used when the format
                        has it and it is not all 0 (8- or 16-bit, detected), else the intensity
  -o, --output OUTDIR   where to write (created if missing); all files appear or none do, also
                        when interrupted (SIGINT, SIGTERM); existing outputs must be regular files.
                        A rerun replaces NAME's set: NAME_depthD.cpp files of an earlier run that
                        this one does not write (fewer depths, --single-source) are removed
  --name NAME           the model's name, e.g. milk_carton: a C++ identifier of at most 64
                        letters, digits and single underscores (not at either end), with a
                        lower-case letter, not a C++ keyword, not ending in _depthD (another
                        model's level source name)
  --depths LIST         comma-separated octree depths, strictly ascending, each 1..16, at most 8
                        of them, or a range A..B (default 6..10, cut where the scan stops
                        sampling densely: a depth with fewer than 3x the voxels of the depth
                        before is left out with all finer ones, unless its measured sample
                        reach, at most 4 voxel footprints, draws it whole from every side that
                        sees much of it, as on airborne scans sampled more coarsely than the
                        voxel; docs/splats.md): depth d cuts the fitted cube into 2^d voxels
                        per axis; an explicit list or range is kept whole
  --colours N           palette size, 1..256 (default 256)
  --crop X0,Y0,Z0,X1,Y1,Z1
                        keep only the points inside this box (scan units, inclusive) before
                        fitting: cuts away the background and far-away junk of a range scan;
                        from COPC only the octree nodes the box meets are read
  --axes y-down|y-up    the scan's axis convention (default y-down): y-down is x right, y down,
                        z away from the sensor (PCL/OpenNI, OpenCV); y-up is x right, y up,
                        z toward the viewer (OpenGL). Models are stored y-down, so that the
                        default view is the sensor's
  --scan-unit UNIT      unit of the scan's coordinates: m, cm or mm (default m); only recorded
                        as the model's metric size
  --normals             estimate surface normals (PCL: integral images on organized scans,
                        k-nearest-neighbour PCA otherwise; oriented toward the sensor; averaged
                        per voxel) and store one per voxel, as an index into a palette of 255
                        directions: one byte per voxel more. Needed by octopoint-render's
                        shaded, lines, toon and outlined styles (docs/styles.md)
  --scene SCENE.json    (a file of at most 1 MiB) the views the app will show (docs/scene.md): )"
                               R"(yaw/pitch ranges or
                        viewpoints, zoom range, framebuffer size, depths (or "auto"), palette,
                        crop box, outlier removal, axes, normals; perspective eyes and camera
                        paths (octopoint-render --eye/--path's). Voxels no view can see are
                        pruned. Replaces --depths, --colours, --crop, --axes, --scan-unit and
                        --normals
  --emit strings|bytes  how the generated sources spell the arrays (default strings): string
                        literals in pieces MSVC accepts, or decimal initialiser lists; strings
                        compile ~10x faster in a quarter of the memory (docs/embedding.md)
  --single-source       write only NAME.h and NAME.cpp (all depths in one source), so that a
                        build rule can name its outputs before the depths are known
  --chunked             write NAME.oct in the chunked format (version 3, docs/format.md): a
                        head with a coarse base, a directory, and chunks that refine the model
                        coarse to fine, for streaming (octopoint-serve, docs/streaming.md). The
                        depths (and a scene's pruning) are as without it; pruned depths are made
                        nested (each holds the parents of the next finer one's voxels)
  --chunk-bytes N       with --chunked: cut each depth into chunks of about N bytes or more on
                        average, 256..16777216 (default 2048, measured in docs/streaming.md);
                        larger when needed to keep the file within the version-1 size
  --memory MB           memory budget for the points in flight (default 1024, 1..1048576):
                        beyond it they go to temporary files; the model itself comes on top
  --threads N           threads to use (default: every core; 1..1024); fewer when the system
                        refuses more (an address-space or process limit), with the same output;
                        --normals' estimation (PCL, OpenMP) takes at most one per core
  --temp-dir DIR        where the temporary files go (default: $TMPDIR, else /tmp); they are
                        deleted as soon as they are made, so nothing is left behind. A LAZ
                        scan is decoded once: in one pass binned on its header's box (checked
                        against the points: a box that lies costs a second decoding), or,
                        with --crop or no box in the header, kept there for the second pass
                        (24 to 34 bytes a point) when the disk has room for twice that
  --progress            show progress on stderr (phase, points done, points/s, time left) even
                        when stderr is not a terminal; on a terminal it shows by itself for
                        steps longer than a second
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
  bool chunked = false;
  octopoint::prepare::ChunkedOptions chunking;
  octopoint::prepare::StreamOptions stream;
  std::vector<std::string>
      model_flags;  // flags a scene file replaces, to refuse them beside --scene
  octopoint::prepare::PrepareOptions options = defaultOptions();

  static octopoint::prepare::PrepareOptions defaultOptions() {
    octopoint::prepare::PrepareOptions options;
    options.depths = octopoint::prepare::defaultDepths();
    options.stop_at_sparse_depth = true;
    return options;
  }
};

// --depths: a list (cli::parseIntList's rules) or a range A..B of at most format::kMaxLevels
// depths.
std::vector<int> parseDepths(std::string_view option, const std::string& text) {
  using octopoint::format::kMaxDepth;
  using octopoint::format::kMaxLevels;
  const std::size_t dots = text.find("..");
  if (dots == std::string::npos) {
    return octopoint::cli::parseIntList(option, text, 1, kMaxDepth, kMaxLevels,
                                        octopoint::cli::ListOrder::kStrictlyAscending);
  }
  const int first =
      octopoint::cli::parseInt(option, std::string_view(text).substr(0, dots), 1, kMaxDepth);
  const int last =
      octopoint::cli::parseInt(option, std::string_view(text).substr(dots + 2), 1, kMaxDepth);
  if (last < first) {
    throw PrepareError(std::string(option) + ": " + octopoint::cli::inQuotes(text) +
                       " is an empty range");
  }
  if (last - first + 1 > kMaxLevels) {
    throw PrepareError(std::string(option) + ": " + octopoint::cli::inQuotes(text) + " is " +
                       std::to_string(last - first + 1) + " depths, at most " +
                       std::to_string(kMaxLevels));
  }
  std::vector<int> depths;
  for (int d = first; d <= last; ++d) depths.push_back(d);
  return depths;
}

// The flags a scene file replaces (--depths, --colours, --crop, --axes, --scan-unit, --normals),
// each noted in args.model_flags: false when `reader` holds another option.
bool parseModelFlag(octopoint::cli::ArgumentReader& reader, Arguments& args) {
  if (reader.is("--depths")) {
    args.model_flags.push_back(reader.name());
    args.options.depths = parseDepths(reader.name(), reader.value());
    args.options.stop_at_sparse_depth = false;
  } else if (reader.is("--colours")) {
    args.model_flags.push_back(reader.name());
    args.options.palette_colours = octopoint::cli::parseInt(reader.name(), reader.value(), 1, 256);
  } else if (reader.is("--crop")) {
    args.model_flags.push_back(reader.name());
    args.options.crop = octopoint::prepare::parseCropBox(reader.name(), reader.value());
  } else if (reader.is("--axes")) {
    args.model_flags.push_back(reader.name());
    args.options.axes =
        octopoint::cli::parseChoice(reader.name(), reader.value(), {"y-down", "y-up"}) == 0
            ? octopoint::prepare::ScanAxes::kYDown
            : octopoint::prepare::ScanAxes::kYUp;
  } else if (reader.is("--scan-unit")) {
    args.model_flags.push_back(reader.name());
    constexpr double kMetres[] = {1.0, 0.01, 0.001};
    args.options.metres_per_scan_unit =
        kMetres[octopoint::cli::parseChoice(reader.name(), reader.value(), {"m", "cm", "mm"})];
  } else if (reader.is("--normals")) {
    reader.noValue();
    args.model_flags.push_back(reader.name());
    args.options.normals = octopoint::prepare::NormalOptions{};
  } else {
    return false;
  }
  return true;
}

// The arguments every run needs, and no model flag beside --scene.
void checkArguments(const Arguments& args, bool have_name) {
  if (args.scan.empty()) throw PrepareError("no SCAN given (see --help)");
  if (args.output_dir.empty())
    throw PrepareError("no output directory given: use -o OUTDIR (see --help)");
  if (!have_name) throw PrepareError("no model name given: use --name NAME (see --help)");
  if (!args.scene.empty() && !args.model_flags.empty()) {
    throw PrepareError(args.model_flags.front() +
                       ": not allowed with --scene (set it in the scene file)");
  }
  const std::string name_problem = octopoint::prepare::modelNameProblem(args.options.name);
  if (!name_problem.empty()) {
    throw PrepareError("--name: " + octopoint::cli::inQuotes(args.options.name) + " " +
                       name_problem + " (see --help for model names)");
  }
}

// Returns nullopt when --help was asked for.
std::optional<Arguments> parseArguments(int argc, char** argv) {
  Arguments args;
  bool have_name = false;
  octopoint::cli::ArgumentReader reader(argc, argv);
  while (reader.next()) {
    if (reader.is("-h") || reader.is("--help")) return std::nullopt;
    if (reader.is("-o") || reader.is("--output")) {
      args.output_dir = reader.value();
    } else if (reader.is("--name")) {
      args.options.name = reader.value();
      have_name = true;
    } else if (reader.is("--scene")) {
      args.scene = reader.value();
    } else if (reader.is("--emit")) {
      args.emit.style =
          octopoint::cli::parseChoice(reader.name(), reader.value(), {"strings", "bytes"}) == 0
              ? octopoint::prepare::EmitStyle::kStrings
              : octopoint::prepare::EmitStyle::kBytes;
    } else if (reader.is("--single-source")) {
      reader.noValue();
      args.emit.single_source = true;
    } else if (reader.is("--chunked")) {
      reader.noValue();
      args.chunked = true;
    } else if (reader.is("--chunk-bytes")) {
      args.chunking.target_chunk_bytes = static_cast<std::size_t>(
          octopoint::cli::parseInteger(reader.name(), reader.value(), 256, 1 << 24));
    } else if (reader.is("--memory")) {
      args.stream.memory_bytes = static_cast<std::uint64_t>(octopoint::cli::parseInteger(
                                     reader.name(), reader.value(), 1, kMaxMemoryMegabytes))
                                 << 20;
    } else if (reader.is("--threads")) {
      args.stream.threads = static_cast<unsigned>(
          octopoint::cli::parseInt(reader.name(), reader.value(), 1, kMaxThreads));
      args.emit.threads = args.stream.threads;
    } else if (reader.is("--temp-dir")) {
      args.stream.temp_dir = reader.value();
    } else if (reader.is("--progress")) {
      reader.noValue();
      octopoint::prepare::Progress::force(true);
    } else if (parseModelFlag(reader, args)) {
      continue;
    } else if (reader.isPlain() && args.scan.empty()) {
      args.scan = reader.current();
    } else if (reader.isPlain()) {
      throw PrepareError("unexpected argument " + octopoint::cli::inQuotes(reader.current()) +
                         ": only one SCAN is read (see --help)");
    } else {
      reader.refuseUnknown();
    }
  }
  checkArguments(args, have_name);
  return args;
}

const char* shadingName(octopoint::prepare::ScanShading shading) {
  switch (shading) {
    case octopoint::prepare::ScanShading::kColour:
      return "colour";
    case octopoint::prepare::ScanShading::kIntensity:
      return "intensity as grey";
    case octopoint::prepare::ScanShading::kNone:
      return "no colour: depth shade";
  }
  return "?";
}

// Takes the model settings from a scene file; returns why the depths were chosen ("" when the
// scene lists them).
std::string applyScene(const octopoint::prepare::Scene& scene,
                       octopoint::prepare::PrepareOptions& options) {
  using namespace octopoint::prepare;
  std::string reason;
  if (scene.auto_depths) {
    DepthChoice choice = chooseDepths(scene);
    options.depths = choice.depths;
    options.stop_at_sparse_depth = true;
    reason = choice.reason;
  } else {
    options.depths = scene.depths;
    options.stop_at_sparse_depth = false;
  }
  options.palette_colours = scene.palette_colours;
  options.greyscale = scene.greyscale;
  options.crop = scene.crop;
  options.outliers = scene.outliers;
  options.axes = scene.axes;
  options.metres_per_scan_unit = scene.metres_per_scan_unit;
  options.normals = scene.normals;
  if (scene.prune) {
    if (scene.orthographic_views) options.visibility_cameras = sceneCameras(scene);
    options.visibility_eyes = scene.eyes;
    options.eye_width = scene.width;
    options.eye_height = scene.height;
  }
  return reason;
}

// Refuses, before any work, outputs that cannot be written: OUTDIR must be a directory (or not
// exist yet) and every file the run may write in it a regular file where it exists. A depth the
// scan turns out not to sample densely is left out later, so its file is checked too.
void checkOutputs(const Arguments& args, const octopoint::prepare::PrepareOptions& options) {
  const std::filesystem::path directory = args.output_dir;
  octopoint::cli::checkOutputDirectory(directory);
  std::error_code error;
  if (!std::filesystem::exists(directory, error)) return;
  std::vector<std::string> names = {options.name + ".h", options.name + ".cpp",
                                    options.name + ".oct"};
  if (!args.emit.single_source) {
    for (int depth : options.depths)
      names.push_back(options.name + "_depth" + std::to_string(depth) + ".cpp");
  }
  for (const std::string& name : names) octopoint::cli::checkOutputFile(directory / name);
}

// How often the points were read: ", decoded once (N MB kept on disk for pass 2)" when a
// compressed scan's points were kept; ", read once, binned on the header's box" when a LAS or
// LAZ header's box held (codegen/streamed_prepare.h).
std::string readOnce(const octopoint::prepare::PrepareSummary& summary) {
  if (summary.decoded_kept_bytes != 0) {
    return ", decoded once (" + std::to_string(summary.decoded_kept_bytes >> 20) +
           " MB kept on disk for pass 2)";
  }
  return summary.source_passes == 1 ? ", read once, binned on the header's box" : "";
}

// One line on how a streamed scan was read.
std::string describeStream(const octopoint::prepare::SourceInfo& info,
                           const octopoint::prepare::PrepareSummary& summary,
                           const octopoint::prepare::StreamOptions& stream) {
  const auto& phase = summary.phase_seconds;
  char line[768];
  std::snprintf(
      line, sizeof line,
      "  streamed %s%s%s: %llu points on %u threads in %.2f s (%.2f M points/s; bounds %.2f s, "
      "binning "
      "%.2f s, voxelizing %.2f s, palette %.2f s), budget %llu MB, %llu MB spilled to disk%s\n",
      info.format.c_str(), summary.colour_note.empty() ? "" : ", ", summary.colour_note.c_str(),
      static_cast<unsigned long long>(summary.points_in_file), summary.threads, summary.seconds,
      static_cast<double>(summary.points_in_file) / summary.seconds / 1e6, phase[0], phase[1],
      phase[2], phase[3], static_cast<unsigned long long>(stream.memory_bytes >> 20),
      static_cast<unsigned long long>(summary.spilled_bytes >> 20), readOnce(summary).c_str());
  std::string text = line;
  if (!summary.header_box_note.empty()) text += "  " + summary.header_box_note + "\n";
  if (summary.pieces_read < summary.pieces) {  // COPC: the crop met only some nodes
    std::snprintf(line, sizeof line,
                  "  the crop met %zu of the %zu COPC nodes: %llu points read and decoded\n",
                  summary.pieces_read, summary.pieces,
                  static_cast<unsigned long long>(summary.points_read));
    text += line;
  }
  if (summary.bytes_read > 0) {  // LAZ counts what it reads
    std::snprintf(line, sizeof line, "  %.1f MB of the file read\n",
                  static_cast<double>(summary.bytes_read) / 1e6);
    text += line;
  }
  return text;
}

// Streamed when the file allows it and no option needs the whole scan; else read whole through
// PCL, by octopoint-prepare-pcl (codegen/whole_scan.h). `stream_line`: the streaming's report.
octopoint::prepare::PreparedModel prepareScan(const Arguments& args,
                                              const octopoint::prepare::PrepareOptions& options,
                                              char** argv,
                                              octopoint::prepare::PrepareSummary& summary,
                                              std::string& stream_line) {
  using namespace octopoint::prepare;
  std::unique_ptr<PointSource> streamed;
  if (!options.outliers && !options.normals) streamed = openStreamedSource(args.scan);
  if (!streamed) return prepareWholeScan(args.scan, options, args.stream, summary, argv);
  PreparedModel model = prepareFromSource(*streamed, args.scan, options, args.stream, &summary);
  if (streamed->info().streamed)
    stream_line = describeStream(streamed->info(), summary, args.stream);
  return model;
}

// Writes the sources and the .oct image; returns the image's size in bytes.
std::size_t writeModel(const Arguments& args, const octopoint::prepare::PreparedModel& model,
                       octopoint::prepare::ChunkedLayout& layout) {
  using namespace octopoint::prepare;
  // The .oct image is made on a second thread while the sources are: both only read the model.
  // Where the system refuses that thread (a process or address-space limit), it is made by this
  // one when asked for (deferred).
  std::future<std::vector<std::uint8_t>> image_made =
      std::async(std::launch::async | std::launch::deferred, [&] {
        return args.chunked ? serializeChunkedModel(model, args.chunking, &layout)
                            : serializeModel(model);
      });
  std::vector<OutputFile> files = emitSources(model, args.emit);
  const std::vector<std::uint8_t> image = image_made.get();
  std::string image_text;
  reserveOnHugePages(image_text, image.size());
  image_text.append(reinterpret_cast<const char*>(image.data()), image.size());
  files.push_back({model.name + ".oct", std::move(image_text)});
  // A rerun replaces the model's whole set: level sources of depths it leaves out go too.
  octopoint::cli::writeFilesAtomically(args.output_dir, files,
                                       staleLevelSources(args.output_dir, model.name, files));
  return image.size();
}

// The normals, the pruning and each depth's voxels and bytes.
void printLevels(const octopoint::prepare::PreparedModel& model,
                 const octopoint::prepare::PrepareOptions& options) {
  using namespace octopoint::prepare;
  if (!model.normal_palette.empty()) {
    std::printf(
        "normals: %s, %zu-entry palette, stored with %.1f degrees mean and %.1f worst error "
        "(finest depth), "
        "1 byte per voxel, %.2f s\n",
        model.normals_from_integral_images
            ? "integral images over the sensor grid"
            : ("k-NN PCA, k = " + std::to_string(model.normal_neighbours)).c_str(),
        model.normal_palette.size(), model.normal_error_mean_deg, model.normal_error_max_deg,
        model.normal_seconds);
  }
  for (const PreparedLevel& level : model.levels) {
    if (level.voxels_before_pruning == 0) continue;
    std::printf(
        "  depth %2d pruned from %zu views and %zu eyes: %zu -> %zu voxels, %zu -> %zu bytes "
        "(-%.1f%%) in %.2f s\n",
        level.depth, options.visibility_cameras.size(), options.visibility_eyes.size(),
        level.voxels_before_pruning, level.leaves.size(), level.bytes_before_pruning,
        level.nodes.size() + level.leaves.size(),
        100.0 - 100.0 * static_cast<double>(level.nodes.size() + level.leaves.size()) /
                    static_cast<double>(level.bytes_before_pruning),
        level.pruning_seconds);
  }
  for (const PreparedLevel& level : model.levels) {
    const double voxels = static_cast<double>(level.leaves.size());
    const std::size_t bytes = level.nodes.size() + level.leaves.size() + level.normals.size();
    std::printf("  depth %2d: %8zu voxels, %8zu node bytes + %8zu colour bytes", level.depth,
                level.leaves.size(), level.nodes.size(), level.leaves.size());
    if (!level.normals.empty()) std::printf(" + %8zu normal bytes", level.normals.size());
    std::printf(" = %9zu bytes, %.2f bits/point geometry, %.2f with colour%s\n", bytes,
                8.0 * static_cast<double>(level.nodes.size()) / voxels,
                8.0 * static_cast<double>(bytes) / voxels,
                level.normals.empty() ? "" : " and normals");
  }
}

void printChunkedLayout(const octopoint::prepare::ChunkedLayout& layout,
                        std::size_t nesting_added) {
  if (nesting_added > 0)
    std::printf("  nesting the pruned depths added %zu voxels\n", nesting_added);
  std::printf(
      "  chunked: base depth %d%s, head %zu bytes, directory %zu bytes, chunks of %zu bytes or "
      "more on average\n",
      layout.base_depth, layout.base_added ? " (added)" : "", layout.head_bytes, layout.table_bytes,
      layout.target_chunk_bytes);
  for (std::size_t j = 0; j < layout.depths.size(); ++j) {
    std::printf("  chunked depth %2d: %6zu chunks (regions at tree level %d), %9zu bytes\n",
                layout.depths[j], layout.chunks[j], layout.region_levels[j], layout.chunk_bytes[j]);
  }
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
  if (args->chunked && options.normals) {
    throw PrepareError(
        "--chunked: the chunked format (version 3) stores no normals; leave out --normals (or the "
        "scene's \"normals\") or write a version 2 file");
  }
  checkOutputs(*args, options);
  // The generated files name the exact command that made them, so anyone can regenerate them.
  options.source_description =
      std::filesystem::path(args->scan).filename().string() + " by: octopoint-prepare";
  for (int i = 1; i < argc; ++i) options.source_description += std::string(" ") + argv[i];
  PrepareSummary summary;
  std::string stream_line;
  PreparedModel model = prepareScan(*args, options, argv, summary, stream_line);
  // A chunked file refines each depth from the one above it, so its depths must be nested; the
  // sources get the same voxels, so that both draw alike.
  const std::size_t nesting_added = args->chunked ? nestLevels(model) : 0;
  ChunkedLayout layout;

  const auto writing = std::chrono::steady_clock::now();
  const std::size_t image_bytes = writeModel(*args, model, layout);
  const double writing_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - writing).count();

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%s: %llu points (%llu dropped as non-finite), %s, %zu palette colours, cube edge %.4g m\n",
      args->scan.c_str(), static_cast<unsigned long long>(summary.finite_points),
      static_cast<unsigned long long>(summary.dropped_non_finite), shadingName(summary.shading),
      model.palette.size(), static_cast<double>(model.cube_edge_pm) * 1e-12);
  std::fputs(stream_line.c_str(), stdout);
  if (!depth_reason.empty()) std::printf("%s\n", depth_reason.c_str());
  if (!model.sparse_depths_dropped.empty()) {
    std::printf(
        "  left out depths %s: finer than the scan samples densely (under %zux the voxels of the "
        "depth before) and not drawn whole by a sample reach of at most %d footprints; the "
        "renderer splats the finest depth kept\n",
        describeDepths(model.sparse_depths_dropped).c_str(), kDenseGrowth,
        kMaxKeptSampleReach / 16);
  }
  printLevels(model, options);
  if (args->chunked) printChunkedLayout(layout, nesting_added);
  std::printf("wrote %s/%s.{h,cpp,oct} (%zu bytes .oct%s) in %.2f s (writing the files %.2f s)\n",
              args->output_dir.c_str(), model.name.c_str(), image_bytes,
              args->chunked ? ", chunked" : "", seconds, writing_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-prepare", argc, argv, run);
}

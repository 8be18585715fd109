// octopoint-tradeoff: measures the speed/accuracy trade of octopoint on one scan
// (docs/tradeoff.md), either over depths and variants at one view or, with --sweep-views, over
// sizes and zooms.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "lab/splat_rule_flag.h"
#include "lab/tradeoff.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr const char* kUsage = R"(usage: octopoint-tradeoff SCAN [options]
       octopoint-tradeoff SCAN --sweep-views [options]

Measures the speed/accuracy trade of octopoint on one scan against a dense double precision
render of the scan's own surface (docs/tradeoff.md defines it).

Without --sweep-views: for every depth, decoder variant, fraction bits and hole filling on/off it
renders one view and records the time per frame, the model size and the quality. Writes
OUTDIR/tradeoff.csv, OUTDIR/tradeoff.png and OUTDIR/tradeoff_reference.png.

With --sweep-views: for every frame size and zoom it draws today's renderer (the finest depth of
the 7,8 model, one pixel per voxel, hole filling off and on) and octopoint's current one (depth
auto, footprint splats), and records time, depth, splat size, empty share of the silhouette, PSNR,
SSIM, each model's palette ceiling (the best PSNR any frame of it can reach) and the share of the
squared error in the silhouette's interior, the 2-pixel bands inside and outside its outline and
the rest. Writes OUTDIR/sweep.csv and OUTDIR/sweep.md (the tables and the issue's targets).

  --axes y-down|y-up     the scan's axes (as octopoint-prepare; default y-down)
  --crop X0,Y0,Z0,X1,Y1,Z1  keep the points inside this box (as octopoint-prepare)
  --yaw DEG, --pitch DEG the view, |DEG| <= 1e6 (default 0, 0)
  --size WxH             framebuffer size, each side 1..8192, at most 16777216 pixels
                         (default 320x240)
  --zoom X               magnification, 1/65536..32767 (default 1: the model cube spans the
                         shorter side of the frame)
  --depths LIST          octree depths, strictly ascending, each 1..16 (default 6,7,8,9,10)
  --fraction-bits LIST   fixed-point fraction bits of the positions, strictly ascending, each
                         1..24 (default 8,12,15,20); a setting the camera refuses for this view
                         (too few integer bits for the frame) is an error
  --sweep-views          sweep sizes and zooms instead (the options below; --size and --zoom
                         are then not used)
  --sizes LIST           WxH,WxH,... up to 16 sizes, each as --size
                         (default 176x208,320x240,640x480,1280x960,1920x1080)
  --zooms LIST           X,X,... up to 16 zooms, each as --zoom (default 0.25,0.5,1,2,4,8)
  --label NAME           names the scan in the sweep's outputs, 1..64 printable characters
                         without ',' '|' or '"' (default: the file's stem)
  --pictures             also write OUTDIR/pictures/WxH_zoomX.png (reference | before with
                         filling | after) and WxH_zoomX_empty.png (after's misses of the
                         silhouette in red, its pixels outside it in blue), each as it is made
  --rounds N             timing rounds over all cells, 1..100 (default 3): a cell's time is the
                         median of its rounds, each the median of at least 9 frames and 0.05 s
  --sparse F             the reference of an unorganized scan draws a point whose 8th neighbour
                         lies more than F times as far as the median point's as a stray return's
                         small disc (a sparse outlier, docs/tradeoff.md "The reference render");
                         F 0 (none) or 1..10 (default 1.9). A scan whose real surfaces are sampled
                         that much more coarsely than its median wants 0
  -o, --output OUTDIR    where to write (default out); the tables appear together at the end or
                         not at all, and existing ones must be regular files
  -h, --help             show this help

SCAN is a regular file of at most 1 GiB. On any error prints one line on stderr and exits with
status 1; every view is checked before anything is written.
)";

// The largest frame drawn: the same cap as octopoint-render's images.
constexpr std::int64_t kMaxFramePixels = std::int64_t{4096} * 4096;
constexpr std::size_t kMaxListItems = 16;
constexpr std::size_t kMaxLabelLength = 64;

struct Options {
  std::string scan;
  prepare::PrepareOptions prepare;
  tradeoff::DepthSweepOptions depth_sweep;
  tradeoff::ViewSweepOptions view_sweep;
  bool sweep_views = false;
  bool label_given = false;
  tradeoff::SplatRule reference_rule = tradeoff::kSplatRule;
  fs::path output = "out";
};

// Splits "a,b,c" (1..kMaxListItems items) and parses each item with `parse`.
template <typename Parse>
auto parseEach(const std::string& option, const std::string& text, Parse parse) {
  std::vector<decltype(parse(std::string()))> values;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    if (item.empty()) {
      throw cli::Error(option + ": item " + std::to_string(values.size() + 1) + " of " +
                       cli::inQuotes(text) + " is empty");
    }
    if (values.size() == kMaxListItems) {
      throw cli::Error(option + ": more than " + std::to_string(kMaxListItems) + " items");
    }
    values.push_back(parse(item));
    at = comma + 1;
  }
  return values;
}

cli::FrameSize parseSize(const std::string& option, const std::string& text) {
  return cli::parseFrameSize(option, text, 1, kMaxViewportSide, kMaxFramePixels);
}

// The label goes into CSV cells and markdown tables: printable, and none of their separators.
std::string parseLabel(const std::string& option, const std::string& text) {
  const bool plain = std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return c >= 0x20 && c < 0x7f && c != ',' && c != '|' && c != '"';
  });
  if (text.empty() || text.size() > kMaxLabelLength || !plain) {
    throw cli::Error(option + ": " + cli::inQuotes(text) + " is not 1.." +
                     std::to_string(kMaxLabelLength) +
                     " printable characters without ',' '|' or '\"'");
  }
  return text;
}

Options parseOptions(int argc, char** argv) {
  Options options;
  Camera& camera = options.depth_sweep.camera;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      std::exit(0);
    } else if (args.is("--axes")) {
      options.prepare.axes = cli::parseChoice(args.name(), args.value(), {"y-down", "y-up"}) == 0
                                 ? prepare::ScanAxes::kYDown
                                 : prepare::ScanAxes::kYUp;
    } else if (args.is("--crop")) {
      options.prepare.crop = prepare::parseCropBox(args.name(), args.value());
    } else if (args.is("--yaw")) {
      camera.yaw = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--pitch")) {
      camera.pitch = cli::parseDegrees(args.name(), args.value());
    } else if (args.is("--size")) {
      const cli::FrameSize size = parseSize(args.name(), args.value());
      camera.width = size.width;
      camera.height = size.height;
    } else if (args.is("--zoom")) {
      camera.zoom = cli::parseZoom(args.name(), args.value());
    } else if (args.is("--depths")) {
      options.depth_sweep.depths =
          cli::parseIntList(args.name(), args.value(), 1, format::kMaxDepth, format::kMaxDepth,
                            cli::ListOrder::kStrictlyAscending);
    } else if (args.is("--fraction-bits")) {
      options.depth_sweep.fraction_bits =
          cli::parseIntList(args.name(), args.value(), kMinFractionBits, kMaxFractionBits,
                            kMaxFractionBits, cli::ListOrder::kStrictlyAscending);
    } else if (args.is("--sweep-views")) {
      args.noValue();
      options.sweep_views = true;
    } else if (args.is("--sizes")) {
      const std::string name = args.name();
      options.view_sweep.sizes.clear();
      for (const cli::FrameSize& size : parseEach(name, args.value(), [&](const std::string& item) {
             return parseSize(name, item);
           })) {
        options.view_sweep.sizes.emplace_back(size.width, size.height);
      }
    } else if (args.is("--zooms")) {
      const std::string name = args.name();
      options.view_sweep.zooms = parseEach(name, args.value(), [&](const std::string& item) {
        return cli::parseZoom(name, item).raw() / static_cast<double>(Q16::kOneRaw);
      });
    } else if (args.is("--label")) {
      options.view_sweep.label = parseLabel(args.name(), args.value());
      options.label_given = true;
    } else if (args.is("--rounds")) {
      options.view_sweep.rounds = cli::parseInt(args.name(), args.value(), 1, 100);
    } else if (args.is("--pictures")) {
      args.noValue();
      options.view_sweep.pictures = true;
    } else if (args.is("--sparse")) {
      const std::string name = args.name();
      options.reference_rule.sparse_factor = tradeoff::parseSparseFactor(name, args.value());
    } else if (args.is("-o") || args.is("--output")) {
      options.output = args.value();
    } else if (args.isPlain() && options.scan.empty()) {
      options.scan = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (options.scan.empty()) throw cli::Error("no SCAN given (see --help)");
  options.view_sweep.camera = camera;
  if (!options.label_given) {
    std::string stem = fs::path(options.scan).stem().string();
    std::replace_if(
        stem.begin(), stem.end(), [](char c) { return c == ',' || c == '|' || c == '"'; }, '_');
    options.view_sweep.label = cli::printable(stem.substr(0, kMaxLabelLength));
  }
  return options;
}

// Refuses, before any work, an output directory or output file that cannot be written.
void checkOutputs(const Options& options) {
  cli::checkOutputDirectory(options.output);
  std::error_code error;
  if (!fs::exists(options.output, error)) return;  // made at the end
  const std::vector<std::string> names =
      options.sweep_views ? tradeoff::viewSweepOutputNames() : tradeoff::depthSweepOutputNames();
  for (const std::string& name : names) cli::checkOutputFile(options.output / name);
  if (options.sweep_views && options.view_sweep.pictures) {
    cli::checkOutputDirectory(options.output / "pictures");
  }
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  checkOutputs(options);
  if (!options.sweep_views) tradeoff::checkDepthSweepViews(options.depth_sweep);
  const tradeoff::Scene scene =
      tradeoff::loadScene(options.scan, options.prepare, options.reference_rule);
  const std::vector<cli::OutputFile> files =
      options.sweep_views ? tradeoff::runViewSweep(scene, options.view_sweep, options.output)
                          : tradeoff::runDepthSweep(scene, options.depth_sweep);
  cli::writeFilesAtomically(options.output, files);
  for (const cli::OutputFile& file : files)
    std::printf("wrote %s\n", (options.output / file.name).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-tradeoff", argc, argv, run);
}

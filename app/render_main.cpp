// octopoint-render: draws a model (embedded in this binary, or a `.oct` file) to a PNG.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "app/contact_sheet.h"
#include "app/model_source.h"
#include "models/registry.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/hole_fill.h"
#include "renderer/model.h"
#include "renderer/render.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr const char* kUsage = R"(usage: octopoint-render [--model NAME | --file M.oct] [options] -o OUT.png
       octopoint-render --list

Draws an octopoint model with the integer renderer and writes it as a PNG. With neither --model
nor --file it draws the default model embedded in this binary.

  --model NAME       an embedded model (see --list)
  --file M.oct       a model file written by octopoint-prepare; it is validated before drawing
  --yaw DEG          turn about the vertical axis (default 0; the scan as its sensor saw it)
  --pitch DEG        turn about the horizontal axis (default 0)
  --roll DEG         turn about the viewing axis (default 0)
  --zoom X           magnification, > 0 (default 1: the model cube spans the shorter side)
  --size WxH         framebuffer size in pixels, each 1..8192 (default 320x240)
  --depth N          which of the model's depths to draw (default: the finest)
  --variant NAME     decoder variant (default fixed_baseline; see --list)
  --fill, --no-fill  scanline hole filling after decoding, as the paper does (default --fill;
                     docs/holefill.md)
  --sheet N          a contact sheet instead: N yaw angles (1..36) in columns, each depth of
                     the model unfilled and filled in rows
  -o, --output FILE  the PNG to write (written whole or not at all)
  --list             list the embedded models and the decoder variants
  -h, --help         show this help

On any error prints one line on stderr and exits with status 1, writing nothing.
)";

constexpr Rgb kBackground{236, 236, 240};  // light grey: range scans are often dark

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::string model_name;
  std::string model_file;
  std::string output;
  Camera camera;
  std::optional<int> depth;
  Variant variant = Variant::kFixedBaseline;
  bool list = false;
  bool fill = true;
  int sheet = 0;  // yaw angles of the contact sheet; 0: a single view
};

double parseNumber(const std::string& flag, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
    throw UsageError(flag + ": '" + text + "' is not a number");
  }
  return value;
}

Angle parseDegrees(const std::string& flag, const std::string& text) {
  const double degrees = parseNumber(flag, text);
  if (std::fabs(degrees) > 1e9) throw UsageError(flag + ": '" + text + "' is out of range");
  // Host-side parsing only: the renderer sees the integer angle (1/65536 turn).
  return Angle::fromMilliDegrees(std::llround(degrees * 1000));
}

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(arg + ": missing value (see --help)");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--list") {
      options.list = true;
    } else if (arg == "--model") {
      options.model_name = value();
    } else if (arg == "--file") {
      options.model_file = value();
    } else if (arg == "--yaw") {
      options.camera.yaw = parseDegrees(arg, value());
    } else if (arg == "--pitch") {
      options.camera.pitch = parseDegrees(arg, value());
    } else if (arg == "--roll") {
      options.camera.roll = parseDegrees(arg, value());
    } else if (arg == "--zoom") {
      const std::string text = value();
      const double zoom = parseNumber(arg, text);
      const double raw = std::round(zoom * Q16::kOneRaw);
      if (!(raw >= 1) || raw > 2147483647.0) {
        throw UsageError("--zoom: '" + text + "' is outside the supported range (2^-16 .. 32767)");
      }
      options.camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(raw));
    } else if (arg == "--size") {
      const std::string text = value();
      int width = 0, height = 0;
      char tail = 0;
      if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 1 ||
          height < 1 || width > kMaxViewportSide || height > kMaxViewportSide) {
        throw UsageError("--size: '" + text + "' is not WxH with each side in 1..8192");
      }
      options.camera.width = width;
      options.camera.height = height;
    } else if (arg == "--depth") {
      options.depth = static_cast<int>(parseNumber(arg, value()));
    } else if (arg == "--variant") {
      const std::string name = value();
      const std::optional<Variant> variant = variantFromName(name);
      if (!variant) throw UsageError("--variant: unknown variant '" + name + "' (see --list)");
      options.variant = *variant;
    } else if (arg == "--fill" || arg == "--no-fill") {
      options.fill = arg == "--fill";
    } else if (arg == "--sheet") {
      const std::string text = value();
      const double count = parseNumber(arg, text);
      if (count < 1 || count > 36 || count != std::floor(count)) {
        throw UsageError("--sheet: '" + text + "' is not a whole number in 1..36");
      }
      options.sheet = static_cast<int>(count);
    } else if (arg == "-o" || arg == "--output") {
      options.output = value();
    } else {
      throw UsageError("unknown argument '" + arg + "' (see --help)");
    }
  }
  if (!options.model_name.empty() && !options.model_file.empty()) {
    throw UsageError("give --model or --file, not both");
  }
  if (!options.list && options.output.empty()) throw UsageError("no output given: use -o OUT.png");
  return options;
}

void listModels() {
  std::printf("embedded models (default first):\n");
  for (const EmbeddedModel* model : models::embeddedModels()) {
    std::printf("  %-20s depths", model->name);
    for (int i = 0; i < model->level_count; ++i) {
      std::printf(" %d (%u voxels)", model->levels[i].depth, model->levels[i].leaf_count);
    }
    std::printf("\n");
  }
  std::printf("variants:\n");
  for (const VariantInfo& info : allVariants()) {
    std::printf("  %-20.*s %.*s\n", static_cast<int>(info.name.size()), info.name.data(),
                static_cast<int>(info.summary.size()), info.summary.data());
  }
}

void writePng(const std::string& path, const cv::Mat& image) {
  // Written to a temporary beside the target and renamed, so a failure leaves no partial PNG.
  const fs::path target(path);
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on a chain of string + here.
  std::string temporary_name = ".";
  temporary_name += target.filename().string();
  temporary_name += ".tmp-";
  temporary_name += std::to_string(::getpid());
  temporary_name += ".png";
  const fs::path temporary = target.parent_path() / temporary_name;
  bool written = false;
  try {
    written = cv::imwrite(temporary.string(), image);
  } catch (const cv::Exception&) {
    written = false;
  }
  std::error_code error;
  if (written) fs::rename(temporary, target, error);
  if (!written || error) {
    fs::remove(temporary, error);
    throw UsageError(path + ": cannot write the PNG here");
  }
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  if (options.list) {
    listModels();
    return 0;
  }
  const std::unique_ptr<LoadedModel> loaded = loadModel(options.model_name, options.model_file);
  const ModelView* model = &*loaded->view;
  const std::string& model_label = loaded->label;
  const LevelView* level = options.depth ? model->levelOfDepth(*options.depth) : &model->finestLevel();
  if (level == nullptr) {
    std::string depths;
    for (int i = 0; i < model->levelCount(); ++i) {
      depths += ' ';  // appended char by char: GCC 12 warns falsely (-Wrestrict) on " " + string
      depths += std::to_string(model->level(i).depth);
    }
    throw UsageError("--depth: " + model_label + " has no depth " + std::to_string(*options.depth) +
                     " (it has" + depths + ")");
  }
  if (options.sheet > 0) {
    try {
      writePng(options.output,
               renderContactSheet(*model, options.camera, options.sheet, options.variant, kBackground));
    } catch (const cv::Exception& error) {
      throw UsageError(std::string("contact sheet: ") + error.what());
    } catch (const std::runtime_error& error) {
      throw UsageError(error.what());
    }
    std::printf("%s: contact sheet of %d views -> %s\n", model_label.c_str(), options.sheet,
                options.output.c_str());
    return 0;
  }
  FrameSetup setup;
  const CameraError camera_error =
      buildFrameSetup(options.camera, level->depth, kDefaultFractionBits, &setup);
  if (camera_error != CameraError::kNone) throw UsageError(std::string("camera refused: ") + describe(camera_error));

  Framebuffer frame(options.camera.width, options.camera.height);
  frame.clear();
  renderLevel(options.variant, *level, setup, frame);
  if (options.fill) HoleFiller(frame.width()).fill(frame, bridgeDepthLimit(setup));

  cv::Mat rgb(options.camera.height, options.camera.width, CV_8UC3);
  resolveToRgb(frame, *model, kBackground, {rgb.data, rgb.total() * 3});
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  writePng(options.output, bgr);
  std::printf("%s: depth %d, %zu points -> %s (%dx%d)\n", model_label.c_str(), level->depth,
              level->leaves.size(), options.output.c_str(), options.camera.width, options.camera.height);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const UsageError& error) {
    std::fprintf(stderr, "octopoint-render: %s\n", error.what());
  } catch (const ModelLoadError& error) {
    std::fprintf(stderr, "octopoint-render: %s\n", error.what());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "octopoint-render: unexpected error: %s\n", error.what());
  }
  return 1;
}

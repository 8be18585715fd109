// octopoint-render: draws a model (embedded in this binary, or a `.oct` file) to a PNG.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "cli/text.h"
#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "octopoint/styles.h"
#include "renderer/chunked_assembly.h"
#include "renderer/level_of_detail.h"
#include "tools/chunked_render.h"
#include "tools/contact_sheet.h"
#include "tools/model_info.h"
#include "tools/model_source.h"
#include "tools/perspective_render.h"
#include "tools/png_file.h"
#include "tools/render_usage.h"
#include "tools/scene_render.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr Rgb kBackground{236, 236, 240};  // light grey: range scans are often dark

struct Options {
  ModelSourceOptions source;
  UrlFetchOptions fetch;  // its point budget is the source's
  std::string output;
  Camera camera;
  std::optional<int> depth;  // none: depth auto
  Variant variant = defaultVariant();
  bool list = false;
  bool info = false;
  bool orbit_camera = false;  // --yaw, --pitch, --roll, --zoom or --pan given
  bool fill = false;
  SplatMode splats = SplatMode::kBox;
  int sheet = 0;  // yaw angles of the contact sheet; 0: a single view
  PerspectiveOptions perspective;
  StyleOptions style;
  std::string city;   // --city SCENE.json
  std::string cells;  // --cells CELLS, with --city
};

// "AZ,EL" in degrees, each within +-90.
Light parseLight(std::string_view option, std::string_view text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) {
    throw cli::Error(std::string(option) + ": " + cli::inQuotes(text) +
                     " is not AZIMUTH,ELEVATION in degrees");
  }
  Light light;
  const double azimuth = cli::parseReal(option, text.substr(0, comma), -90, 90);
  const double elevation = cli::parseReal(option, text.substr(comma + 1), -90, 90);
  // Host side only: the renderer sees the integer angles (1/65536 turn).
  light.azimuth = Angle::fromMilliDegrees(std::llround(azimuth * 1000));
  light.elevation = Angle::fromMilliDegrees(std::llround(elevation * 1000));
  return light;
}

// The view options (--yaw, --pitch, --roll, --zoom, --pan, --size): false when `args` holds
// another option.
bool parseViewOption(cli::ArgumentReader& args, Camera& camera) {
  if (args.is("--yaw")) {
    camera.yaw = cli::parseDegrees(args.name(), args.value());
  } else if (args.is("--pitch")) {
    camera.pitch = cli::parseDegrees(args.name(), args.value());
  } else if (args.is("--roll")) {
    camera.roll = cli::parseDegrees(args.name(), args.value());
  } else if (args.is("--zoom")) {
    camera.zoom = cli::parseZoom(args.name(), args.value());
  } else if (args.is("--pan")) {
    const std::string text = args.value();
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos)
      throw cli::Error("--pan: " + cli::inQuotes(text) + " is not X,Y");
    camera.pan_x_px = cli::parseInt(args.name(), text.substr(0, comma), -1'000'000, 1'000'000);
    camera.pan_y_px = cli::parseInt(args.name(), text.substr(comma + 1), -1'000'000, 1'000'000);
  } else if (args.is("--size")) {
    const cli::FrameSize size =
        cli::parseFrameSize(args.name(), args.value(), 1, kMaxViewportSide, kMaxOutputPixels);
    camera.width = size.width;
    camera.height = size.height;
  } else {
    return false;
  }
  return true;
}

// The style options (--style, --light, --headlight, --crease): false when `args` holds another
// option.
bool parseStyleOption(cli::ArgumentReader& args, StyleOptions& style) {
  if (args.is("--style")) {
    const std::size_t choice = cli::parseChoice(args.name(), args.value(),
                                                {"colour", "shaded", "lines", "toon", "outlined"});
    style.style = allStyles()[choice].style;
  } else if (args.is("--light")) {
    const bool headlight = style.light.headlight;
    style.light = parseLight(args.name(), args.value());
    style.light.headlight = headlight;
  } else if (args.is("--headlight")) {
    args.noValue();
    style.light.headlight = true;
  } else if (args.is("--crease")) {
    style.crease_angle = Angle::fromMilliDegrees(
        std::llround(cli::parseReal(args.name(), args.value(), 1, 179) * 1000));
  } else {
    return false;
  }
  return true;
}

// How a URL is fetched (--bytes, --timeout): false when `args` holds another option.
bool parseFetchOption(cli::ArgumentReader& args, UrlFetchOptions& fetch) {
  if (args.is("--bytes")) {
    fetch.bytes = static_cast<std::uint64_t>(
        cli::parseInteger(args.name(), args.value(), 1, std::int64_t{1} << 50));
  } else if (args.is("--timeout")) {
    fetch.timeout_seconds = cli::parseInt(args.name(), args.value(), 1, 86400);
  } else {
    return false;
  }
  return true;
}

// The options that exclude or need each other.
void checkCombination(const Options& options) {
  checkOneModelSource(options.source);
  if (!options.city.empty()) {
    checkCityOptions(options.perspective, options.orbit_camera,
                     !options.source.model_name.empty() || !options.source.model_file.empty() ||
                         !options.source.url.empty(),
                     options.depth.has_value(), options.fill, options.sheet > 0,
                     options.style.style != Style::kColour);
    if (options.output.empty()) throw cli::Error("no output given: use -o OUT.png");
    return;
  }
  if (!options.cells.empty()) throw cli::Error("--cells needs --city (they are a scene's cells)");
  const bool url = !options.source.url.empty();
  if (!url && options.fetch.bytes > 0) throw cli::Error("--bytes needs --url");
  if (url && (options.depth || options.sheet > 0)) {
    throw cli::Error("--url draws the depth the view needs: --depth and --sheet do not apply");
  }
  if (url && options.style.style != Style::kColour) {
    throw cli::Error("--style " + std::string(styleName(options.style.style)) +
                     ": --url draws a chunked model, in colour only (it stores no normals)");
  }
  if (options.perspective.any() && options.depth && options.source.point_budget > 0) {
    throw cli::Error(std::string(options.perspective.mode()) +
                     " --point-budget chooses each part's depth by distance: --depth N does not "
                     "apply");
  }
  checkPerspectiveOptions(options.perspective, {options.orbit_camera, options.sheet > 0});
  if (options.info &&
      (url || options.perspective.any() || options.sheet > 0 || !options.output.empty())) {
    throw cli::Error(
        "--info prints what a model file or an embedded model holds: give no -o, "
        "--url, --sheet or perspective option");
  }
  if (options.splats == SplatMode::kSmooth &&
      (options.fill || options.sheet > 0 || options.perspective.any() ||
       !drawsSplats(options.variant))) {
    throw cli::Error(
        "--splats smooth draws a single orthographic view with fixed_fast or fixed_simd: "
        "--fill, --sheet, --perspective, --eye, --path and other variants do not apply yet");
  }
  if (!options.list && !options.info && options.output.empty())
    throw cli::Error("no output given: use -o OUT.png");
}

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << octopoint::kRenderUsage;
      std::exit(0);
    } else if (args.is("--list") || args.is("--info")) {
      args.noValue();
      (args.is("--list") ? options.list : options.info) = true;
    } else if (parseModelSourceOption(args, options.source) ||
               parseFetchOption(args, options.fetch) ||
               parsePerspectiveOption(args, options.perspective) ||
               parseStyleOption(args, options.style)) {
      continue;
    } else if (parseViewOption(args, options.camera)) {
      options.orbit_camera = options.orbit_camera || !args.is("--size");
    } else if (args.is("--depth")) {
      const std::string text = args.value();
      if (text == "auto") {
        options.depth.reset();
      } else {
        options.depth = cli::parseInt(args.name(), text, 1, format::kMaxDepth);
      }
    } else if (args.is("--variant")) {
      const std::string name = args.value();
      const std::optional<Variant> variant = variantFromName(name);
      if (!variant)
        throw cli::Error("--variant: unknown variant " + cli::inQuotes(name) + " (see --list)");
      options.variant = *variant;
    } else if (args.is("--splats")) {
      const std::string name = args.value();
      const std::optional<SplatMode> mode = splatModeFromName(name);
      if (!mode) {
        throw cli::Error("--splats: unknown mode " + cli::inQuotes(name) + " (box or smooth)");
      }
      options.splats = *mode;
    } else if (args.is("--fill") || args.is("--no-fill")) {
      args.noValue();
      options.fill = args.is("--fill");
    } else if (args.is("--sheet")) {
      options.sheet = cli::parseInt(args.name(), args.value(), 1, 36);
    } else if (args.is("-o") || args.is("--output")) {
      options.output = args.value();
    } else if (args.is("--cells")) {
      options.cells = args.value();
      if (options.cells.empty()) throw cli::Error("--cells: empty (give a cell table)");
    } else if (args.is("--city")) {
      options.city = args.value();
      if (options.city.empty()) throw cli::Error("--city: empty (give a scene file)");
    } else {
      args.refuseUnknown();
    }
  }
  checkCombination(options);
  // The camera is known now: a perspective eye that cannot be placed is refused before any file is
  // read or checked.
  if (options.perspective.orbit) {
    static_cast<void>(orbitPerspectiveView(
        options.camera,
        options.perspective.fov.value_or(Angle::fromDegrees(kDefaultFieldOfViewDegrees))));
  }
  options.fetch.point_budget = options.source.point_budget;
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

// A chunked model fetched by URL in perspective: each view fetches what it needs and is drawn from
// what is held then, every region at the finest depth held there (tools/chunked_render.h).
int renderUrlPerspective(const Options& options) {
  // Before fetching, as renderUrl (a path's frames are checked by name when it draws them).
  if (options.perspective.path.empty()) cli::checkOutputFile(options.output);
  PerspectiveUrlSource source(options.source.url, options.fetch);
  const ModelView& model = source.headModel();
  PerspectiveJob job{&model,
                     options.source.url,
                     std::nullopt,
                     &model.finestLevel(),
                     options.camera,
                     options.output,
                     kBackground,
                     {},
                     0,
                     {options.fill, nullptr},
                     options.sheet};
  job.parts = [&source](const PerspectiveView& view) -> const HeldParts& {
    return source.follow(view);
  };
  job.point_budget = options.fetch.point_budget;
  runPerspective(options.perspective, job);
  std::printf("%s: %s\n", options.source.url.c_str(), source.report().c_str());
  return 0;
}

// A model fetched by URL, drawn at the depth the view needs.
int renderUrl(const Options& options) {
  if (options.perspective.any()) return renderUrlPerspective(options);
  cli::checkOutputFile(
      options.output);  // before fetching: a FIFO, a device or a directory is refused
  std::string report;
  const cv::Mat image =
      renderFromUrl(options.source.url, options.camera, options.variant, options.fill, kBackground,
                    options.fetch, &report, options.splats);
  writePng(options.output, image);
  std::printf("%s: %s -> %s (%dx%d)\n", options.source.url.c_str(), report.c_str(),
              options.output.c_str(), options.camera.width, options.camera.height);
  return 0;
}

// A chunked model file, drawn at the depth the view needs.
int renderChunked(const Options& options, LoadedModel& loaded) {
  cli::checkOutputFile(options.output);
  if (options.depth || options.sheet > 0) {
    throw cli::Error(loaded.label +
                     ": a chunked model is drawn at the depth the view needs: --depth and "
                     "--sheet do not apply");
  }
  ProgressiveDrawStats stats;
  loaded.chunked->setPointBudget(options.fetch.point_budget);
  writePng(options.output, renderChunkedView(*loaded.chunked, options.camera, options.variant,
                                             options.fill, kBackground, &stats, options.splats));
  std::printf("%s: chunked, depth %d, %llu points%s -> %s (%dx%d)\n", loaded.label.c_str(),
              stats.drawn_depth, static_cast<unsigned long long>(stats.points),
              overBudgetNote(stats).c_str(), options.output.c_str(), options.camera.width,
              options.camera.height);
  return 0;
}

// The level --depth names, or depth auto's for the camera.
const LevelView& chooseLevel(const ModelView& model, const std::string& model_label,
                             const Options& options) {
  const LevelView* level =
      options.depth ? model.levelOfDepth(*options.depth) : autoLevel(model, options.camera);
  if (level == nullptr && !options.depth) {
    throw cli::Error(std::string("camera refused: ") + describe(CameraError::kOverflow));
  }
  if (level == nullptr) {
    std::string depths;
    for (int i = 0; i < model.levelCount(); ++i) {
      depths += ' ';  // appended char by char: GCC 12 warns falsely (-Wrestrict) on " " + string
      depths += std::to_string(model.level(i).depth);
    }
    throw cli::Error("--depth: " + model_label + " has no depth " + std::to_string(*options.depth) +
                     " (it has" + depths + ")");
  }
  return *level;
}

// Sets the styler to `style`, refusing a style the model or the variant cannot draw.
void setStyle(FrameStyler& styler, const StyleOptions& style, const std::string& model_label,
              Variant variant) {
  if (const StyleError error = styler.setOptions(style); error != StyleError::kNone) {
    throw cli::Error("--style " + std::string(styleName(style.style)) + ": " + model_label + ": " +
                     describe(error));
  }
  if (styler.payload() == PixelPayload::kColourNormal && !drawsNormals(variant)) {
    std::string variant_name;
    for (const VariantInfo& info : allVariants()) {
      if (info.variant == variant) variant_name = info.name;
    }
    throw cli::Error("--style " + std::string(styleName(style.style)) + ": --variant " +
                     variant_name +
                     " draws colour only, not the normals this style needs (use another variant)");
  }
}

int renderSheet(const ModelView& model, const std::string& model_label, const Options& options,
                const StyleOptions& style) {
  const std::int64_t sheet_pixels = contactSheetPixels(model, options.camera, options.sheet);
  if (sheet_pixels > kMaxOutputPixels) {
    throw cli::Error("--sheet " + std::to_string(options.sheet) + " at --size " +
                     std::to_string(options.camera.width) + "x" +
                     std::to_string(options.camera.height) + " makes a " +
                     std::to_string(sheet_pixels) + "-pixel image, at most " +
                     std::to_string(kMaxOutputPixels) + ": give fewer views or a smaller --size");
  }
  try {
    writePng(options.output,
             renderContactSheet(model, options.camera, options.sheet, options.variant, style));
  } catch (const cv::Exception& error) {
    throw cli::Error(std::string("contact sheet: ") + error.what());
  } catch (const std::runtime_error& error) {
    throw cli::Error(std::string("contact sheet: ") + error.what());
  }
  std::printf("%s: contact sheet of %d views -> %s\n", model_label.c_str(), options.sheet,
              options.output.c_str());
  return 0;
}

// --splats smooth: the box frame, blended (octopoint/smooth.h), in the style, as RGB888.
void drawSmooth(Variant variant, const LevelView& level, const FrameSetup& setup,
                const ModelView& model, FrameStyler& styler, Framebuffer& frame,
                std::span<std::uint8_t> rgb) {
  SmoothSplats smooth(setup.width, setup.height, model);
  if (!renderSmooth(variant, level, setup, frame, smooth, paletteOf(model)))
    throw cli::Error(std::string("draw refused: ") + describe(checkRender(level, setup, frame)));
  styler.beginFrame(setup);
  if (const StyleError error = styler.resolve(frame, rgb, smooth.pixelBlend());
      error != StyleError::kNone) {
    throw cli::Error(std::string("style refused: ") + describe(error));
  }
}

int renderFrame(const ModelView& model, const LevelView& level, FrameStyler& styler,
                const std::string& model_label, const Options& options) {
  FrameSetup setup;
  const CameraError camera_error =
      buildFrameSetup(options.camera, level.depth, kDefaultFractionBits, &setup);
  if (camera_error != CameraError::kNone)
    throw cli::Error(std::string("camera refused: ") + describe(camera_error));

  Framebuffer frame(options.camera.width, options.camera.height);
  frame.clear(styler.payload());
  cv::Mat rgb(options.camera.height, options.camera.width, CV_8UC3);
  if (options.splats == SplatMode::kSmooth) {
    drawSmooth(options.variant, level, setup, model, styler, frame, {rgb.data, rgb.total() * 3});
  } else {
    if (!renderLevel(options.variant, level, setup, frame))
      throw cli::Error(std::string("draw refused: ") + describe(checkRender(level, setup, frame)));
    if (options.fill && HoleFiller(frame.width()).fill(frame, bridgeDepthLimit(setup)).refused)
      throw cli::Error("hole filling refused the frame");
    styler.beginFrame(setup);
    if (const StyleError error = styler.resolve(frame, {rgb.data, rgb.total() * 3});
        error != StyleError::kNone) {
      throw cli::Error(std::string("style refused: ") + describe(error));
    }
  }
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  writePng(options.output, bgr);
  const SplatFootprint& splat = drawsSplats(options.variant) ? setup.splat : SplatFootprint{};
  std::printf("%s: depth %d%s, %zu points, splat up to %dx%d px -> %s (%dx%d)\n",
              model_label.c_str(), level.depth, options.depth ? "" : " (auto)", level.leaves.size(),
              splat.columns, splat.rows, options.output.c_str(), options.camera.width,
              options.camera.height);
  return 0;
}

// `styler` (null: colour) draws --style.
int renderPerspectiveViews(const ModelView& model, const LevelView& level,
                           const std::string& model_label, const Options& options,
                           FrameStyler* styler = nullptr) {
  PerspectiveJob job{&model,
                     model_label,
                     options.depth,
                     &level,
                     options.camera,
                     options.output,
                     kBackground,
                     {},
                     0,
                     {options.fill, styler},
                     options.sheet};
  job.point_budget = options.fetch.point_budget;
  runPerspective(options.perspective, job);
  return 0;
}

// A chunked model file in perspective: its complete depths spliced back into one model (a
// complete file: the same model as prepared in one file), each part of the frame at the depth its
// distance asks for among them.
int renderChunkedPerspective(const Options& options, const LoadedModel& loaded) {
  const std::unique_ptr<AssembledModel> assembled = assembleChunked(*loaded.chunked);
  if (assembled == nullptr) throw cli::Error(loaded.label + ": its chunks do not make one model");
  const std::string label = loaded.label + " (chunked, depths " +
                            std::to_string(assembled->view->level(0).depth) + ".." +
                            std::to_string(assembled->view->finestLevel().depth) + " of " +
                            std::to_string(assembled->chunked_levels) + " levels)";
  const LevelView& level = chooseLevel(*assembled->view, label, options);
  // Drawn from its held parts, as a stream of it is: a whole file is one part, the assembled model
  // of its densely sampled depths. `--depth N` draws the assembled model's depth N, sparse or not.
  const HeldParts parts = assembleHeldParts(*loaded.chunked);
  PerspectiveJob job{assembled->view ? &*assembled->view : nullptr,
                     label,
                     options.depth,
                     &level,
                     options.camera,
                     options.output,
                     kBackground,
                     {},
                     0,
                     {options.fill, nullptr},
                     options.sheet};
  if (!options.depth)
    job.parts = [&parts](const PerspectiveView&) -> const HeldParts& { return parts; };
  job.point_budget = options.fetch.point_budget;
  runPerspective(options.perspective, job);
  return 0;
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  if (options.list) {
    listModels();
    return 0;
  }
  if (!options.city.empty()) {
    runCity(options.perspective,
            {options.city, options.cells, options.camera, options.output, kBackground});
    return 0;
  }
  if (!options.source.url.empty()) return renderUrl(options);
  const std::unique_ptr<LoadedModel> loaded =
      loadModel(options.source.model_name, options.source.model_file, true);
  if (options.info) {
    std::fputs(modelInfo(*loaded).c_str(), stdout);
    return 0;
  }
  if (loaded->chunked && options.style.style != Style::kColour) {
    throw cli::Error("--style " + std::string(styleName(options.style.style)) + ": " +
                     loaded->label +
                     ": a chunked model is drawn in colour only (it stores no normals)");
  }
  if (loaded->chunked && options.perspective.any())
    return renderChunkedPerspective(options, *loaded);
  if (loaded->chunked) return renderChunked(options, *loaded);
  if (options.fetch.point_budget > 0 && !options.perspective.any()) {
    throw cli::Error(loaded->label +
                     ": --point-budget applies to a chunked model (octopoint-prepare --chunked) "
                     "or a perspective view");
  }
  const ModelView& model = *loaded->view;
  const std::string& model_label = loaded->label;
  const LevelView& level = chooseLevel(model, model_label, options);
  FrameStyler styler(model);
  StyleOptions style = options.style;
  style.background = kBackground;
  setStyle(styler, style, model_label, options.variant);
  // The perspective views check their camera, then the output (tools/perspective_render.h).
  if (options.perspective.any()) {
    return renderPerspectiveViews(model, level, model_label, options,
                                  style.style != Style::kColour ? &styler : nullptr);
  }
  cli::checkOutputFile(
      options.output);  // before drawing: a FIFO, a device or a directory is refused
  if (options.sheet > 0) return renderSheet(model, model_label, options, style);
  return renderFrame(model, level, styler, model_label, options);
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-render", argc, argv, run);
}

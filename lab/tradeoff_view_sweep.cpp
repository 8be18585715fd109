// octopoint-tradeoff --sweep-views (docs/tradeoff.md): every frame size x zoom, today's renderer
// ("before": the finest depth of the 7,8 model, one pixel per voxel, hole filling off and on)
// against depth auto with footprint splats ("after"), box and smooth, measured against the
// surface reference.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/error.h"
#include "cli/output_file.h"
#include "cli/text.h"
#include "codegen/depth_range.h"
#include "lab/image_quality.h"
#include "lab/palette_ceiling.h"
#include "lab/tradeoff.h"
#include "lab/tradeoff_report.h"
#include "lab/voxel_cover.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"
#include "renderer/level_of_detail.h"

namespace octopoint::tradeoff {
namespace {

namespace fs = std::filesystem;

// Today's default model: depths 7 and 8, drawn at its finest.
const std::vector<int> kBeforeDepths = {7, 8};

// Draws one configuration's frames: everything a frame costs happens in draw() (clear, depth
// choice, camera set-up, decoding, filling), so that it can be timed.
class SweepDrawer {
 public:
  SweepDrawer(const ModelView& before, const ModelView& after)
      : before_(before), after_(after), after_palette_(paletteOf(after)) {}

  // Draws `config` for `camera` into `frame` (blending smooth splats in `smooth`, of the frame's
  // size); throws when the camera is refused.
  void draw(Config config, const Camera& camera, Framebuffer& frame, HoleFiller& filler,
            SmoothSplats& smooth) {
    frame.clear();
    const bool after = config == Config::kAfter || config == Config::kAfterSmooth;
    const LevelView* level = after ? autoLevel(after_, camera) : &before_.finestLevel();
    if (level == nullptr) throw cli::Error("depth auto: the camera is refused at every depth");
    // The after model's splats widened by the depth's stored sample reach, as octopoint-render
    // draws them (depth auto chose the depth counting that reach).
    const CameraError error =
        buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup_,
                        after ? after_.sampleReachOfDepth(level->depth) : kOneSampleReach);
    if (error != CameraError::kNone) throw cli::Error(std::string("camera: ") + describe(error));
    if (!after) setup_.splat = SplatFootprint{};  // one pixel per leaf, as before
    if (config == Config::kAfterSmooth) {
      if (!renderSmooth(variant_, *level, setup_, frame, smooth, after_palette_))
        throw cli::Error("smooth splats refused the frame");
      return;
    }
    if (!renderLevel(variant_, *level, setup_, frame))
      throw cli::Error(std::string("draw: ") + describe(checkRender(*level, setup_, frame)));
    if (config == Config::kBeforeFilled && filler.fill(frame, bridgeDepthLimit(setup_)).refused)
      throw cli::Error("hole filling refused the frame");
  }
  // Throws, naming the view, when draw() or exactCover() would refuse `camera` in some
  // configuration.
  void check(const Camera& camera) {
    for (Config config : {Config::kBefore, Config::kAfter}) {
      const LevelView* level =
          config == Config::kAfter ? autoLevel(after_, camera) : &before_.finestLevel();
      CameraError error = level == nullptr
                              ? CameraError::kOverflow
                              : buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup_,
                                                model(config).sampleReachOfDepth(level->depth));
      std::string what = configName(config);
      if (error == CameraError::kNone) {
        error = buildFrameSetup(coverCamera(camera), model(config).finestLevel().depth,
                                kDefaultFractionBits, &setup_);
        what += ", exact voxel cover";
      }
      if (error != CameraError::kNone) {
        throw cli::Error(std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                         " at zoom " + std::to_string(camera.zoom.raw() / 65536.0) + " (" + what +
                         "): " + describe(error));
      }
    }
  }
  // The camera exactCover() draws with: `camera` at voxelCoverFactor() times its size.
  static Camera coverCamera(Camera camera) {
    const int factor = voxelCoverFactor(camera.width, camera.height);
    camera.width *= factor;
    camera.height *= factor;
    return camera;
  }
  // The exact cover (lab/voxel_cover.h) of the finest level of `config`'s model (the after
  // model's finest dense depth) for `camera`, as an 8-bit BGR image of the camera's size.
  cv::Mat exactCover(Config config, const Camera& camera) {
    const ModelView& view = model(config);
    const Camera big = coverCamera(camera);
    FrameSetup setup;
    const CameraError error =
        buildFrameSetup(big, view.finestLevel().depth, kDefaultFractionBits, &setup);
    if (error != CameraError::kNone) throw cli::Error(std::string("camera: ") + describe(error));
    Framebuffer frame(big.width, big.height);
    if (!renderLevel(variant_, view.finestLevel(), setup, frame)) {
      throw cli::Error(std::string("draw: ") +
                       describe(checkRender(view.finestLevel(), setup, frame)));
    }
    return sampleAtPixelCentres(toImage(frame, view),
                                voxelCoverFactor(camera.width, camera.height));
  }
  // The last frame's set-up (its depth and splat).
  const FrameSetup& setup() const { return setup_; }
  const ModelView& model(Config config) const {
    return config == Config::kAfter || config == Config::kAfterSmooth ? after_ : before_;
  }
  // The last smooth frame's colours, BGR, kBackground where empty.
  cv::Mat smoothImage(const Framebuffer& frame, const SmoothSplats& smooth) const {
    cv::Mat rgb(frame.height(), frame.width(), CV_8UC3);
    // The image is made for the frame: resolveToRgb cannot refuse it.
    static_cast<void>(
        smooth.resolveToRgb(frame, after_palette_, kBackground, {rgb.data, rgb.total() * 3}));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    return bgr;
  }

 private:
  const ModelView& before_;
  const ModelView& after_;
  const PaletteRgb after_palette_;
  const Variant variant_ = defaultVariant();
  FrameSetup setup_;
};

constexpr Config kConfigs[] = {Config::kBefore, Config::kBeforeFilled, Config::kAfter,
                               Config::kAfterSmooth};
constexpr std::size_t kConfigCount = std::size(kConfigs);

// "6..8 (123,456 bytes)": a model's stored depths and its size.
std::string storedDepths(const InMemoryModel& model) {
  std::vector<int> depths;
  for (int i = 0; i < model.view->levelCount(); ++i) depths.push_back(model.view->level(i).depth);
  const std::string digits = std::to_string(model.bytes.size());
  std::string bytes;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) bytes += ',';
    bytes += digits[i];
  }
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + string.
  std::string text = prepare::describeDepths(depths);
  text += " (";
  text += bytes;
  text += " bytes)";
  return text;
}

Camera cameraOf(const ViewSweepOptions& options, const SweepCell& cell) {
  Camera camera = options.camera;
  camera.width = cell.width;
  camera.height = cell.height;
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(std::lround(cell.zoom * Q16::kOneRaw)));
  return camera;
}

// Reference | before with filling | after, side by side under a caption strip.
// Only the `region` of each (the whole frame, or its centre for a closer look at 1:1).
struct Panels {
  const char* captions[3];
};
constexpr Panels kBeforeAfter{
    {"reference (scan surface)", "before: depth 8 + hole filling", "after: depth auto, splats"}};
constexpr Panels kBoxSmooth{
    {"reference (scan surface)", "--splats box (depth auto)", "--splats smooth (depth auto)"}};
cv::Mat sideBySide(const Panels& panels_of, const cv::Mat& reference, const cv::Mat& before,
                   const cv::Mat& after, const cv::Rect& region) {
  constexpr int kCaption = 28, kGap = 6;
  const int w = region.width, h = region.height;
  cv::Mat out(h + kCaption, 3 * w + 2 * kGap, CV_8UC3, cv::Scalar(255, 255, 255));
  const char* const* captions = panels_of.captions;
  const cv::Mat* panels[] = {&reference, &before, &after};
  for (int k = 0; k < 3; ++k) {
    (*panels[k])(region).copyTo(out(cv::Rect(k * (w + kGap), kCaption, w, h)));
    // The captions shrink with narrow panels (about 260 pixels of text at scale 0.5).
    cv::putText(out, captions[k], {k * (w + kGap) + 4, kCaption - 8}, cv::FONT_HERSHEY_SIMPLEX,
                std::min(0.5, 0.5 * (w - 8) / 260.0), cv::Scalar(0, 0, 0));
  }
  return out;
}

// Where the after frame misses the silhouette (red) and covers what is not in it (blue); grey
// where both agree the object is, white where both agree it is not.
void markEmpty(const Reference& reference, const Framebuffer& frame, cv::Mat* marked) {
  *marked = cv::Mat(frame.height(), frame.width(), CV_8UC3, cv::Scalar(255, 255, 255));
  for (int y = 0; y < frame.height(); ++y) {
    for (int x = 0; x < frame.width(); ++x) {
      const bool object = reference.silhouette.at<std::uint8_t>(y, x) != 0,
                 drawn = frame.covered(x, y);
      if (object || drawn) {
        marked->at<cv::Vec3b>(y, x) = !drawn    ? cv::Vec3b(0, 0, 255)
                                      : !object ? cv::Vec3b(255, 128, 0)
                                                : cv::Vec3b(170, 170, 170);
      }
    }
  }
}

// A cell's pictures: WxH_zoomZ.png (reference | before with filling | after), _centre.png (the
// centre quarter of each at 1:1), _empty.png (markEmpty), _splats.png and _splats_centre.png
// (reference | box | smooth), each written whole.
void writePictures(const fs::path& directory, const SweepCell& cell, const cv::Mat& reference,
                   const cv::Mat (&frames)[kConfigCount], const cv::Mat& after_empty) {
  const int w = cell.width, h = cell.height;
  char stem[48];
  std::snprintf(stem, sizeof stem, "%dx%d_zoom%g", w, h, cell.zoom);
  const cv::Rect whole(0, 0, w, h), centre(w / 4, h / 4, std::max(1, w / 2), std::max(1, h / 2));
  const std::string base = stem;
  const auto sideBySidePng = [&](const std::string& suffix, const Panels& panels, std::size_t left,
                                 std::size_t right, const cv::Rect& region) {
    cli::writeFileAtomically(
        directory / (base + suffix + ".png"),
        encodePng(sideBySide(panels, reference, frames[left], frames[right], region)));
  };
  sideBySidePng("", kBeforeAfter, 1, 2, whole);
  sideBySidePng("_centre", kBeforeAfter, 1, 2, centre);
  cli::writeFileAtomically(directory / (base + "_empty.png"), encodePng(after_empty));
  sideBySidePng("_splats", kBoxSmooth, 2, 3, whole);
  sideBySidePng("_splats_centre", kBoxSmooth, 2, 3, centre);
}

// One cell's quality: a frame of each configuration against the reference, with each model's
// palette ceiling and exact cover; its pictures written when the options ask for them.
SweepCell measureCell(const Scene& scene, const ViewSweepOptions& options, SweepDrawer& drawer,
                      const std::vector<cv::Vec3b>& before_colours,
                      const std::vector<cv::Vec3b>& after_colours, SweepCell cell,
                      Framebuffer& frame, HoleFiller& filler, SmoothSplats& smooth,
                      const fs::path& pictures_dir) {
  const Camera camera = cameraOf(options, cell);
  const Reference reference = referenceFor(scene, camera);
  const double before_ceiling = paletteCeilingPsnr(reference.image, before_colours);
  const double after_ceiling = paletteCeilingPsnr(reference.image, after_colours);
  const cv::Mat before_cover = drawer.exactCover(Config::kBefore, camera);
  const cv::Mat after_cover = drawer.exactCover(Config::kAfter, camera);
  const double cover_psnr[] = {psnr(reference.image, before_cover),
                               psnr(reference.image, after_cover)};
  const double cover_ssim[] = {ssim(reference.image, before_cover),
                               ssim(reference.image, after_cover)};
  cv::Mat pictures[kConfigCount], after_empty;
  for (std::size_t k = 0; k < kConfigCount; ++k) {
    const Config config = kConfigs[k];
    drawer.draw(config, camera, frame, filler, smooth);
    const cv::Mat image = config == Config::kAfterSmooth ? drawer.smoothImage(frame, smooth)
                                                         : toImage(frame, drawer.model(config));
    const SplatFootprint& splat = drawer.setup().splat;
    const std::size_t m = config == Config::kAfter || config == Config::kAfterSmooth ? 1 : 0;
    cell.results.push_back({config, drawer.setup().depth, splat.columns, splat.rows, 0,
                            measure(reference, frame, image),
                            m == 1 ? after_ceiling : before_ceiling, cover_psnr[m], cover_ssim[m]});
    if (options.pictures) {
      pictures[k] = image;
      if (config == Config::kAfter) markEmpty(reference, frame, &after_empty);
    }
  }
  if (options.pictures) writePictures(pictures_dir, cell, reference.image, pictures, after_empty);
  return cell;
}

// Time: rounds over all cells, each a median over repeated frames; a cell's time is the median
// of its rounds, so that a burst of load on a shared machine spoils one round, not the figure.
void timeCells(SweepDrawer& drawer, const ViewSweepOptions& options,
               std::vector<SweepCell>& cells) {
  std::vector<std::vector<double>> round_ms(cells.size() * kConfigCount);
  for (int round = 0; round < options.rounds; ++round) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const Camera camera = cameraOf(options, cells[c]);
      Framebuffer frame(camera.width, camera.height);
      HoleFiller filler(camera.width);
      SmoothSplats smooth(camera.width, camera.height);
      for (std::size_t k = 0; k < kConfigCount; ++k) {
        round_ms[c * kConfigCount + k].push_back(medianMilliseconds(
            [&] { drawer.draw(kConfigs[k], camera, frame, filler, smooth); }, options.repeats));
      }
    }
    std::printf("%s timing round %d of %d done\n", options.label.c_str(), round + 1,
                options.rounds);
    std::fflush(stdout);
  }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (std::size_t k = 0; k < kConfigCount; ++k) {
      std::vector<double>& ms = round_ms[c * kConfigCount + k];
      std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2),
                       ms.end());
      cells[c].results[k].ms_per_frame = ms[ms.size() / 2];
    }
  }
}

}  // namespace

std::vector<std::string> viewSweepOutputNames() { return {"sweep.csv", "sweep.md"}; }

std::vector<cli::OutputFile> runViewSweep(const Scene& scene, const ViewSweepOptions& options,
                                          const fs::path& output) {
  const std::unique_ptr<InMemoryModel> before_model = prepareInMemory(scene, kBeforeDepths);
  // After: the model octopoint-prepare makes by default (depths 6..10 as far as the scan samples
  // them densely), drawn at depth auto.
  const std::unique_ptr<InMemoryModel> after_model =
      prepareInMemory(scene, prepare::defaultDepths(), /*dense_only=*/true);
  SweepDrawer drawer(*before_model->view, *after_model->view);
  // Every view is checked before anything is written: a refused one leaves no half-written sweep.
  for (const auto& [width, height] : options.sizes) {
    for (double zoom : options.zooms)
      drawer.check(cameraOf(options, SweepCell{width, height, zoom, {}}));
  }
  const fs::path pictures_dir = output / "pictures";
  if (options.pictures) {
    std::error_code error;
    fs::create_directories(pictures_dir, error);
    if (error)
      throw cli::Error(cli::displayPath(pictures_dir) + ": cannot create it: " + error.message());
  }

  // Quality: one frame of each configuration per cell against the reference, the best any frame
  // of each model could do (its palette ceiling) and what its finest voxels show exactly (their
  // exact cover).
  const std::vector<cv::Vec3b> before_colours = frameColours(*before_model->view, kBackground);
  const std::vector<cv::Vec3b> after_colours = frameColours(*after_model->view, kBackground);
  std::vector<SweepCell> cells;
  for (const auto& [width, height] : options.sizes) {
    Framebuffer frame(width, height);
    HoleFiller filler(width);
    SmoothSplats smooth(width, height);
    for (double zoom : options.zooms) {
      cells.push_back(measureCell(scene, options, drawer, before_colours, after_colours,
                                  SweepCell{width, height, zoom, {}}, frame, filler, smooth,
                                  pictures_dir));
    }
    std::printf("%s %dx%d measured\n", options.label.c_str(), width, height);
    std::fflush(stdout);
  }

  timeCells(drawer, options, cells);
  std::string models = "Before: depths ";
  models += storedDepths(*before_model);
  models += ", after: depths ";
  models += storedDepths(*after_model);
  models += ".";
  const std::vector<std::string> names = viewSweepOutputNames();
  return {{names[0], sweepCsv(options.label, cells)},
          {names[1], sweepMarkdown(options.label, models, cells)}};
}

}  // namespace octopoint::tradeoff

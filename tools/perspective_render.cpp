#include "tools/perspective_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <vector>

#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/real_numbers.h"
#include "cli/text.h"
#include "renderer/perspective_depth.h"
#include "renderer/perspective_renderer.h"
#include "tools/camera_path.h"
#include "tools/perspective_sheet.h"
#include "tools/png_file.h"

namespace octopoint {
namespace {

constexpr double kVideoFramesPerSecond = 25;

Angle degreesToAngle(double degrees) {
  return Angle::fromMilliDegrees(std::llround(degrees * 1000));
}

// The stored depth --depth named, or 0: each part of the frame at the depth its own distance asks
// for (detail by distance, renderer/perspective_renderer.h).
int depthToDraw(const PerspectiveJob& job) { return job.depth ? job.chosen_level->depth : 0; }

// The cube's placement, which an eye in the scan's units needs.
ScanCube requireCube(const PerspectiveJob& job, const char* option) {
  const std::optional<ScanCube> cube = scanCube(job.model->cubePlacement());
  if (!cube) {
    throw cli::Error(job.label + ": " + option +
                     " needs where the model's cube lies in the scan, which format version " +
                     std::to_string(job.model->formatVersion()) +
                     " does not record: prepare the scan again with octopoint-prepare");
  }
  return *cube;
}

// The frame of `view` from the job's model or parts (`held`, when the job has parts), each voxel
// fine enough up to `pixels_q8` on screen.
cv::Mat renderAt(const PerspectiveJob& job, const HeldParts* held, const PerspectiveView& view,
                 std::uint32_t pixels_q8, PerspectiveDrawStats* stats) {
  if (held != nullptr) {
    return renderPerspectiveParts(*held, depthToDraw(job), view, job.background, stats, pixels_q8,
                                  job.finish);
  }
  return renderPerspective(*job.model, depthToDraw(job), view, job.background, stats, pixels_q8,
                           job.finish);
}

// The voxel sizes on screen a point budget tries: one pixel, then up by 2^(1/4) a step (19,484 /
// 2^14, rounded), to 2^16 pixels, where every part is at the coarsest depth.
std::vector<std::uint32_t> budgetLadder() {
  std::vector<std::uint32_t> ladder{kOnePixelQ8};
  while (ladder.back() < (std::uint32_t{1} << 24)) {
    const std::uint64_t next = (std::uint64_t{ladder.back()} * 19'484 + 8'192) >> 14;
    ladder.push_back(static_cast<std::uint32_t>(std::min<std::uint64_t>(next, 1u << 24)));
  }
  return ladder;
}

// The frame of `view`: within the job's point budget, the first voxel size of the ladder at which
// it hands at most that many points to the plot (found by doubling the step, then halving the
// gap; fewer points at a larger size, so the same size every run). `pixels_q8` gets the size.
cv::Mat renderView(const PerspectiveJob& job, const PerspectiveView& view,
                   PerspectiveDrawStats* stats, std::uint32_t* pixels_q8 = nullptr) {
  const HeldParts* held = job.parts ? &job.parts(view) : nullptr;
  PerspectiveDrawStats drawn;
  cv::Mat image = renderAt(job, held, view, kOnePixelQ8, &drawn);
  std::uint32_t chosen = kOnePixelQ8;
  if (job.point_budget > 0 && drawn.leaves > job.point_budget) {
    static const std::vector<std::uint32_t> ladder = budgetLadder();
    const auto fits = [&](std::size_t step) {
      PerspectiveDrawStats probe;
      static_cast<void>(renderAt(job, held, view, ladder[step], &probe));
      return probe.leaves <= job.point_budget;
    };
    std::size_t over = 0, within = 1;  // ladder[over] draws too many
    while (within < ladder.size() - 1 && !fits(within)) {
      over = within;
      within = std::min(ladder.size() - 1, within * 2);
    }
    while (within - over > 1) {
      const std::size_t middle = over + (within - over) / 2;
      (fits(middle) ? within : over) = middle;
    }
    chosen = ladder[within];
    image = renderAt(job, held, view, chosen, &drawn);
  }
  if (stats != nullptr) *stats = drawn;
  if (pixels_q8 != nullptr) *pixels_q8 = chosen;
  return image;
}

std::string lookText(Angle yaw, Angle pitch, Angle roll) {
  return degreesText(yaw) + "," + degreesText(pitch) + "," + degreesText(roll);
}

// `pixels_q8`: the largest voxel size on screen the point budget chose (kOnePixelQ8: none).
std::string depthText(const PerspectiveJob& job, const PerspectiveDrawStats& stats,
                      std::uint32_t pixels_q8 = kOnePixelQ8) {
  std::string budget;
  if (job.point_budget > 0) {
    char size[32];
    std::snprintf(size, sizeof size, "%.2f", pixels_q8 / 256.0);
    budget = " (point budget " + std::to_string(job.point_budget) + ": voxels up to " + size +
             " pixels on screen)";
  }
  return (job.depth ? "depth " + std::to_string(job.chosen_level->depth)
                    : std::string("depth by distance (auto)")) +
         ", " + std::to_string(stats.leaves) + " points drawn" + budget;
}

// The camera of --eye, looking `look`.
PerspectiveView eyeView(const PerspectiveOptions& options, const PerspectiveJob& job,
                        const Look& look) {
  return scanEyeView(requireCube(job, "--eye"), *options.eye, look,
                     options.fov.value_or(Angle::fromDegrees(kDefaultFieldOfViewDegrees)),
                     modelNearPlane(*job.model, options.near, "--near"), job.camera.width,
                     job.camera.height, "--eye");
}

// The camera of --perspective, the orbit camera `camera` seen in perspective.
PerspectiveView orbitView(const PerspectiveOptions& options, const PerspectiveJob& job,
                          const Camera& camera) {
  return orbitPerspectiveView(camera,
                              options.fov.value_or(Angle::fromDegrees(kDefaultFieldOfViewDegrees)),
                              modelNearPlane(*job.model, options.near, "--near"));
}

void drawOrbit(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const PerspectiveView view = orbitView(options, job, job.camera);
  cli::checkOutputFile(job.output);
  PerspectiveDrawStats stats;
  std::uint32_t pixels_q8 = kOnePixelQ8;
  writePng(job.output, renderView(job, view, &stats, &pixels_q8));
  // Where the eye is in the scan, so that --eye can take the view from here.
  std::string eye;
  if (const std::optional<ScanCube> cube = scanCube(job.model->cubePlacement())) {
    eye = ", eye " + eyeText(*cube, view.camera.eye) + " looking " +
          lookText(view.camera.yaw, view.camera.pitch, view.camera.roll);
  }
  std::printf("%s: %s, perspective%s -> %s (%dx%d)\n", job.label.c_str(),
              depthText(job, stats, pixels_q8).c_str(), eye.c_str(), job.output.c_str(),
              job.camera.width, job.camera.height);
}

void drawEye(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const Look look = options.look.value_or(Look{});
  const PerspectiveView view = eyeView(options, job, look);
  cli::checkOutputFile(job.output);
  PerspectiveDrawStats stats;
  std::uint32_t pixels_q8 = kOnePixelQ8;
  writePng(job.output, renderView(job, view, &stats, &pixels_q8));
  std::printf("%s: %s, eye %s looking %s -> %s (%dx%d)\n", job.label.c_str(),
              depthText(job, stats, pixels_q8).c_str(), scanPointText(*options.eye).c_str(),
              lookText(look.yaw, look.pitch, look.roll).c_str(), job.output.c_str(),
              job.camera.width, job.camera.height);
}

// The files a path writes; all of them removed again unless the whole path was written.
class PathOutput {
 public:
  explicit PathOutput(std::string prefix) : prefix_(std::move(prefix)) {}
  PathOutput(const PathOutput&) = delete;
  PathOutput& operator=(const PathOutput&) = delete;
  ~PathOutput() {
    if (video_.isOpened()) video_.release();
    if (done_) return;
    std::error_code ignored;
    for (const std::string& file : written_) std::filesystem::remove(file, ignored);
    std::filesystem::remove(partialVideo(), ignored);
  }

  std::string frameName(int index) const {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%04d.png", index);
    return prefix_ + suffix;
  }
  std::string videoName() const { return prefix_ + ".avi"; }

  // The video where OpenCV's own Motion JPEG writer (which needs no codec library) works.
  void openVideo(int width, int height) {
    try {
      video_.open(partialVideo(), cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                  kVideoFramesPerSecond, cv::Size(width, height));
    } catch (const cv::Exception&) {
      video_.release();
    }
  }
  bool hasVideo() const { return video_.isOpened(); }

  void add(int index, const cv::Mat& image) {
    const std::string name = frameName(index);
    written_.push_back(name);  // before writing: a failed write leaves nothing either way
    writePng(name, image);
    if (video_.isOpened()) video_.write(image);
  }

  // Puts the video in place: the path is complete.
  void finish() {
    if (video_.isOpened()) {
      video_.release();
      written_.push_back(videoName());
      std::error_code error;
      std::filesystem::rename(partialVideo(), videoName(), error);
      if (error)
        throw cli::Error(cli::displayPath(videoName()) + ": cannot write: " + error.message());
    }
    done_ = true;
  }

 private:
  std::string partialVideo() const { return prefix_ + ".partial.avi"; }

  std::string prefix_;
  std::vector<std::string> written_;
  cv::VideoWriter video_;
  bool done_ = false;
};

// --collide: the path's eyes walked with collision from frame to frame; one line says how often
// something stopped the eye.
void collidePoses(const ModelView& model, const ScanCube& cube, const PerspectiveOptions& options,
                  std::vector<PathPose>& poses) {
  const WalkBody body = walkBodyOf(cube, options.collision);
  std::vector<ScanPoint> eyes;
  for (const PathPose& pose : poses) eyes.push_back(pose.eye);
  const CollidedEyes collided = collideEyes(model, cube, body, eyes, "--collide");
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i].eye = collided.eyes[i];
  std::printf("%s\n", collisionSummary(cube, body, collided.stopped, poses.size()).c_str());
}

// The cameras of `frames` evenly spaced times along `path` (with --collide, walked with collision).
std::vector<PerspectiveView> pathViews(const PerspectiveOptions& options, const PerspectiveJob& job,
                                       const CameraPath& path, int frames) {
  const ScanCube cube = requireCube(job, "--path");
  const Angle fov = options.fov        ? *options.fov
                    : path.fov_degrees ? degreesToAngle(*path.fov_degrees)
                                       : Angle::fromDegrees(kDefaultFieldOfViewDegrees);
  std::vector<PerspectiveView> views;
  std::vector<PathPose> poses = samplePath(path, frames);
  if (options.collision.collide) collidePoses(*job.model, cube, options, poses);
  const std::int64_t near = modelNearPlane(*job.model, options.near, "--near");
  for (std::size_t i = 0; i < poses.size(); ++i) {
    views.push_back(scanEyeView(
        cube, poses[i].eye, poses[i].look, fov, near, job.camera.width, job.camera.height,
        "--path " + cli::displayPath(options.path) + ": frame " + std::to_string(i) + " (eye " +
            scanPointText(poses[i].eye) + ")"));
  }
  return views;
}

void drawPath(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const CameraPath path = loadCameraPath(options.path);
  const std::int64_t pixels = std::int64_t{options.frames} * job.camera.width * job.camera.height;
  if (pixels > kMaxPathPixels) {
    throw cli::Error("--frames " + std::to_string(options.frames) + " at --size " +
                     std::to_string(job.camera.width) + "x" + std::to_string(job.camera.height) +
                     " makes " + std::to_string(pixels) + " pixels of PNGs, at most " +
                     std::to_string(kMaxPathPixels) + ": give fewer frames or a smaller --size");
  }
  // Every frame's camera first: a path that leaves what the camera holds is refused before any
  // file is written.
  const std::vector<PerspectiveView> views = pathViews(options, job, path, options.frames);
  std::string prefix = job.output;
  if (prefix.size() > 4 && prefix.ends_with(".png")) prefix.resize(prefix.size() - 4);
  PathOutput output(prefix);
  cli::checkOutputFile(output.frameName(0));
  cli::checkOutputFile(output.videoName());
  output.openVideo(job.camera.width, job.camera.height);
  PerspectiveDrawStats all;  // summed over the frames
  std::uint32_t largest_q8 = kOnePixelQ8;
  for (std::size_t i = 0; i < views.size(); ++i) {
    PerspectiveDrawStats stats;
    std::uint32_t pixels_q8 = kOnePixelQ8;
    output.add(static_cast<int>(i), renderView(job, views[i], &stats, &pixels_q8));
    all.leaves += stats.leaves;
    largest_q8 = std::max(largest_q8, pixels_q8);
  }
  const bool video = output.hasVideo();
  output.finish();
  std::printf("%s: %s, %d frames along %s -> %s .. %s%s%s (%dx%d)\n", job.label.c_str(),
              depthText(job, all, largest_q8).c_str(), options.frames,
              cli::displayPath(options.path).c_str(), output.frameName(0).c_str(),
              output.frameName(options.frames - 1).c_str(),
              video ? " and " : ", no video (OpenCV's Motion JPEG writer refused it)",
              video ? output.videoName().c_str() : "", job.camera.width, job.camera.height);
}

}  // namespace

bool parsePerspectiveOption(cli::ArgumentReader& args, PerspectiveOptions& options) {
  if (args.is("--perspective")) {
    args.noValue();
    options.orbit = true;
  } else if (args.is("--fov")) {
    options.fov = degreesToAngle(
        cli::parseReal(args.name(), args.value(), kMinFieldOfViewDegrees, kMaxFieldOfViewDegrees));
  } else if (args.is("--eye")) {
    options.eye = parseScanPoint(args.name(), args.value());
  } else if (args.is("--look")) {
    options.look = parseLook(args.name(), args.value());
  } else if (args.is("--path")) {
    options.path = args.value();
    if (options.path.empty()) throw cli::Error("--path: empty (give a value)");
  } else if (args.is("--frames")) {
    options.frames = cli::parseInt(args.name(), args.value(), 1, kMaxPathFrames);
  } else if (args.is("--near")) {
    // modelNearPlane checks it against the model's cube.
    options.near = cli::parseReal(args.name(), args.value(), 1e-12, kMaxEyeCoordinate);
  } else {
    return parseCollisionOption(args, options.collision);
  }
  return true;
}

void checkPerspectiveOptions(const PerspectiveOptions& options, const OtherOptions& other) {
  if (options.orbit + options.eye.has_value() + !options.path.empty() > 1)
    throw cli::Error("give one of --perspective, --eye and --path");
  if (options.fov && !options.any()) throw cli::Error("--fov needs --perspective, --eye or --path");
  if (options.look && !options.eye) throw cli::Error("--look needs --eye");
  if (options.frames > 0 && options.path.empty()) throw cli::Error("--frames needs --path");
  if (options.near && !options.any())
    throw cli::Error("--near needs --perspective, --eye or --path");
  if (!options.path.empty() && options.frames == 0 && !other.sheet) {
    throw cli::Error("--path needs --frames N (1.." + std::to_string(kMaxPathFrames) +
                     ") or --sheet N");
  }
  if (options.collision.any() && !options.collision.collide)
    throw cli::Error("--eye-radius and --eye-height need --collide");
  if (options.collision.collide && options.path.empty()) throw cli::Error("--collide needs --path");
  if (!options.any()) return;
  if (!options.orbit && other.orbit_camera) {
    throw cli::Error(std::string(options.mode()) +
                     " places the eye in the scan: --yaw, --pitch, --roll, --zoom and --pan do "
                     "not apply (turn it with --look or the path's keys)");
  }
  if (other.sheet && options.frames > 0)
    throw cli::Error("--sheet N draws N frames of the path: --frames does not apply");
}

PerspectiveView orbitPerspectiveView(const Camera& camera, Angle fov, std::int64_t near) {
  PerspectiveView view;
  if (const PerspectiveError error =
          orbitPerspective(camera, fov, kDefaultFractionBits, &view, near);
      error == PerspectiveError::kEyeTooFar) {
    throw cli::Error("--perspective: at this zoom and field of view the eye would be more than " +
                     std::to_string(kMaxEyeDistance) +
                     " cube edges from the model: zoom in or widen --fov");
  } else if (error != PerspectiveError::kNone) {
    throw cli::Error(std::string("--perspective: ") + describe(error));
  }
  return view;
}

namespace {

// Hole filling with the perspective bridge rule at `finest`, if asked.
void fillIfAsked(Framebuffer& frame, const PerspectiveView& view, const PerspectiveFinish& finish,
                 int finest) {
  if (finish.fill && HoleFiller(frame.width()).fill(frame, perspectiveBridge(view, finest)).refused)
    throw cli::Error("hole filling refused the frame");
}

cv::Mat frameToBgr(const Framebuffer& frame, const ModelView& model, const PerspectiveView& view,
                   Rgb background, const PerspectiveFinish& finish) {
  cv::Mat rgb(view.camera.height, view.camera.width, CV_8UC3);
  // The frame is sized to the camera: neither resolveToRgb nor the styler can refuse it.
  if (finish.styler != nullptr) {
    finish.styler->beginPerspectiveFrame(view.world_to_camera, view.focal_q16);
    static_cast<void>(finish.styler->resolve(frame, {rgb.data, rgb.total() * 3}));
  } else {
    static_cast<void>(resolveToRgb(frame, model, background, {rgb.data, rgb.total() * 3}));
  }
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace

cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats, std::uint32_t pixels_q8,
                          const PerspectiveFinish& finish) {
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear(finish.styler != nullptr ? finish.styler->payload() : PixelPayload::kColour);
  PerspectiveRenderer renderer(model);
  PerspectiveRenderer::Options options;
  options.depth = depth;
  options.pixels_q8 = pixels_q8;
  // No abort flag: it completes; `depth` is a stored one (the caller chose it from the model),
  // and a frame for normals is asked only of a model that has them (FrameStyler::setOptions).
  // The renderer adds to the counts it is given: these are this frame's.
  PerspectiveDrawStats drawn;
  static_cast<void>(renderer.draw(view, options, frame, &drawn));
  if (stats != nullptr) *stats = drawn;
  fillIfAsked(frame, view, finish, depth != 0 ? depth : renderer.detailDepths().back());
  return frameToBgr(frame, model, view, background, finish);
}

cv::Mat renderPerspectiveParts(const HeldParts& parts, int depth, const PerspectiveView& view,
                               Rgb background, PerspectiveDrawStats* stats, std::uint32_t pixels_q8,
                               const PerspectiveFinish& finish) {
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  PerspectiveDrawStats all;
  for (const std::unique_ptr<AssembledModel>& part : parts.parts) {
    PerspectiveRenderer renderer(*part->view, parts.detailDepths());
    PerspectiveRenderer::Options options;
    options.depth = depth;
    options.pixels_q8 = pixels_q8;
    PerspectiveDrawStats drawn;
    // A part that does not hold `depth` draws nothing (false): the others do.
    if (renderer.draw(view, options, frame, &drawn)) {
      all.leaves += drawn.leaves;
      all.hidden_subtrees += drawn.hidden_subtrees;
    }
  }
  if (stats != nullptr) *stats = all;
  fillIfAsked(frame, view, {finish.fill, nullptr},
              depth != 0 ? depth : parts.detailDepths().back());
  // Every part has the head's palette; no part has normals.
  return frameToBgr(frame, *parts.parts.front()->view, view, background, {});
}

cv::Mat renderPerspectiveView(const PerspectiveJob& job, const PerspectiveView& view,
                              PerspectiveDrawStats* stats) {
  return renderView(job, view, stats);
}

std::vector<PerspectiveView> sheetViews(const PerspectiveOptions& options,
                                        const PerspectiveJob& job, int count) {
  if (!options.path.empty()) return pathViews(options, job, loadCameraPath(options.path), count);
  std::vector<PerspectiveView> views;
  for (int column = 0; column < count; ++column) {
    const Angle turn = Angle::fromTurns16(std::int64_t{column} * Angle::kUnitsPerTurn / count);
    if (options.orbit) {
      Camera camera = job.camera;
      camera.yaw = camera.yaw + turn;
      views.push_back(orbitView(options, job, camera));
    } else {
      Look look = options.look.value_or(Look{});
      look.yaw = look.yaw + turn;
      views.push_back(eyeView(options, job, look));
    }
  }
  return views;
}

void runPerspective(const PerspectiveOptions& options, const PerspectiveJob& job) {
  if (job.sheet > 0) {
    drawPerspectiveSheet(job, sheetViews(options, job, job.sheet));
  } else if (options.orbit) {
    drawOrbit(options, job);
  } else if (options.eye) {
    drawEye(options, job);
  } else {
    drawPath(options, job);
  }
}

}  // namespace octopoint

#include "tools/perspective_render.h"

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
#include "renderer/perspective_renderer.h"
#include "tools/camera_path.h"
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

std::string lookText(Angle yaw, Angle pitch, Angle roll) {
  return degreesText(yaw) + "," + degreesText(pitch) + "," + degreesText(roll);
}

std::string depthText(const PerspectiveJob& job, const PerspectiveDrawStats& stats) {
  return (job.depth ? "depth " + std::to_string(job.chosen_level->depth)
                    : std::string("depth by distance (auto)")) +
         ", " + std::to_string(stats.leaves) + " points drawn";
}

void drawOrbit(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const PerspectiveView view = orbitPerspectiveView(
      job.camera, options.fov.value_or(Angle::fromDegrees(kDefaultFieldOfViewDegrees)),
      modelNearPlane(*job.model, options.near, "--near"));
  cli::checkOutputFile(job.output);
  PerspectiveDrawStats stats;
  writePng(job.output,
           renderPerspective(*job.model, depthToDraw(job), view, job.background, &stats));
  // Where the eye is in the scan, so that --eye can take the view from here.
  std::string eye;
  if (const std::optional<ScanCube> cube = scanCube(job.model->cubePlacement())) {
    eye = ", eye " + scanPointText(scanPointOf(*cube, view.camera.eye)) + " looking " +
          lookText(view.camera.yaw, view.camera.pitch, view.camera.roll);
  }
  std::printf("%s: %s, perspective%s -> %s (%dx%d)\n", job.label.c_str(),
              depthText(job, stats).c_str(), eye.c_str(), job.output.c_str(), job.camera.width,
              job.camera.height);
}

void drawEye(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const ScanCube cube = requireCube(job, "--eye");
  const Look look = options.look.value_or(Look{});
  const PerspectiveView view =
      scanEyeView(cube, *options.eye, look,
                  options.fov.value_or(Angle::fromDegrees(kDefaultFieldOfViewDegrees)),
                  modelNearPlane(*job.model, options.near, "--near"), job.camera.width,
                  job.camera.height, "--eye");
  cli::checkOutputFile(job.output);
  PerspectiveDrawStats stats;
  writePng(job.output,
           renderPerspective(*job.model, depthToDraw(job), view, job.background, &stats));
  std::printf("%s: %s, eye %s looking %s -> %s (%dx%d)\n", job.label.c_str(),
              depthText(job, stats).c_str(), scanPointText(*options.eye).c_str(),
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

void drawPath(const PerspectiveOptions& options, const PerspectiveJob& job) {
  const ScanCube cube = requireCube(job, "--path");
  const CameraPath path = loadCameraPath(options.path);
  const std::int64_t pixels = std::int64_t{options.frames} * job.camera.width * job.camera.height;
  if (pixels > kMaxPathPixels) {
    throw cli::Error("--frames " + std::to_string(options.frames) + " at --size " +
                     std::to_string(job.camera.width) + "x" + std::to_string(job.camera.height) +
                     " makes " + std::to_string(pixels) + " pixels of PNGs, at most " +
                     std::to_string(kMaxPathPixels) + ": give fewer frames or a smaller --size");
  }
  const Angle fov = options.fov        ? *options.fov
                    : path.fov_degrees ? degreesToAngle(*path.fov_degrees)
                                       : Angle::fromDegrees(kDefaultFieldOfViewDegrees);
  // Every frame's camera first: a path that leaves what the camera holds is refused before any
  // file is written.
  std::vector<PerspectiveView> views;
  const std::vector<PathPose> poses = samplePath(path, options.frames);
  const std::int64_t near = modelNearPlane(*job.model, options.near, "--near");
  for (std::size_t i = 0; i < poses.size(); ++i) {
    views.push_back(scanEyeView(
        cube, poses[i].eye, poses[i].look, fov, near, job.camera.width, job.camera.height,
        "--path " + cli::displayPath(options.path) + ": frame " + std::to_string(i) + " (eye " +
            scanPointText(poses[i].eye) + ")"));
  }
  std::string prefix = job.output;
  if (prefix.size() > 4 && prefix.ends_with(".png")) prefix.resize(prefix.size() - 4);
  PathOutput output(prefix);
  cli::checkOutputFile(output.frameName(0));
  cli::checkOutputFile(output.videoName());
  output.openVideo(job.camera.width, job.camera.height);
  PerspectiveDrawStats all;  // summed over the frames
  for (std::size_t i = 0; i < views.size(); ++i) {
    PerspectiveDrawStats stats;
    output.add(static_cast<int>(i),
               renderPerspective(*job.model, depthToDraw(job), views[i], job.background, &stats));
    all.leaves += stats.leaves;
  }
  const bool video = output.hasVideo();
  output.finish();
  std::printf("%s: %s, %d frames along %s -> %s .. %s%s%s (%dx%d)\n", job.label.c_str(),
              depthText(job, all).c_str(), options.frames, cli::displayPath(options.path).c_str(),
              output.frameName(0).c_str(), output.frameName(options.frames - 1).c_str(),
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
    return false;
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
  if (!options.path.empty() && options.frames == 0)
    throw cli::Error("--path needs --frames N (1.." + std::to_string(kMaxPathFrames) + ")");
  if (!options.any()) return;
  if (!options.orbit && other.orbit_camera) {
    throw cli::Error(std::string(options.mode()) +
                     " places the eye in the scan: --yaw, --pitch, --roll, --zoom and --pan do "
                     "not apply (turn it with --look or the path's keys)");
  }
  if (other.url || other.fill || other.sheet || other.style) {
    throw cli::Error(std::string(options.mode()) +
                     " draws a model file or an embedded model in colour: --url, --fill, --sheet "
                     "and --style do not apply yet");
  }
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

cv::Mat renderPerspective(const ModelView& model, int depth, const PerspectiveView& view,
                          Rgb background, PerspectiveDrawStats* stats) {
  Framebuffer frame(view.camera.width, view.camera.height);
  frame.clear();
  PerspectiveRenderer renderer(model);
  PerspectiveRenderer::Options options;
  options.depth = depth;
  // No abort flag: it completes; `depth` is a stored one (the caller chose it from the model).
  static_cast<void>(renderer.draw(view, options, frame, stats));
  cv::Mat rgb(view.camera.height, view.camera.width, CV_8UC3);
  // The frame is sized to the camera: resolveToRgb cannot refuse it.
  static_cast<void>(resolveToRgb(frame, model, background, {rgb.data, rgb.total() * 3}));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

void runPerspective(const PerspectiveOptions& options, const PerspectiveJob& job) {
  if (options.orbit) {
    drawOrbit(options, job);
  } else if (options.eye) {
    drawEye(options, job);
  } else {
    drawPath(options, job);
  }
}

}  // namespace octopoint

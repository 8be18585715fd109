// libFuzzer harness for the model reader, validator and decoders: any bytes go through
// ModelView::fromBytes, exactly as octopoint-render --file does with a `.oct` file; a model that
// validates is drawn at every level with a few cameras by every variant. ASan and UBSan catch a
// read past the buffers or an overflow; the checks below catch a decoder that walks a different
// tree than the validator (leaf count), fixed-point variants that disagree with each other (those
// that draw footprint splats among themselves, and every fixed variant at one pixel per leaf), and
// a frame reused from the previous input that holds anything but what a fresh frame holds (its
// clear empties only the rectangle drawn, octopoint/framebuffer.h).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "renderer/decode_baseline.h"

namespace {

using namespace octopoint;

// Small frames keep each execution fast; the cameras cover the identity, turns on every axis,
// zoom in and out, a pan that puts most of the model off screen, and a 1 x 1 viewport.
Camera camera(int yaw_degrees, int pitch_degrees, int roll_degrees, std::int32_t zoom_q16,
              std::int32_t pan_px, std::int32_t width, std::int32_t height) {
  Camera result;
  result.yaw = Angle::fromMilliDegrees(yaw_degrees * 1000);
  result.pitch = Angle::fromMilliDegrees(pitch_degrees * 1000);
  result.roll = Angle::fromMilliDegrees(roll_degrees * 1000);
  result.zoom = Q16::fromRaw(zoom_q16);
  result.pan_x_px = pan_px;
  result.pan_y_px = -pan_px;
  result.width = width;
  result.height = height;
  return result;
}

const std::array kCameras = {
    camera(0, 0, 0, 1 << 16, 0, 48, 32),    camera(30, -20, 10, 3 << 15, 0, 40, 40),
    camera(180, 90, 0, 1 << 14, 5, 33, 17), camera(-45, 45, 135, 5 << 16, 30, 64, 48),
    camera(0, 0, 0, 1 << 16, 0, 1, 1),
};

struct LeafCounter {
  std::size_t count = 0;
  void operator()(std::int32_t, std::int32_t, std::int32_t, std::uint8_t) { ++count; }
};

void check(bool condition) {
  if (!condition) std::abort();
}

// A level this large (a real scan's) is drawn with the first camera only: the mutants of the
// default model in the seed corpus would otherwise cost most of the run.
constexpr std::size_t kLeavesForAllCameras = 4096;

void drawEveryWay(const LevelView& level) {
  const std::size_t cameras = level.leaves.size() > kLeavesForAllCameras ? 1 : kCameras.size();
  for (std::size_t c = 0; c < cameras; ++c) {
    const Camera& cam = kCameras[c];
    FrameSetup setup;
    if (buildFrameSetup(cam, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
      continue;
    LeafCounter counter;
    BaselineWalk<LeafCounter> walk(level, setup, counter);
    check(walk.run());
    check(counter.count == level.leaves.size());

    FrameSetup one_pixel = setup;
    one_pixel.splat = SplatFootprint{};
    const auto same = [](const FrameView& a, const FrameView& b) {
      return std::ranges::equal(a.pixels(), b.pixels());
    };
    // The first frame of each kind: one pixel per leaf, and with the set-up's splats.
    std::optional<Framebuffer> first_one_pixel, first_splatted;
    const auto compare = [&](std::optional<Framebuffer>& first, Framebuffer&& frame) {
      if (first) {
        check(same(frame, *first));
      } else {
        first.emplace(std::move(frame));
      }
    };
    for (const VariantInfo& info : allVariants()) {
      Framebuffer frame(cam.width, cam.height);
      check(renderLevel(info.variant, level, setup, frame));
      if (!isFixedPoint(info.variant)) continue;  // float references are only close
      compare(drawsSplats(info.variant) ? first_splatted : first_one_pixel, std::move(frame));
      if (!drawsSplats(info.variant)) continue;
      Framebuffer one(cam.width, cam.height);
      check(renderLevel(info.variant, level, one_pixel, one));
      compare(first_one_pixel, std::move(one));
    }
    // The same frame drawn into one kept from the previous inputs, cleared.
    static std::array<std::optional<Framebuffer>, kCameras.size()> kept;
    if (!kept[c]) kept[c].emplace(cam.width, cam.height);
    kept[c]->clear();
    check(renderLevel(defaultVariant(), level, setup, *kept[c]));
    check(same(*kept[c], drawsSplats(defaultVariant()) ? *first_splatted : *first_one_pixel));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromBytes(std::span(data, size), &issue);
  check(model.has_value() == (issue.error == ModelError::kNone));
  if (!model) return 0;
  for (int i = 0; i < model->levelCount(); ++i) drawEveryWay(model->level(i));
  return 0;
}

// line_pass_timing: the line pass of the line styles (octopoint/styles.h, docs/styles.md) in
// integer arithmetic against the same pass written in float, as Hekmatzada et al. compared their
// fixed and float line drawings on a PDA without FPU. Built for the `armel` preset it runs under
// qemu-arm, an ARMv5TE without FPU, where every float operation is a libgcc soft-float call
// (docs/device.md).
//
// The float pass is a reference written as a float program would be: each pixel's depth in
// float (the depth key times its unit), the silhouette jump in float, each normal's slope slack
// from its float normal turned by the float rotation, and the crease test as the dot product of
// the two pixels' unit normals (floats) against cos(crease angle). The integer pass is
// FrameStyler's: keys compared as integers, the slack and the crease tables built once per frame
// and per model.
// Both paint the lines style (white paper, black silhouettes, grey creases) into RGB888 and the
// tool prints how many pixels differ (the crease test's rounding at the threshold may differ).
// This file is a float reference by design: it is not part of the integer libraries.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <optional>
#include <vector>

#include "octopoint/fixed.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"

namespace octopoint {
namespace {

constexpr int kRuns = 5;  // the reported time is the median over runs
constexpr std::int64_t kRunNs = 200'000'000;

std::int64_t threadCpuNs() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

template <typename Pass>
std::int64_t medianNs(Pass pass) {
  pass();  // warm-up: caches, page faults, qemu's translation
  std::array<std::int64_t, kRuns> per_pass{};
  for (std::int64_t& result : per_pass) {
    const std::int64_t start = threadCpuNs();
    std::int64_t passes = 0;
    do {
      pass();
      ++passes;
    } while (threadCpuNs() - start < kRunNs / kRuns);
    result = (threadCpuNs() - start) / passes;
  }
  std::sort(per_pass.begin(), per_pass.end());
  return per_pass[kRuns / 2];
}

struct FloatNormal {
  float x, y, z;
};

// The float line pass over a kColourNormal frame: what octopoint/styles.h computes, in float.
struct FloatLinePass {
  std::vector<FloatNormal> normals;  // unit vectors
  std::vector<float> slack;          // per normal: how far its surface recedes beyond the jump
  float depth_unit = 1.0f;           // a key step, in the float depth's unit
  float jump = 0.0f;                 // the silhouette jump, in the same unit
  float cos_crease = 0.5f;

  // SurfaceSlopes (octopoint/styles.h) in float: (|v_x| reach_x + |v_y| reach_y + (1 - |v_z|) e)
  // / |v_z| pixels of depth for the normal v in view axes, capped.
  void buildSlack(const float (&rotation)[3][3], float reach_x, float reach_y, float edge,
                  float pixel) {
    const float most = static_cast<float>(kMaxSurfaceSlope) * (std::max(reach_x, reach_y) + edge);
    slack.clear();
    for (const FloatNormal& n : normals) {
      float v[3];
      for (int row = 0; row < 3; ++row)
        v[row] =
            std::fabs(rotation[row][0] * n.x + rotation[row][1] * n.y + rotation[row][2] * n.z);
      const float rise = v[0] * reach_x + v[1] * reach_y + (1.0f - std::min(v[2], 1.0f)) * edge;
      slack.push_back((rise >= most * v[2] ? most : rise / v[2]) * pixel);
    }
  }

  float depthOf(std::uint32_t word) const { return static_cast<float>(word >> 16) * depth_unit; }
  bool crease(std::uint32_t a, std::uint32_t b) const {
    const FloatNormal& n = normals[Framebuffer::normalIndexOf(a)];
    const FloatNormal& m = normals[Framebuffer::normalIndexOf(b)];
    return std::fabs(n.x * m.x + n.y * m.y + n.z * m.z) < cos_crease;
  }

  // Whether covered pixel (x, y) has a neighbour that is background or farther than the jump.
  bool silhouette(const FrameView& frame, std::int32_t x, std::int32_t y) const {
    const std::uint32_t word = frame.pixelAt(x, y);
    const float farthest = depthOf(word) + jump;
    const auto outlines = [&](std::int32_t qx, std::int32_t qy) {
      const std::uint32_t q = frame.pixelAt(qx, qy);
      if (q == Framebuffer::kEmpty) return true;
      const float allowed =
          std::min(slack[Framebuffer::normalIndexOf(word)], slack[Framebuffer::normalIndexOf(q)]);
      return depthOf(q) > farthest + allowed;
    };
    return (x > 0 && outlines(x - 1, y)) || (x + 1 < frame.width() && outlines(x + 1, y)) ||
           (y > 0 && outlines(x, y - 1)) || (y + 1 < frame.height() && outlines(x, y + 1));
  }

  Edge classify(const FrameView& frame, std::int32_t x, std::int32_t y) const {
    if (silhouette(frame, x, y)) return Edge::kSilhouette;
    const std::uint32_t word = frame.pixelAt(x, y);
    const float depth = depthOf(word);
    const auto creaseWith = [&](std::int32_t qx, std::int32_t qy, bool p_draws_ties) {
      const std::uint32_t q = frame.pixelAt(qx, qy);
      const float other = depthOf(q);
      return (other > depth || (other == depth && p_draws_ties)) &&
             Framebuffer::normalIndexOf(word) != Framebuffer::normalIndexOf(q) && crease(word, q) &&
             !silhouette(frame, qx, qy);
    };
    const bool is_crease = (x > 0 && creaseWith(x - 1, y, false)) ||
                           (x + 1 < frame.width() && creaseWith(x + 1, y, true)) ||
                           (y > 0 && creaseWith(x, y - 1, false)) ||
                           (y + 1 < frame.height() && creaseWith(x, y + 1, true));
    return is_crease ? Edge::kCrease : Edge::kNone;
  }

  void run(const FrameView& frame, std::uint8_t* rgb) const {
    for (std::int32_t y = 0; y < frame.height(); ++y) {
      for (std::int32_t x = 0; x < frame.width(); ++x, rgb += 3) {
        const Edge edge =
            frame.pixelAt(x, y) == Framebuffer::kEmpty ? Edge::kNone : classify(frame, x, y);
        const std::uint8_t grey = edge == Edge::kSilhouette ? 0x00
                                  : edge == Edge::kCrease   ? 0x80
                                                            : 0xFF;
        rgb[0] = rgb[1] = rgb[2] = grey;
      }
    }
  }
};

int run() {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!model || !model->hasNormals()) {
    std::fprintf(stderr, "line_pass_timing: the default model is invalid or has no normals\n");
    return 1;
  }
  Camera camera;  // 320x240
  camera.yaw = Angle::fromDegrees(30);
  const LevelView& level = model->finestLevel();
  FrameSetup setup;
  if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup) != CameraError::kNone) {
    std::fprintf(stderr, "line_pass_timing: camera refused\n");
    return 1;
  }
  FrameStyler styler(*model);
  StyleOptions options;
  options.style = Style::kLines;
  if (styler.setOptions(options) != StyleError::kNone) return 1;
  Framebuffer frame(camera.width, camera.height);
  frame.clear(styler.payload());
  if (!renderLevel(defaultVariant(), level, setup, frame)) return 1;
  styler.beginFrame(setup);

  FloatLinePass float_pass;
  for (int i = 0; i < model->normalCount(); ++i) {
    const NormalQ14 n = model->normal(i);
    const float one = 1.0f / 16384.0f;  // Q1.14
    float_pass.normals.push_back({n.x * one, n.y * one, n.z * one});
  }
  const EdgeRule rule = edgeRuleFor(setup, PixelPayload::kColourNormal, nullptr, nullptr);
  float_pass.depth_unit =
      1.0f / 256.0f;  // any unit: the float pass's depths are float multiples of it
  float_pass.jump = static_cast<float>(rule.jump) * float_pass.depth_unit;
  {
    const Rotation rotation = rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll);
    float turn[3][3];
    for (std::size_t row = 0; row < 3; ++row) {
      for (std::size_t col = 0; col < 3; ++col)
        turn[row][col] = static_cast<float>(rotation.m_q30[row][col]) / 1073741824.0f;
    }
    const float one_pixel = static_cast<float>(1 << setup.fraction_bits);
    // A pixel of depth in the float depth's unit: 2^(F - depth_shift) key units, the word's key
    // the top 16 of its 24 bits.
    const float pixel = static_cast<float>((1 << setup.fraction_bits) >> setup.depth_shift) /
                        256.0f * float_pass.depth_unit;
    float_pass.buildSlack(turn, static_cast<float>(setup.splat.columns + 1),
                          static_cast<float>(setup.splat.rows + 1),
                          static_cast<float>(voxelEdgeOnScreen(setup)) / one_pixel, pixel);
  }
  float_pass.cos_crease =
      std::cos(static_cast<float>(kDefaultCreaseDegrees) * 3.14159265f / 180.0f);

  const std::size_t bytes =
      static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height) * 3;
  std::vector<std::uint8_t> fixed_rgb(bytes), float_rgb(bytes);
  if (styler.resolve(frame, fixed_rgb) != StyleError::kNone) return 1;
  // Timed after the check above: the same frame and buffer cannot be refused the next times.
  const std::int64_t fixed_ns =
      medianNs([&] { static_cast<void>(styler.resolve(frame, fixed_rgb)); });
  const std::int64_t float_ns = medianNs([&] { float_pass.run(frame, float_rgb.data()); });
  std::size_t differing = 0;
  for (std::size_t i = 0; i < bytes; i += 3) differing += fixed_rgb[i] != float_rgb[i] ? 1 : 0;
  const double pixels = static_cast<double>(camera.width) * camera.height;
  std::printf("line pass, default model depth %d, 320x240, yaw 30 (CPU time, median of %d runs)\n",
              level.depth, kRuns);
  std::printf("  integer: %.1f us (%.1f ns per pixel)\n", fixed_ns / 1e3, fixed_ns / pixels);
  std::printf("  float:   %.1f us (%.1f ns per pixel)\n", float_ns / 1e3, float_ns / pixels);
  std::printf("  float / integer: %.2fx; pixels that differ: %zu of %.0f\n",
              static_cast<double>(float_ns) / fixed_ns, differing, pixels);
  return 0;
}

}  // namespace
}  // namespace octopoint

int main() { return octopoint::run(); }

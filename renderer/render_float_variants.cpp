// The floating point reference variants (docs/design.md section 4): the same algorithms as the
// fixed ones (renderer/decode_algorithms.h), with positions, rotation and displacement vectors in
// single precision computed from the camera, as an FPU-equipped port of the paper's renderer would.
// This file is the only place in renderer/ that uses floating point at run time; the device build
// checks that nothing else does.
#include <algorithm>
#include <cmath>

#include "octopoint/render.h"
#include "renderer/decode_algorithms.h"

namespace octopoint {
namespace {

struct FloatFrame {
  Point3<float> root;
  OffsetTable<float> offsets;
};

using Matrix3 = std::array<std::array<float, 3>, 3>;

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 m{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
  return m;
}

// The same frame as buildFrameSetup, in single precision: R = Rz(roll) Rx(pitch) Ry(yaw).
FloatFrame floatFrameFrom(const FrameSetup& setup) {
  const Camera& camera = setup.camera;
  constexpr float kRadiansPerUnit = 6.28318530718f / 65536.0f;
  const float yaw = static_cast<float>(camera.yaw.turns16()) * kRadiansPerUnit;
  const float pitch = static_cast<float>(camera.pitch.turns16()) * kRadiansPerUnit;
  const float roll = static_cast<float>(camera.roll.turns16()) * kRadiansPerUnit;
  const Matrix3 ry = {
      {{std::cos(yaw), 0, std::sin(yaw)}, {0, 1, 0}, {-std::sin(yaw), 0, std::cos(yaw)}}};
  const Matrix3 rx = {
      {{1, 0, 0}, {0, std::cos(pitch), -std::sin(pitch)}, {0, std::sin(pitch), std::cos(pitch)}}};
  const Matrix3 rz = {
      {{std::cos(roll), -std::sin(roll), 0}, {std::sin(roll), std::cos(roll), 0}, {0, 0, 1}}};
  const Matrix3 r = multiply(rz, multiply(rx, ry));
  const float edge_px = static_cast<float>(camera.zoom.raw()) / 65536.0f *
                        static_cast<float>(std::min(camera.width, camera.height));

  FloatFrame frame{};
  frame.root = {static_cast<float>(camera.width) / 2 + static_cast<float>(camera.pan_x_px),
                static_cast<float>(camera.height) / 2 + static_cast<float>(camera.pan_y_px), 0};
  for (int level = 0; level < setup.depth; ++level) {
    const float half_child_px = edge_px / std::ldexp(1.0f, level + 2);
    for (std::size_t k = 0; k < 8; ++k) {
      const float sign[3] = {k & 4 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 1 ? 1.0f : -1.0f};
      float v[3];
      for (std::size_t axis = 0; axis < 3; ++axis) {
        v[axis] =
            (r[axis][0] * sign[0] + r[axis][1] * sign[1] + r[axis][2] * sign[2]) * half_child_px;
      }
      frame.offsets[static_cast<std::size_t>(level)][k] = {v[0], v[1], v[2]};
    }
  }
  return frame;
}

// Pixel = floor of the position; z becomes the fixed variants' depth key (FrameSetup::depthKey),
// clamped to the range they can produce, which rounding here may overshoot by a hair.
template <PixelPayload kPayload>
struct FloatPlot {
  std::uint32_t* pixel;
  std::int32_t width;
  std::int32_t height;
  float z_scale;
  float z_limit;
  const FrameSetup* setup;
  void operator()(const Point3<float>& p, std::uint32_t payload) const {
    if (!(p.x >= 0.0f && p.y >= 0.0f)) return;
    const auto x = static_cast<std::int32_t>(p.x);
    const auto y = static_cast<std::int32_t>(p.y);
    if (x >= width || y >= height) return;
    const std::size_t at =
        static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    const auto z = static_cast<std::int32_t>(std::clamp(p.z * z_scale, -z_limit, z_limit));
    const std::uint32_t word = Framebuffer::packLeaf<kPayload>(setup->depthKey(z), payload);
    if (word < pixel[at]) pixel[at] = word;
  }
};

template <typename Visit>
bool renderFloatWith(Visit visit, const LevelView& level, const FrameSetup& setup, FrameView& frame,
                     const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
  const FloatFrame float_frame = floatFrameFrom(setup);
  // The largest float not above depth_bias: its conversion to int32 stays within the bias.
  const float z_limit = std::nextafter(static_cast<float>(setup.depth_bias), 0.0f);
  return withLeafCursor(level, frame, [&]<typename Leaves>(Leaves leaves) {
    const FloatPlot<Leaves::kPayload> plot{frame.pixelData(), frame.width(),
                                           frame.height(),    std::ldexp(1.0f, setup.fraction_bits),
                                           z_limit,           &setup};
    DecodeState<float, FloatPlot<Leaves::kPayload>, Leaves> state{
        level.nodes.data(), leaves, float_frame.offsets, setup.depth, plot, abort};
    visit(state, 0, float_frame.root);
    return !state.aborted;
  });
}

}  // namespace

bool renderFloatBaseline(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderFloatWith([](auto& s, int l, Point3<float> p) { visitBaseline(s, l, p); }, level,
                         setup, frame, abort);
}

bool renderFloatLeafCall(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderFloatWith([](auto& s, int l, Point3<float> p) { visitLeafCall(s, l, p); }, level,
                         setup, frame, abort);
}

bool renderFloatUnrolled(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const std::atomic<bool>* abort) {
  return renderFloatWith([](auto& s, int l, Point3<float> p) { visitUnrolled(s, l, p); }, level,
                         setup, frame, abort);
}

}  // namespace octopoint

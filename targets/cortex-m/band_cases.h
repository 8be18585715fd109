#pragma once
// The frames the bare-metal band test draws (targets/cortex-m/band_test_main.cpp) and the host
// golden tool (targets/cortex-m/golden_main.cpp) checksums: the same list compiled into both, so
// the goldens always describe exactly the cases the device renders. Everything is constexpr: on the
// device the list lives in flash, and no angle conversion (a division) runs there.

#include <array>
#include <cstddef>
#include <cstdint>

#include "octopoint/camera.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint::mcu {

struct BandCase {
  int camera;  // index into kCameras
  int depth;
  bool fill;
  std::int32_t band_rows;
};

constexpr Camera makeCamera(std::int32_t width, std::int32_t height, int yaw, int pitch,
                            int zoom_percent, std::int32_t pan_x, std::int32_t pan_y) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  camera.zoom = Q16::fromRaw(zoom_percent * Q16::kOneRaw / 100);
  camera.pan_x_px = pan_x;
  camera.pan_y_px = pan_y;
  return camera;
}

// Straight on at the panel's landscape size; turned, zoomed and panned so that the model leaves
// the frame (straddling subtrees, clipped bands); the portrait panel turned the other way.
inline constexpr Camera kCameras[] = {
    makeCamera(320, 240, 0, 0, 100, 0, 0),
    makeCamera(320, 240, 30, -20, 150, 20, -10),
    makeCamera(240, 320, -40, 10, 120, 0, 0),
};
inline constexpr int kCameraCount = 3;

// Band heights: one row, a height that divides neither 240 nor 320, the two the targets name.
inline constexpr std::int32_t kBandRows[] = {1, 7, 8, 24};
inline constexpr int kBandRowsCount = 4;
inline constexpr int kDepths[] = {7, 8};

// Largest frame side and band (with hole filling's margins): what the test's buffers must hold.
inline constexpr std::int32_t kMaxWidth = 320;
inline constexpr std::int32_t kMaxBandRows = 24;

inline constexpr int kCaseCount = kCameraCount * 2 * 2 * kBandRowsCount;

// Every case, in the order both programs use: camera, depth, fill, band rows. A table built at
// compile time: the device looks cases up, it does not compute them.
inline constexpr std::array<BandCase, kCaseCount> kCases = [] {
  std::array<BandCase, kCaseCount> cases{};
  int i = 0;
  for (int camera = 0; camera < kCameraCount; ++camera) {
    for (const int depth : kDepths) {
      for (const bool fill : {false, true}) {
        for (const std::int32_t rows : kBandRows)
          cases[static_cast<std::size_t>(i++)] = {camera, depth, fill, rows};
      }
    }
  }
  return cases;
}();

// Perspective frames (docs/perspective.md) drawn in bands (renderer/perspective_bands.h): detail
// by distance over the model's densely sampled depths, with and without occlusion culling (the
// same frame), against the host's whole frame (PerspectiveRenderer).
struct PerspectiveCase {
  PerspectiveCamera camera;
  std::int32_t band_rows;
};

constexpr PerspectiveCamera makePerspectiveCamera(std::int64_t x_percent, std::int64_t y_percent,
                                                  std::int64_t z_percent, int yaw, int pitch,
                                                  int fov) {
  PerspectiveCamera camera;
  camera.eye = {x_percent * kPerspectiveUnit / 100, y_percent * kPerspectiveUnit / 100,
                z_percent * kPerspectiveUnit / 100};
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  camera.fov = Angle::fromDegrees(fov);
  camera.width = 320;
  camera.height = 240;
  return camera;
}

// The eye at the table's edge (the view of docs/perspective.md's walk-through), and outside the
// cube, two edges before it; bands of 24 and 8 rows.
inline constexpr PerspectiveCamera kPerspectiveCameras[] = {
    makePerspectiveCamera(0, 28, -46, 0, 28, 90),
    makePerspectiveCamera(0, 0, -200, 0, 0, 60),
};
inline constexpr int kPerspectiveCaseCount = 4;
inline constexpr std::array<PerspectiveCase, kPerspectiveCaseCount> kPerspectiveCases = {{
    {kPerspectiveCameras[0], 24},
    {kPerspectiveCameras[0], 8},
    {kPerspectiveCameras[1], 24},
    {kPerspectiveCameras[1], 8},
}};

// Smooth splats in bands (renderSmoothBands, docs/device.md): the RAM budget image's two
// cameras at depth 8, zoomed in so that voxels are magnified and blended, in 3-row bands (what
// fits 36 KB beside the blend's 16 bytes a pixel), against the host's whole smooth frame.
inline constexpr Camera kSmoothCameras[] = {
    makeCamera(320, 240, 0, 0, 300, 0, 0),
    makeCamera(320, 240, 30, -20, 450, 20, -10),
};
inline constexpr int kSmoothCaseCount = 2;
inline constexpr int kSmoothDepth = 8;
inline constexpr std::int32_t kSmoothBandRows = 3;

// FNV-1a over a band's RGB565 bytes: the checksum both sides compute.
constexpr std::uint32_t kChecksumSeed = 2166136261u;
constexpr std::uint32_t checksum(std::uint32_t hash, const std::uint8_t* bytes, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) hash = (hash ^ bytes[i]) * 16777619u;
  return hash;
}

// The background the device draws (and the host goldens assume).
inline constexpr Rgb kBackground{16, 16, 24};

}  // namespace octopoint::mcu

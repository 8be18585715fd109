#pragma once
// Camera paths (octopoint-render --path PATH.json --frames N, docs/perspective.md "Camera
// paths"): key frames of an eye in the scan's units and a look, interpolated smoothly through
// every key (a cubic Hermite curve whose tangents are the keys' neighbours' differences, as
// Catmull-Rom's), sampled at N evenly spaced times. Host side: doubles; each sample becomes the
// integer camera of renderer/perspective.h through tools/scan_eye.h.

#include <optional>
#include <string>
#include <vector>

#include "tools/scan_eye.h"

namespace octopoint {

inline constexpr std::size_t kMaxPathKeys = 1000;
inline constexpr int kMaxPathFrames = 3600;  // two minutes at 30 frames a second
// frames x width x height: the PNGs of one path hold at most this many pixels (3 GiB as RGB).
inline constexpr std::int64_t kMaxPathPixels = std::int64_t{1} << 30;
inline constexpr std::uint64_t kMaxPathFileBytes = std::uint64_t{1} << 20;

struct PathKey {
  double time = 0;
  ScanPoint eye{};
  std::array<double, 3> look_degrees{};  // yaw, pitch, roll
};

struct CameraPath {
  std::vector<PathKey> keys;  // times strictly ascending
  std::optional<double> fov_degrees;
};

// Reads and checks a path file (at most kMaxPathFileBytes); a cli::Error, one line naming the
// file and the key, otherwise.
CameraPath loadCameraPath(const std::string& path);
CameraPath parseCameraPath(const std::string& text, const std::string& path);

struct PathPose {
  ScanPoint eye{};
  Look look;
};

// The path at `frames` evenly spaced times from its first key's to its last's (one frame: the
// first key). Yaw, pitch and roll turn the short way between keys (a key at 170 degrees and the
// next at -170 turn 20 degrees, not 340).
std::vector<PathPose> samplePath(const CameraPath& path, int frames);

}  // namespace octopoint

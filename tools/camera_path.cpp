#include "tools/camera_path.h"

#include <cmath>

#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/real_numbers.h"
#include "cli/strict_json.h"
#include "cli/text.h"

namespace octopoint {
namespace {

using nlohmann::json;

constexpr double kMaxTime = 1e9;

class PathReader : public cli::JsonReader<cli::Error> {
 public:
  using JsonReader::JsonReader;

  // A list of `low`..`high` numbers, each within +-limit.
  std::vector<double> numbers(const json& value, const std::string& key, std::size_t low,
                              std::size_t high, double limit, const char* shape) const {
    if (!value.is_array() || value.size() < low || value.size() > high) fail(key, shape);
    std::vector<double> out;
    for (const json& item : value) out.push_back(number(item, key, -limit, limit));
    return out;
  }
};

PathKey readKey(const PathReader& reader, const json& item, std::size_t index, bool timed) {
  const std::string where = "keys[" + std::to_string(index) + "]";
  reader.onlyKeys(item, where, {"time", "eye", "look"});
  if (!item.contains("eye")) reader.fail(where, "has no \"eye\"");
  if (timed != item.contains("time")) reader.fail(where, "give \"time\" in every key or in none");
  PathKey key;
  key.time = timed ? reader.number(item["time"], where + ".time", -kMaxTime, kMaxTime)
                   : static_cast<double>(index);
  const std::vector<double> eye =
      reader.numbers(item["eye"], where + ".eye", 3, 3, kMaxEyeCoordinate, "expected [x, y, z]");
  key.eye = {eye[0], eye[1], eye[2]};
  if (item.contains("look")) {
    const std::vector<double> look =
        reader.numbers(item["look"], where + ".look", 2, 3, cli::kMaxDegrees,
                       "expected [yaw, pitch] or [yaw, pitch, roll] in degrees");
    key.look_degrees = {look[0], look[1], look.size() == 3 ? look[2] : 0.0};
  }
  return key;
}

// The value at `t` of the cubic Hermite curve through (times[k], values[k]) whose tangent at each
// inner key is the slope between its neighbours, at an end key the slope to its neighbour.
double hermite(const std::vector<double>& times, const std::vector<double>& values, double t) {
  const std::size_t n = values.size();
  if (n == 1) return values[0];
  std::size_t k = 0;  // the segment [times[k], times[k + 1]] holding t
  while (k + 2 < n && t > times[k + 1]) ++k;
  const auto slope = [&](std::size_t i) {
    const std::size_t a = i == 0 ? 0 : i - 1;
    const std::size_t b = i + 1 == n ? i : i + 1;
    return (values[b] - values[a]) / (times[b] - times[a]);
  };
  const double h = times[k + 1] - times[k];
  const double s = (t - times[k]) / h;  // 0..1 within the segment
  const double s2 = s * s;
  const double s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * values[k] + (s3 - 2 * s2 + s) * h * slope(k) +
         (-2 * s3 + 3 * s2) * values[k + 1] + (s3 - s2) * h * slope(k + 1);
}

// Degrees as the camera's angle (as --yaw rounds them: to the millidegree, then 1/65536 turn).
Angle angleOf(double degrees) { return Angle::fromMilliDegrees(std::llround(degrees * 1000)); }

}  // namespace

CameraPath parseCameraPath(const std::string& text, const std::string& path) {
  const PathReader reader(path);
  const json root = cli::parseStrictJson(text, path, "a camera path");
  reader.onlyKeys(root, "", {"keys", "fov"});
  CameraPath camera_path;
  if (root.contains("fov")) {
    camera_path.fov_degrees =
        reader.number(root["fov"], "fov", kMinFieldOfViewDegrees, kMaxFieldOfViewDegrees);
  }
  if (!root.contains("keys")) throw cli::Error(reader.path() + ": no \"keys\": a path needs keys");
  const json& keys = root["keys"];
  if (!keys.is_array() || keys.empty() || keys.size() > kMaxPathKeys) {
    reader.fail("keys", "expected a list of 1 to " + std::to_string(kMaxPathKeys) + " keys");
  }
  const bool timed = keys[0].is_object() && keys[0].contains("time");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    camera_path.keys.push_back(readKey(reader, keys[i], i, timed));
    if (i > 0 && !(camera_path.keys[i].time > camera_path.keys[i - 1].time)) {
      reader.fail("keys[" + std::to_string(i) + "].time",
                  "times must rise from key to key (" +
                      cli::realText(camera_path.keys[i - 1].time) + " before it)");
    }
  }
  return camera_path;
}

CameraPath loadCameraPath(const std::string& path) {
  return parseCameraPath(cli::readInputFile(path, cli::InputKind{"camera path", kMaxPathFileBytes}),
                         path);
}

std::vector<PathPose> samplePath(const CameraPath& path, int frames) {
  const std::size_t n = path.keys.size();
  std::vector<double> times(n);
  std::array<std::vector<double>, 6> values;  // eye x, y, z; yaw, pitch, roll
  for (auto& list : values) list.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const PathKey& key = path.keys[k];
    times[k] = key.time;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      values[axis][k] = key.eye[axis];
      double degrees = key.look_degrees[axis];
      if (k > 0) {
        // The short way round from the previous key's angle, as it was unwrapped.
        const double previous = values[3 + axis][k - 1];
        degrees = previous + std::remainder(degrees - previous, 360.0);
      }
      values[3 + axis][k] = degrees;
    }
  }
  std::vector<PathPose> poses;
  for (int i = 0; i < frames; ++i) {
    const double t = frames == 1
                         ? times.front()
                         : times.front() + (times.back() - times.front()) * i / (frames - 1);
    std::array<double, 6> at{};
    for (std::size_t c = 0; c < at.size(); ++c) at[c] = hermite(times, values[c], t);
    poses.push_back({{at[0], at[1], at[2]}, {angleOf(at[3]), angleOf(at[4]), angleOf(at[5])}});
  }
  return poses;
}

}  // namespace octopoint

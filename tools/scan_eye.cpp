#include "tools/scan_eye.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/error.h"
#include "cli/real_numbers.h"
#include "cli/text.h"

namespace octopoint {
namespace {

// The pieces of a comma-separated list of `low`..`high` numbers; a cli::Error naming the format.
std::vector<std::string_view> splitCommas(std::string_view option, std::string_view text,
                                          std::size_t low, std::size_t high,
                                          std::string_view format) {
  std::vector<std::string_view> pieces;
  std::size_t at = 0;
  while (pieces.size() <= high) {
    const std::size_t comma = text.find(',', at);
    pieces.push_back(text.substr(at, comma == std::string_view::npos ? text.npos : comma - at));
    if (comma == std::string_view::npos) break;
    at = comma + 1;
  }
  if (pieces.size() < low || pieces.size() > high) {
    throw cli::Error(std::string(option) + ": " + cli::inQuotes(text) + " is not " +
                     std::string(format));
  }
  return pieces;
}

// The model coordinate, in Q.24 cube edges, of a scan point whose coordinate on `axis` is `value`
// (the other axes do not enter it); nullopt beyond the camera's reach, and for NaN.
std::optional<std::int64_t> modelCoordinate(const ScanCube& cube, std::size_t axis, double value) {
  double edges = (value - cube.corner[axis]) / cube.edge - 0.5;
  if (cube.y_up && axis > 0) edges = -edges;
  if (!(std::fabs(edges) <= static_cast<double>(kMaxEyeDistance))) return std::nullopt;
  return std::llround(edges * static_cast<double>(kPerspectiveUnit));
}

// `value` rounded to `decimals` decimals, as reading that decimal back gives it.
double withDecimals(double value, int decimals) {
  char text[400];  // %f of the largest double takes 309 digits
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  const double rounded = std::strtod(text, nullptr);
  return rounded == 0 ? 0.0 : rounded;  // "0", not "-0" (-0.3 to no decimals)
}

}  // namespace

std::optional<ScanCube> scanCube(const CubePlacement& placement) {
  if (!placement.recorded()) return std::nullopt;
  ScanCube cube;
  for (std::size_t axis = 0; axis < 3; ++axis)
    cube.corner[axis] = std::bit_cast<double>(placement.corner_bits[axis]);
  cube.edge = std::bit_cast<double>(placement.edge_bits);
  cube.y_up = placement.scan_axes == format::kScanAxesYUp;
  return cube;
}

ScanPoint parseScanPoint(std::string_view option, std::string_view text) {
  const std::vector<std::string_view> pieces = splitCommas(option, text, 3, 3, "X,Y,Z");
  ScanPoint point;
  for (std::size_t axis = 0; axis < 3; ++axis)
    point[axis] = cli::parseReal(option, pieces[axis], -kMaxEyeCoordinate, kMaxEyeCoordinate);
  return point;
}

Look parseLook(std::string_view option, std::string_view text) {
  const std::vector<std::string_view> pieces =
      splitCommas(option, text, 2, 3, "YAW,PITCH or YAW,PITCH,ROLL in degrees");
  Look look;
  look.yaw = cli::parseDegrees(option, pieces[0]);
  look.pitch = cli::parseDegrees(option, pieces[1]);
  if (pieces.size() == 3) look.roll = cli::parseDegrees(option, pieces[2]);
  return look;
}

ModelPoint modelPointOf(const ScanCube& cube, const ScanPoint& point, std::string_view option) {
  std::array<std::int64_t, 3> model{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::optional<std::int64_t> coordinate = modelCoordinate(cube, axis, point[axis]);
    if (!coordinate) {
      // Beyond the camera's reach, or NaN (from an infinite edge ratio).
      const double edges = std::fabs((point[axis] - cube.corner[axis]) / cube.edge - 0.5);
      char text[320];
      std::snprintf(text, sizeof text,
                    ": the eye is %.3g cube edges from the model's centre along %c; the camera "
                    "holds at most %d (the cube: %s %s)",
                    edges, "xyz"[axis], static_cast<int>(kMaxEyeDistance),
                    scanPointText(cube.corner).c_str(), cli::realText(cube.edge).c_str());
      throw cli::Error(std::string(option) + text);
    }
    model[axis] = *coordinate;
  }
  return {model[0], model[1], model[2]};
}

ScanPoint scanPointOf(const ScanCube& cube, const ModelPoint& point) {
  const auto unit = static_cast<double>(kPerspectiveUnit);
  std::array<double, 3> edges = {static_cast<double>(point.x) / unit,
                                 static_cast<double>(point.y) / unit,
                                 static_cast<double>(point.z) / unit};
  if (cube.y_up) edges = {edges[0], -edges[1], -edges[2]};
  ScanPoint scan;
  for (std::size_t axis = 0; axis < 3; ++axis)
    scan[axis] = cube.corner[axis] + (edges[axis] + 0.5) * cube.edge;
  return scan;
}

std::int64_t modelNearPlane(const ModelView& model, std::optional<double> distance,
                            std::string_view option) {
  if (!distance) return nearPlaneForDepth(model.finestLevel().depth);
  const std::optional<ScanCube> cube = scanCube(model.cubePlacement());
  if (!cube) {
    throw cli::Error(std::string(option) +
                     " is in scan units, and this model does not record its cube's placement "
                     "(format version " +
                     std::to_string(model.formatVersion()) +
                     "): prepare the scan again with octopoint-prepare");
  }
  const double edges = *distance / cube->edge;
  const double q24 = std::round(edges * static_cast<double>(kPerspectiveUnit));
  if (!(q24 >= 1 && q24 <= static_cast<double>(kMaxEyeDistance * kPerspectiveUnit))) {
    char text[200];
    std::snprintf(text, sizeof text,
                  ": %s scan units is %.3g cube edges (of %s); the camera takes 2^-24 to %d",
                  cli::realText(*distance).c_str(), edges, cli::realText(cube->edge).c_str(),
                  static_cast<int>(kMaxEyeDistance));
    throw cli::Error(std::string(option) + text);
  }
  return static_cast<std::int64_t>(q24);
}

PerspectiveView scanEyeView(const ScanCube& cube, const ScanPoint& eye, const Look& look, Angle fov,
                            std::int64_t near, int width, int height, std::string_view option) {
  PerspectiveCamera camera;
  camera.eye = modelPointOf(cube, eye, option);
  camera.near = near;
  camera.yaw = look.yaw;
  camera.pitch = look.pitch;
  camera.roll = look.roll;
  camera.fov = fov;
  camera.width = width;
  camera.height = height;
  PerspectiveView view;
  if (const PerspectiveError error = buildPerspectiveView(camera, kDefaultFractionBits, &view);
      error != PerspectiveError::kNone) {
    throw cli::Error(std::string(option) + ": " + describe(error));
  }
  return view;
}

std::string scanPointText(const ScanPoint& point) {
  return cli::realText(point[0]) + "," + cli::realText(point[1]) + "," + cli::realText(point[2]);
}

std::string eyeText(const ScanCube& cube, const ModelPoint& point) {
  const ScanPoint scan = scanPointOf(cube, point);
  const std::array<std::int64_t, 3> model = {point.x, point.y, point.z};
  std::string text;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    double shortest = scan[axis];  // the double itself reads back as itself
    for (int decimals = 0; decimals <= 17; ++decimals) {
      const double candidate = withDecimals(scan[axis], decimals);
      if (modelCoordinate(cube, axis, candidate) == model[axis]) {
        shortest = candidate;
        break;
      }
    }
    if (axis > 0) text += ',';
    text += cli::realText(shortest);
  }
  return text;
}

std::string degreesText(Angle angle) {
  // Within (-180, 180], the fewest decimals that read back (cli::parseDegrees: whole millidegrees,
  // rounded to the nearest 1/65536 turn) as this very angle: -28 rather than 332.0013427734375.
  // A 1/65536 turn is 0.0055 degrees, so three decimals always suffice.
  const auto sameAngle = [&](Angle other) {
    return static_cast<std::uint16_t>(other.turns16()) ==
           static_cast<std::uint16_t>(angle.turns16());
  };
  int units = static_cast<std::uint16_t>(angle.turns16());
  if (units > Angle::kUnitsPerTurn / 2) units -= Angle::kUnitsPerTurn;
  const double degrees = units * (360.0 / Angle::kUnitsPerTurn);  // exact in a double
  char text[32];
  for (int decimals = 0;; ++decimals) {
    std::snprintf(text, sizeof text, "%.*f", decimals, degrees);
    const double read = std::strtod(text, nullptr);
    if (decimals == 3 || sameAngle(Angle::fromMilliDegrees(std::llround(read * 1000)))) break;
  }
  return std::string(std::strcmp(text, "-0") == 0 ? "0" : text);
}

}  // namespace octopoint

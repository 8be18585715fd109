#pragma once
// octopoint-render --eye/--look (and the camera paths): the perspective camera placed in the scan's
// own units and axes, the frame octopoint-prepare's --crop takes, through the cube's placement the
// model records (octopoint/model.h, CubePlacement). Host side: doubles here, the renderer gets the
// integer camera of renderer/perspective.h (Q.24 cube edges about the cube's centre).

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "octopoint/model.h"
#include "renderer/perspective.h"

namespace octopoint {

using ScanPoint = std::array<double, 3>;  // scan units, the scan's own axes

// The cube's placement as numbers.
struct ScanCube {
  ScanPoint corner{};  // the lowest corner
  double edge = 0;
  bool y_up = false;  // the model is the scan turned 180 degrees about x
};

// nullopt when the model does not record where its cube lies (format versions 1 to 3).
std::optional<ScanCube> scanCube(const CubePlacement& placement);

// The direction of the eye, in degrees: yaw turns right, pitch up, roll clockwise; 0,0 looks the
// way the sensor did (+z of a y-down scan, -z of a y-up one).
struct Look {
  Angle yaw, pitch, roll;
};

// The largest |coordinate| --eye takes: the crop box's (codegen/prepare.h), past any LAS
// coordinate; the camera then refuses what lies beyond kMaxEyeDistance cube edges.
inline constexpr double kMaxEyeCoordinate = 1e13;

// "X,Y,Z": three finite numbers within kMaxEyeCoordinate; a cli::Error naming `option` otherwise.
ScanPoint parseScanPoint(std::string_view option, std::string_view text);
// "YAW,PITCH" or "YAW,PITCH,ROLL" in degrees (each as --yaw takes it).
Look parseLook(std::string_view option, std::string_view text);

// The model point (Q.24 cube edges about the cube's centre) of `point`, rounded to the nearest
// unit; a cli::Error naming `option` when it lies more than kMaxEyeDistance cube edges from the
// centre on some axis.
ModelPoint modelPointOf(const ScanCube& cube, const ScanPoint& point, std::string_view option);
// And back: where a model point lies in the scan.
ScanPoint scanPointOf(const ScanCube& cube, const ModelPoint& point);

// The near plane a camera drawing `model` takes: `distance` scan units (--near) where given, a
// cli::Error naming `option` when that is not within (0, kMaxEyeDistance] cube edges once rounded
// to Q.24 or the model records no placement; nearPlaneForDepth of its finest depth otherwise.
std::int64_t modelNearPlane(const ModelView& model, std::optional<double> distance,
                            std::string_view option);

// The perspective camera of an eye at `eye` looking `look` with the vertical field of view `fov`
// and the near plane `near` (Q.24 cube edges) on a width x height frame; a cli::Error naming
// `option` when it cannot be drawn.
PerspectiveView scanEyeView(const ScanCube& cube, const ScanPoint& eye, const Look& look, Angle fov,
                            std::int64_t near, int width, int height, std::string_view option);

// "X,Y,Z" with the digits that give the same numbers back, and an angle in degrees likewise.
std::string scanPointText(const ScanPoint& point);
// "X,Y,Z" of a model point in the scan: each coordinate with the fewest decimals that
// --eye (modelPointOf) reads back as the very same model point: 0.05,0.1,-0.45 rather than
// 0.05000000000223892,0.0999999859662672,-0.45000000204890966.
std::string eyeText(const ScanCube& cube, const ModelPoint& point);
std::string degreesText(Angle angle);

}  // namespace octopoint

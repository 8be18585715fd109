// How octopoint-render and octopoint-view print an angle and an eye (tools/scan_eye.h): a text the
// user can pass back to --look, --fov or --eye that reads as the very same angle or model point,
// and as short as that allows.
#include "tools/scan_eye.h"

#include <gtest/gtest.h>

#include "cli/real_numbers.h"

namespace octopoint {
namespace {

TEST(DegreesText, EveryAngleReadsBackAsItself) {
  for (std::int32_t units = 0; units < Angle::kUnitsPerTurn; ++units) {
    const Angle angle = Angle::fromTurns16(units);
    const std::string text = degreesText(angle);
    const Angle read = cli::parseDegrees("--look", text);
    ASSERT_EQ(static_cast<std::uint16_t>(read.turns16()), static_cast<std::uint16_t>(units))
        << text;
  }
}

TEST(DegreesText, WhatTheUserTypedComesBackShortAndSigned) {
  for (const char* typed : {"0", "-28", "28", "90", "-90", "180", "33.3", "-12.5", "0.25", "179"}) {
    EXPECT_EQ(degreesText(cli::parseDegrees("--look", typed)), typed);
  }
  EXPECT_EQ(degreesText(cli::parseDegrees("--look", "332")), "-28");
  EXPECT_EQ(degreesText(cli::parseDegrees("--look", "-180")), "180");
}

// A cube as a scan records it: corner and edge not round in binary.
ScanCube someCube(bool y_up) {
  ScanCube cube;
  cube.corner = {-0.3717, 0.0123, -1.45};
  cube.edge = 0.8311;
  cube.y_up = y_up;
  return cube;
}

TEST(EyeText, EveryModelPointReadsBackAsItself) {
  for (const bool y_up : {false, true}) {
    const ScanCube cube = someCube(y_up);
    std::uint64_t state = 12345;  // a linear congruential walk over the camera's whole reach
    for (int i = 0; i < 20000; ++i) {
      ModelPoint point{};
      for (std::int64_t* coordinate : {&point.x, &point.y, &point.z}) {
        state = state * 6364136223846793005u + 1442695040888963407u;
        const std::int64_t reach = kMaxEyeDistance * kPerspectiveUnit;
        *coordinate = static_cast<std::int64_t>(state >> 20) % (2 * reach + 1) - reach;
      }
      const std::string text = eyeText(cube, point);
      const ModelPoint read = modelPointOf(cube, parseScanPoint("--eye", text), "--eye");
      ASSERT_EQ(read.x, point.x) << text;
      ASSERT_EQ(read.y, point.y) << text;
      ASSERT_EQ(read.z, point.z) << text;
    }
  }
}

TEST(EyeText, WhatTheUserTypedComesBackShort) {
  for (const bool y_up : {false, true}) {
    const ScanCube cube = someCube(y_up);
    for (const char* typed : {"0.05,0.1,-0.45", "0,0,0", "-2.5,3,-1.25", "0.01,-0.002,0.3"}) {
      const ModelPoint point = modelPointOf(cube, parseScanPoint("--eye", typed), "--eye");
      EXPECT_EQ(eyeText(cube, point), typed);
    }
  }
}

}  // namespace
}  // namespace octopoint

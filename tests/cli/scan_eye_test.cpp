// How octopoint-render and octopoint-view print an angle (tools/scan_eye.h): a text the user can
// pass back to --look or --fov that reads as the very same angle, and as short as that allows.
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

}  // namespace
}  // namespace octopoint

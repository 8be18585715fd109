#pragma once
// What the golden-format tests of every version share (tests/core/golden_format_test.cpp,
// tests/core/golden_format_v2_test.cpp): the validated view of a golden image, and the camera that
// draws one pixel per leaf on an 8 x 8 frame.

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/model.h"

namespace octopoint::testing {

// The validated view of a golden image; a refusal fails the test (gtest reports the exception).
inline ModelView validated(const std::vector<std::uint8_t>& image) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromBytes(image, &issue);
  if (!model) {
    throw std::runtime_error(std::string("golden model refused: ") + describe(issue.error) +
                             " at byte " + std::to_string(issue.offset));
  }
  return *model;
}

// The identity camera on an 8 x 8 frame: the cube spans 8 pixels around the centre (4, 4), so a
// child at tree level l sits +-8 / 2^(l + 2) pixels from its parent on each axis.
inline FrameSetup identitySetup(int depth) {
  Camera camera;
  camera.width = 8;
  camera.height = 8;
  FrameSetup setup;
  EXPECT_EQ(buildFrameSetup(camera, depth, 15, &setup), CameraError::kNone);
  setup.splat =
      SplatFootprint{};  // one pixel per leaf: the positions, as every fixed variant draws them
  return setup;
}

}  // namespace octopoint::testing

// The page's pixels (web/web_canvas.h): the colour style is resolved straight into RGBA, and only
// where the frame or the last frame was drawn. Every draw of a sequence whose drawn rectangle
// shrinks, grows, moves, changes size and follows another style must still be, pixel for pixel,
// octopoint-render's frame of the same view (RgbRenderer: the frame resolved whole on the same
// background) with an opaque alpha byte.
#include "web/web_canvas.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/rgb_renderer.h"
#include "web/octopoint_web.h"

namespace octopoint {
namespace {

struct View {
  std::int32_t yaw, pitch, zoom_q16, width, height;
};

std::vector<std::uint8_t> nativeRgba(const View& view) {
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  EXPECT_TRUE(model.has_value());
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(view.yaw);
  camera.pitch = Angle::fromMilliDegrees(view.pitch);
  camera.zoom = Q16::fromRaw(view.zoom_q16);
  camera.width = view.width;
  camera.height = view.height;
  std::vector<std::uint8_t> rgb(std::size_t(view.width) * std::size_t(view.height) * 3);
  RgbRenderer renderer;
  DrawOptions options;
  options.background = web::kBackground;
  EXPECT_EQ(renderer.draw(*model, camera, rgb, options), DrawError::kNone);
  std::vector<std::uint8_t> rgba;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
  return rgba;
}

std::vector<std::uint8_t> pageRgba(const View& view) {
  EXPECT_EQ(octopoint_web_draw(view.yaw, view.pitch, 0, view.zoom_q16, view.width, view.height), 0)
      << octopoint_web_error();
  const std::uint8_t* pixels = octopoint_web_pixels();
  return {pixels, pixels + std::size_t(view.width) * std::size_t(view.height) * 4};
}

TEST(WebCanvas, EveryColourFrameIsOctopointRendersWhateverWasDrawnBefore) {
  ASSERT_EQ(octopoint_web_create(), 0);
  ASSERT_EQ(octopoint_web_stream_close(), 0);
  ASSERT_EQ(octopoint_web_set_style("colour"), 0);
  constexpr std::int32_t kOne = 65536;  // zoom 1, Q16.16
  const View sequence[] = {
      {30000, 10000, 2 * kOne, 320, 240},   // the model over the whole frame
      {30000, 10000, kOne / 4, 320, 240},   // small in the middle: the rest must be background
      {-60000, 40000, kOne / 3, 320, 240},  // turned: a drawn rectangle of another shape
      {-60000, 40000, kOne, 320, 240},      // grown again
      {30000, 10000, kOne / 4, 200, 300},   // another size: no pixel of the last one stays
  };
  for (const View& view : sequence) {
    SCOPED_TRACE(testing::Message()
                 << "zoom " << view.zoom_q16 << " at " << view.width << "x" << view.height);
    EXPECT_EQ(pageRgba(view), nativeRgba(view));
  }
  // After a frame in another style (written whole through RGB), the colour style's again.
  const View wide{30000, 10000, 2 * kOne, 200, 300};
  ASSERT_EQ(octopoint_web_set_style("shaded"), 0) << octopoint_web_error();
  const std::vector<std::uint8_t> shaded = pageRgba(wide);
  ASSERT_NE(shaded, nativeRgba(wide));
  ASSERT_EQ(octopoint_web_set_style("colour"), 0);
  const View small{30000, 10000, kOne / 4, 200, 300};
  EXPECT_EQ(pageRgba(small), nativeRgba(small));
}

}  // namespace
}  // namespace octopoint

// The C interface the page (web/octopoint.js) calls: one renderer for the embedded default model,
// a camera, a draw, and the RGBA pixels of the last frame in the module's memory. The frame is
// drawn exactly as octopoint-render draws one view (depth auto, the style chosen, its background
// and the variant defaultVariant() picks, fixed_fast on WebAssembly), so that the page's frames can
// be compared with the native PNG pixel for pixel. The style is octopoint-render's --style, with
// its defaults for the light and the crease angle.
#include "web/octopoint_web.h"

#include <cstdint>
#include <optional>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/models.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"
#include "renderer/level_of_detail.h"

namespace {

using namespace octopoint;

// octopoint-render's background (tools/render_main.cpp): the frames must match its PNGs.
constexpr Rgb kBackground{236, 236, 240};
// The most pixels octopoint-render writes in a frame (it allows sides up to 8192), and so the
// page's.
constexpr std::int64_t kMaxPixels = std::int64_t{4096} * 4096;

struct WebRenderer {
  ModelView model;
  FrameStyler styler;
  std::vector<std::uint8_t> rgb;   // what the styler writes, 3 bytes a pixel
  std::vector<std::uint8_t> rgba;  // what the page copies into its canvas, 4 bytes a pixel
  // Kept between draws and made anew only when the size changes: no allocation per frame (the
  // vectors above keep their capacity too).
  std::optional<Framebuffer> frame;
  explicit WebRenderer(const ModelView& view) : model(view), styler(model) {}
};

std::optional<WebRenderer>& renderer() {
  static std::optional<WebRenderer> instance;
  return instance;
}

const char* g_error = "";

int fail(const char* message) {
  g_error = message;
  return -1;
}

// Widens the styler's RGB into opaque RGBA, the layout of a canvas's ImageData.
void toRgba(const std::vector<std::uint8_t>& rgb, std::vector<std::uint8_t>& rgba) {
  const std::size_t pixels = rgb.size() / 3;
  rgba.resize(pixels * 4);
  for (std::size_t i = 0; i < pixels; ++i) {
    rgba[i * 4 + 0] = rgb[i * 3 + 0];
    rgba[i * 4 + 1] = rgb[i * 3 + 1];
    rgba[i * 4 + 2] = rgb[i * 3 + 2];
    rgba[i * 4 + 3] = 255;
  }
}

}  // namespace

extern "C" {

int octopoint_web_create(void) {
  if (renderer()) return 0;
  ModelIssue issue;
  const std::optional<ModelView> view = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!view) return fail("the embedded model is invalid");
  renderer().emplace(*view);
  StyleOptions style;
  style.background = kBackground;
  if (renderer()->styler.setOptions(style) != StyleError::kNone) {
    renderer().reset();
    return fail("the colour style is refused");
  }
  return 0;
}

int octopoint_web_draw(std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                       std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
                       std::int32_t height) {
  return octopoint::web::drawWith(defaultVariant(), yaw_millidegrees, pitch_millidegrees,
                                  roll_millidegrees, zoom_q16, width, height);
}

const std::uint8_t* octopoint_web_pixels(void) {
  return renderer() ? renderer()->rgba.data() : nullptr;
}

int octopoint_web_set_style(const char* name) {
  if (!renderer()) return fail("octopoint_web_create was not called");
  const std::optional<Style> style = name == nullptr ? std::nullopt : styleFromName(name);
  if (!style) return fail("no such style (colour, shaded, lines, toon, outlined)");
  StyleOptions options = renderer()->styler.options();
  options.style = *style;
  if (const StyleError error = renderer()->styler.setOptions(options); error != StyleError::kNone) {
    return fail(describe(error));
  }
  g_error = "";
  return 0;
}

const char* octopoint_web_error(void) { return g_error; }

}  // extern "C"

namespace octopoint::web {

int drawWith(Variant variant, std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
             std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
             std::int32_t height) {
  if (!renderer()) return fail("octopoint_web_create was not called");
  WebRenderer& web = *renderer();
  if (width < 1 || height < 1 || width > kMaxViewportSide || height > kMaxViewportSide ||
      std::int64_t{width} * height > kMaxPixels) {
    return fail("the size must be 1..8192 a side and 16777216 pixels at most");
  }
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(yaw_millidegrees);
  camera.pitch = Angle::fromMilliDegrees(pitch_millidegrees);
  camera.roll = Angle::fromMilliDegrees(roll_millidegrees);
  camera.zoom = Q16::fromRaw(zoom_q16);  // Q16.16, as octopoint-render's --zoom
  camera.width = width;
  camera.height = height;
  const LevelView* level = autoLevel(web.model, camera);
  if (level == nullptr) return fail(describe(CameraError::kOverflow));
  FrameSetup setup;
  if (const CameraError error = buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup);
      error != CameraError::kNone) {
    return fail(describe(error));
  }
  if (!web.frame || web.frame->width() != width || web.frame->height() != height)
    web.frame.emplace(width, height);
  Framebuffer& frame = *web.frame;
  frame.clear(web.styler.payload());
  if (!renderLevel(variant, *level, setup, frame)) return fail("the draw was refused");
  web.rgb.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  web.styler.beginFrame(setup);
  if (web.styler.resolve(frame, web.rgb) != StyleError::kNone) return fail("the style refused");
  toRgba(web.rgb, web.rgba);
  g_error = "";
  return 0;
}

}  // namespace octopoint::web

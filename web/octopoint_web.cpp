// The C interface the page (web/octopoint.js) calls: one renderer for the embedded default model
// (or, once the page opened one, a chunked model: web/octopoint_web_stream.cpp), a camera, a draw,
// and the RGBA pixels of the last frame in the module's memory. The frame is
// drawn exactly as octopoint-render draws one view (depth auto, the style chosen, its background
// and the variant defaultVariant() picks, fixed_fast on WebAssembly), so that the page's frames can
// be compared with the native PNG pixel for pixel. The style is octopoint-render's --style, with
// its defaults for the light and the crease angle. Built with OCTOPOINT_WEB_EMBEDDED_MODEL=0 (the
// page without a model, build/wasm/web-nomodel/), it embeds none and draws only chunked models.
#include "web/octopoint_web.h"

#include <cstdint>
#include <optional>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#if OCTOPOINT_WEB_EMBEDDED_MODEL
#include "octopoint/models.h"
#endif
#include "octopoint/render.h"
#include "octopoint/styles.h"
#include "renderer/level_of_detail.h"
#include "web/web_canvas.h"

namespace {

using namespace octopoint;
using web::fail;
using web::succeed;

#if OCTOPOINT_WEB_EMBEDDED_MODEL
// The embedded model and its styles. The page without a model has neither: its chunked models are
// drawn in colour by the stream (web/octopoint_web_stream.cpp), and leaving the styles' code out
// keeps it within its weight (docs/web.md, "Page weight").
struct WebRenderer {
  ModelView model;
  FrameStyler styler;
  explicit WebRenderer(const ModelView& view) : model(view), styler(model) {}
};

std::optional<WebRenderer>& renderer() {
  static std::optional<WebRenderer> instance;
  return instance;
}
#endif

bool& created() {
  static bool done = false;
  return done;
}

}  // namespace

extern "C" {

int octopoint_web_create(void) {
#if OCTOPOINT_WEB_EMBEDDED_MODEL
  if (renderer()) return 0;
  ModelIssue issue;
  const std::optional<ModelView> view = ModelView::fromEmbedded(*models::defaultModel(), &issue);
  if (!view) return fail("the embedded model is invalid");
  renderer().emplace(*view);
  StyleOptions style;
  style.background = web::kBackground;
  if (renderer()->styler.setOptions(style) != StyleError::kNone) {
    renderer().reset();
    return fail("the colour style is refused");
  }
#endif
  created() = true;
  return 0;
}

int octopoint_web_draw(std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                       std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
                       std::int32_t height) {
  return octopoint::web::drawWith(defaultVariant(), yaw_millidegrees, pitch_millidegrees,
                                  roll_millidegrees, zoom_q16, width, height);
}

const std::uint8_t* octopoint_web_pixels(void) {
  const std::vector<std::uint32_t>& rgba = web::canvas().rgba;
  // The words' bytes, R, G, B, A a pixel in memory order (web/web_canvas.h).
  return rgba.empty() ? nullptr : reinterpret_cast<const std::uint8_t*>(rgba.data());
}

int octopoint_web_set_style(const char* name) {
  if (!created()) return fail("octopoint_web_create was not called");
  const std::optional<Style> style = name == nullptr ? std::nullopt : styleFromName(name);
  if (!style) return fail("no such style (colour, shaded, lines, toon, outlined)");
  if (*style != Style::kColour && (web::streamOpen() || !OCTOPOINT_WEB_EMBEDDED_MODEL))
    return fail("a chunked model is drawn in colour only (it stores no normals)");
#if OCTOPOINT_WEB_EMBEDDED_MODEL
  StyleOptions options = renderer()->styler.options();
  options.style = *style;
  if (const StyleError error = renderer()->styler.setOptions(options); error != StyleError::kNone) {
    return fail(describe(error));
  }
#endif
  return succeed();
}

const char* octopoint_web_error(void) { return web::errorText(); }

}  // extern "C"

namespace octopoint::web {

const ModelView* embeddedModel() {
#if OCTOPOINT_WEB_EMBEDDED_MODEL
  return renderer() ? &renderer()->model : nullptr;
#else
  return nullptr;
#endif
}

int drawWith(Variant variant, std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
             std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
             std::int32_t height) {
  if (!created()) return fail("octopoint_web_create was not called");
  if (!sizeAllowed(width, height)) return fail(kSizeRule);
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(yaw_millidegrees);
  camera.pitch = Angle::fromMilliDegrees(pitch_millidegrees);
  camera.roll = Angle::fromMilliDegrees(roll_millidegrees);
  camera.zoom = Q16::fromRaw(zoom_q16);  // Q16.16, as octopoint-render's --zoom
  camera.width = width;
  camera.height = height;
  if (streamOpen()) return drawStream(variant, camera);
#if !OCTOPOINT_WEB_EMBEDDED_MODEL
  return fail("this page embeds no model: open a chunked one (model=NAME.oct)");
#else
  if (!renderer()) return fail("the embedded model is invalid");
  WebRenderer& web = *renderer();
  const LevelView* level = autoLevel(web.model, camera);
  if (level == nullptr) return fail(describe(CameraError::kOverflow));
  FrameSetup setup;
  // The level's splats as wide as its samples lie apart, as octopoint-render draws them.
  if (const CameraError error = buildFrameSetup(camera, level->depth, kDefaultFractionBits, &setup,
                                                web.model.sampleReachOfDepth(level->depth));
      error != CameraError::kNone) {
    return fail(describe(error));
  }
  Canvas& out = canvas();
  Framebuffer& frame = out.sized(camera.width, camera.height);
  frame.clear(web.styler.payload());
  if (!renderLevel(variant, *level, setup, frame)) return fail("the draw was refused");
  if (web.styler.options().style == Style::kColour) {
    // The palette's colours on the background (the styler's colour style): straight into RGBA.
    out.resolveColour(web.model, web.styler.options().background);
    return succeed();
  }
  web.styler.beginFrame(setup);
  if (web.styler.resolve(frame, out.rgbToWrite()) != StyleError::kNone)
    return fail("the style refused");
  out.toRgba();
  return succeed();
#endif
}

}  // namespace octopoint::web

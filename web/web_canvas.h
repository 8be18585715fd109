#pragma once
// What the page's two models share in the module (web/octopoint_web.cpp draws the embedded model,
// web/octopoint_web_stream.cpp a chunked one): the frame and its pixels, kept between draws of one
// size, the camera of the page's view, and the message of the last failure.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/progressive.h"
#include "octopoint/render.h"
#include "renderer/perspective.h"

namespace octopoint::web {

// octopoint-render's background (tools/render_main.cpp): the frames must match its PNGs.
inline constexpr Rgb kBackground{236, 236, 240};

struct Canvas {
  // What the styler writes for the styles other than colour, 3 bytes a pixel.
  std::vector<std::uint8_t> rgb;
  // What the page copies into its canvas: each word a pixel's R, G, B and A bytes in memory order
  // (the layout of a canvas's ImageData), row after row.
  std::vector<std::uint32_t> rgba;
  // Kept between draws and made anew only when the size changes: no allocation per frame (the
  // vectors above keep their capacity too).
  std::optional<Framebuffer> frame;

  // The frame at this size (not cleared) and rgba sized to match.
  Framebuffer& sized(std::int32_t width, std::int32_t height);
  // The colour style (octopoint-render's resolveToRgb: a covered pixel's palette colour, an empty
  // one `background`) of the drawn frame, straight into rgba: one pass and one table load a
  // pixel. Only the pixels that may differ from the last frame's are written: those in the
  // frame's drawnRect() or in the last frame's (every other pixel of rgba already holds the
  // background, and the frame is empty there).
  void resolveColour(const ModelView& model, Rgb background);
  // rgb (sized here to the frame) for a styler to write, then widened into opaque RGBA.
  std::span<std::uint8_t> rgbToWrite();
  void toRgba();

 private:
  // Outside this rectangle rgba holds background_ (the RGBA word of the last resolveColour's
  // background); the whole frame when that is not known.
  PixelRect stale_;
  std::uint32_t background_ = 0;
};

Canvas& canvas();

// The sizes the page draws: octopoint-render's sides (1..8192) and at most its pixels (16777216).
bool sizeAllowed(std::int32_t width, std::int32_t height);
inline constexpr const char* kSizeRule =
    "the size must be 1..8192 a side and 16777216 pixels at most";

// The embedded default model (validated once by octopoint_web_create), or null: none embedded, or
// octopoint_web_create not called yet.
const ModelView* embeddedModel();

// Records why the call failed (octopoint_web_error) and returns -1; succeed() clears it, returns 0.
int fail(std::string message);
int succeed();
const char* errorText();  // "" after a success

// The chunked model's part (web/octopoint_web_stream.cpp): whether the page opened one (then the
// draws are of it, in colour), and its draw of the camera (the camera also becomes the view its
// fetch order follows).
bool streamOpen();
int drawStream(Variant variant, const Camera& camera);
// Walk mode on the chunked model (web/octopoint_web_walk.cpp): the model once its head has arrived
// (null before); how many parts it has taken so far (a new count: the held parts changed); and the
// perspective view its fetch order follows from now on (renderer/perspective_fetch.h: visible,
// coarse before fine, nearest first), until the next orbit draw.
const ProgressiveModel* streamModel();
std::uint64_t streamTaken();
void streamFollow(const PerspectiveView& view);

}  // namespace octopoint::web

#pragma once
// The C interface of the WebAssembly build (web/octopoint_web.cpp), what web/octopoint.js calls.
// Every function returns 0 when it worked, -1 otherwise (octopoint_web_error says why).

#include <cstdint>

#include "octopoint/render.h"

extern "C" {

// Validates the embedded default model and prepares its renderer (once; a second call does
// nothing).
int octopoint_web_create(void);
// Draws one frame of the camera: yaw, pitch and roll in thousandths of a degree, zoom in Q16.16
// (octopoint-render's --yaw, --pitch, --roll, --zoom, rounded as it rounds them), the size in
// pixels (its --size).
int octopoint_web_draw(std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                       std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
                       std::int32_t height);
// The style of the next draws, by octopoint-render's --style name (colour, shaded, lines, toon,
// outlined), with its default light and crease angle; an unknown name, or a style the model cannot
// draw, is refused and the style stays.
int octopoint_web_set_style(const char* name);
// The last frame, width * height RGBA pixels, row after row from the top; null before a draw.
// Valid until the next draw.
const std::uint8_t* octopoint_web_pixels(void);
// Why the last call failed, in words ("" after a success).
const char* octopoint_web_error(void);
}

namespace octopoint::web {

// octopoint_web_draw with the decoder variant given (it draws with defaultVariant()): for the
// native benchmark of the page's draw (bench/web_draw_bench.cpp), fixed_fast against fixed_simd.
int drawWith(Variant variant, std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
             std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
             std::int32_t height);

}  // namespace octopoint::web

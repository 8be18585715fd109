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

// Streaming a chunked model (docs/web.md, "Streaming"; web/octopoint_web_stream.cpp). The page
// fetches byte ranges; the module says which (the native client's order for the view of the last
// draw), checks every byte as the native renderer does and draws what it holds.
//
// Opens a new chunked model (forgetting any other): from now on octopoint_web_draw draws it, in
// colour (it fails, drawing nothing, until the model's head has arrived).
int octopoint_web_stream_open(void);
// Forgets the chunked model: octopoint_web_draw draws the embedded model again.
int octopoint_web_stream_close(void);
// The next request to make: its id (> 0; octopoint_web_stream_request says which bytes), 0 when
// there is none to make now (every wanted part in flight, or the view complete and the rest
// fetched), -1 when the stream cannot go on (no model open, or its head is not a chunked model).
std::int32_t octopoint_web_stream_next(void);
// The last request octopoint_web_stream_next made: the first byte's offset (low and high 32 bits)
// and the bytes to ask for (Range: bytes=offset-(offset+size-1)).
const std::uint32_t* octopoint_web_stream_request(void);
// Room in the module for `bytes` (1..16777216) bytes the page copies in before
// octopoint_web_stream_receive; valid until the next call (the module's memory may move).
std::uint8_t* octopoint_web_input(std::int32_t bytes);
// The next `bytes` bytes of request `id`'s body, copied into octopoint_web_input's room. Every
// record table and chunk whose last byte arrived is validated and taken, or refused (and asked for
// again by a later request). 0: taken; 1: a part was refused as damaged (octopoint_web_error says
// which; the request goes on); -1: the request is ended (more bytes than asked, an unknown id) or
// the head is refused for good.
int octopoint_web_stream_receive(std::int32_t id, std::int32_t bytes);
// Request `id` ended (its body complete, or the page gave up on it): its parts that did not arrive
// whole are asked for again by a later request. -1 when fewer bytes came than were asked for.
int octopoint_web_stream_end(std::int32_t id);
// The most points a frame of the chunked model draws (ProgressiveModel's point budget, the
// native --point-budget); 0: no budget.
int octopoint_web_set_point_budget(std::int32_t points);
// The stream as the overlay shows it, eleven words: state (1 waiting for the head, 2 drawing, 3
// failed), bytes received (low, high), the file's bytes (low, high), chunks held, the view's
// tables and chunks still to come, whether the view is complete (1), parts refused as damaged,
// requests in flight, points the last draw drew. Null when no model is open. Valid until the next
// call.
const std::uint32_t* octopoint_web_stream_status(void);

// Walk mode (docs/web.md, "Walk mode"; web/octopoint_web_walk.cpp): the eye stands in the embedded
// model, or in the chunked model opened (once its head is in: its held parts, the fetch following
// the eye), as octopoint-view's walk mode and octopoint-render --eye --look --fov place it (the
// page without a model, build/wasm/web-nomodel/: in the chunked model only). The eye is in the
// camera's Q.24 cube edges about the cube's centre (renderer/perspective.h), each coordinate given
// as its low and high 32 bits; angles as the other calls take them; the page converts from and to
// the scan's units with the cube's placement.
//
// Where the walked model's cube lies in the scan (octopoint/model.h, CubePlacement): nine words,
// the binary64 bits of the lowest corner's x, y, z and of the edge (low, high word each), then 1
// when the model is the scan turned y-up. Null when there is no model (a chunked one's head not in
// yet) or it records none.
const std::uint32_t* octopoint_web_walk_cube(void);
// Puts the eye at that point looking yaw, pitch, roll, with that vertical field of view (10..120
// degrees, in thousandths); refused when the eye is more than 128 cube edges from the centre.
int octopoint_web_walk_place(std::int32_t x_low, std::int32_t x_high, std::int32_t y_low,
                             std::int32_t y_high, std::int32_t z_low, std::int32_t z_high,
                             std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                             std::int32_t roll_millidegrees, std::int32_t fov_millidegrees);
// Puts the eye where octopoint-render --perspective puts it for this orbit view (entering walk mode
// from the orbit view, as octopoint-view's Tab); refused, keeping the eye, when it is too far.
int octopoint_web_walk_enter(std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                             std::int32_t roll_millidegrees, std::int32_t zoom_q16,
                             std::int32_t width, std::int32_t height);
// Moves the eye as key `key` (0 forward, 1 back, 2 left, 3 right, 4 up, 5 down) held for
// `held_us` microseconds moves it: the walk speed times the time, along the look's yaw (level),
// at right angles to it, or along the scan's up.
int octopoint_web_walk_move(std::int32_t key, std::int32_t held_us);
// Turns the eye (a drag), in 1/65536 turns: yaw to the right, pitch up (kept within +-90 degrees).
int octopoint_web_walk_turn(std::int32_t yaw_turns16, std::int32_t pitch_turns16);
// The walk speed one step of 5/4 faster (`faster` != 0) or slower: 1/1024 to 64 cube edges a
// second, a quarter at first.
int octopoint_web_walk_faster(std::int32_t faster);
// Draws the eye's frame as octopoint-render --eye draws it (detail by distance, culled, colour on
// its background), the eye first moved by the keys held for the times given (not kept: the page
// moves the eye with octopoint_web_walk_move when a key is let go); `coarse` != 0 draws each part
// a depth coarser (octopoint-view's frames while a key is held). Pixels in octopoint_web_pixels.
int octopoint_web_walk_draw(std::int32_t width, std::int32_t height, std::int32_t coarse,
                            std::int32_t forward_us, std::int32_t back_us, std::int32_t left_us,
                            std::int32_t right_us, std::int32_t up_us, std::int32_t down_us);
// The eye of the last draw (or of the last call that moved it): thirteen words, x, y, z (low, high
// word each), yaw, pitch, roll and the field of view in 1/65536 turns, the speed in Q.24 cube edges
// a second (low, high), and the points the last walk frame drew (the perspective renderer's
// leaves, octopoint-render --eye's "points drawn"; at most 2^32 - 1).
const std::uint32_t* octopoint_web_walk_state(void);
}

namespace octopoint::web {

// The keys octopoint_web_walk_move and octopoint_web_walk_draw know.
inline constexpr int kWalkKeys = 6;

// octopoint_web_draw with the decoder variant given (it draws with defaultVariant()): for the
// native benchmark of the page's draw (bench/web_draw_bench.cpp), fixed_fast against fixed_simd.
int drawWith(Variant variant, std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
             std::int32_t roll_millidegrees, std::int32_t zoom_q16, std::int32_t width,
             std::int32_t height);

}  // namespace octopoint::web

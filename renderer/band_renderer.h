#pragma once
// Band rendering: a frame drawn as horizontal bands of a few rows into a small band buffer, each
// band handed to the display driver as soon as it is finished (like LVGL's partial mode and its
// flush_cb). What a microcontroller does whose RAM cannot hold a whole frame (docs/device.md).
//
// A band of rows [y0, y0 + B) is the whole frame's FrameSetup with root.y reduced by y0 << F and
// height B (bandFrameSetup); the camera's per-level vectors are unchanged. So the decoders and
// their hierarchical clipping draw it unchanged (subtrees outside the band are skipped, leaves
// outside it dropped by the per-pixel clip), every leaf lands on the same pixel as in the whole
// frame, and the concatenated bands are bit-identical to the whole frame for every fixed variant
// (tests/band_renderer_test.cpp proves it at every band height). The float references rebuild
// their set-up from the camera and do not draw bands.
//
// Hole filling reads two rows above and below each pixel: with it, each band is drawn with those
// neighbour rows as margins (band buffer rows B + 4), filled by fillHoleRows, and only its own rows
// are sent, so the filled bands are bit-identical to the filled whole frame too.
//
// With a BandIndex (renderer/band_index.h) a band does not walk the whole tree: the levels above
// the index level are walked (cheap: few nodes), and only the subtrees at the index level that
// meet the band are drawn, each by the same decoder as a tree of its own (its stream is a valid
// stream of depth - level, its root its centre): the additions are the same, so are the pixels.
//
// Nothing here allocates: the band buffers and the fill history are the caller's.

#include <cstddef>
#include <cstdint>
#include <span>

#include "renderer/band_index.h"
#include "renderer/camera.h"
#include "renderer/model.h"
#include "renderer/render.h"
#include "renderer/rgb565.h"

namespace octopoint {

// A band's set-up: `frame`'s with root.y reduced by y0 << F and height `rows`. Refuses (kOverflow)
// a band whose shifted coordinates could leave 32 bits, and rows outside the frame (kBadViewport).
CameraError bandFrameSetup(const FrameSetup& frame, std::int32_t y0, std::int32_t rows, FrameSetup* band);

// Whether `variant` can draw bands (every fixed variant; the float references cannot).
bool supportsBands(Variant variant);

// Where the finished bands go.
struct BandSink {
  void* user = nullptr;
  // A finished band: frame rows [y0, y0 + rows), `rows` * width RGB565 pixels, row-major, each a
  // 16-bit word in the CPU's byte order (swap for a big-endian SPI panel as LVGL's
  // LV_COLOR_16_SWAP does). The bytes live in the band buffer until `wait` says the flush is done.
  void (*flush)(void* user, std::int32_t y0, std::int32_t rows, std::span<const std::uint8_t> rgb565) = nullptr;
  // Optional, for flushes that finish later (DMA): returns once the flush that last read `buffer`
  // has finished. Called before a buffer is drawn into again. Without it a flush must be finished
  // when flush returns.
  void (*wait)(void* user, std::span<const std::uint8_t> buffer) = nullptr;
};

struct BandConfig {
  Variant variant = Variant::kFixedFast;
  std::int32_t band_rows = 24;
  bool fill = false;  // hole filling (renderer/hole_fill.h), as the whole frame's `fill`
  Rgb background{};   // for palette conversion: see Rgb565Palette
};

// Rows above and below each band a post pass reads: hole filling's kHoleFillReachRows, else 0.
// (Line styles over depth and normals would add their reach here.)
std::int32_t bandMarginRows(const BandConfig& config);

// 32-bit words one band buffer needs: (band_rows + 2 * margin) rows of `width` pixels.
std::size_t bandBufferWords(std::int32_t width, const BandConfig& config);

// Two buffers let the next band be drawn while the previous one is still being sent (`second`
// empty: one buffer). `fill_history` (holeFillHistoryWords(width) words) is needed with fill.
struct BandBuffers {
  std::span<std::uint32_t> first;
  std::span<std::uint32_t> second;
  std::span<std::uint32_t> fill_history;
};

enum class BandError : std::uint8_t {
  kNone,
  kUnsupportedVariant,  // a float reference variant
  kBadBandRows,         // band_rows < 1
  kBufferTooSmall,      // a band buffer below bandBufferWords, or the fill history too small
  kOverflow,            // a band's shifted coordinates would leave 32 bits (bandFrameSetup)
  kNoSink,              // no flush callback
  kRefused,             // what renderLevel refuses (renderer/render_check.h: a level of another
                        // depth than the set-up's, an implausible level, a set-up buildFrameSetup
                        // would not make), or an index no tree of the level's depth has or that
                        // does not fit the level (its entries or sizes: found on the first band)
};

const char* describe(BandError error);

// Draws one frame of `level` band by band, top to bottom, and hands each band to `sink`. `index`
// may be empty (level 0). `palette` is the model's palette in RGB565 (makeRgb565Palette).
BandError renderBands(const LevelView& level, const FrameSetup& setup, const BandConfig& config,
                      const BandIndex& index, const Rgb565Palette& palette, const BandBuffers& buffers,
                      const BandSink& sink);

}  // namespace octopoint

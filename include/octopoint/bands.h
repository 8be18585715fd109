#pragma once
// octopoint/bands.h: Drawing in horizontal bands into a small buffer, for microcontrollers (RGB565
// to a display). The manual of the whole library is octopoint/octopoint.h.

#include <cstddef>
#include <cstdint>
#include <span>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"

// Where the subtrees of one tree level end in a level's depth-first stream: what lets band
// rendering (octopoint/bands.h) jump straight to the subtrees that meet a band instead of
// stepping over the bytes of every other one, once per band.
//
// A depth-first stream has no index: a subtree's bytes can only be passed by reading them all
// (skipSubtree). The index remembers, for every node at `level` in stream order, how many node
// bytes and leaves its subtree has; the band walk reaches the subtrees in stream order, so it knows
// where each begins and, with its size, where it ends. Sizes fit 16 bits when the subtree has at
// most 5 levels (at most 4,681 nodes and 32,768 leaves), so the index costs 4 bytes per node of
// its level. It depends on the model only, not on the camera: build it once at set-up, into memory
// the caller provides, and keep it for every frame. Level 0 needs no memory and means "no index":
// each band then walks the whole tree.

namespace octopoint {

struct SubtreeSize {
  std::uint16_t nodes;   // mask bytes of the subtree
  std::uint16_t leaves;  // its leaves
};

// The most levels an indexed subtree may have: its sizes must fit SubtreeSize.
inline constexpr int kMaxIndexedSubtreeLevels = 5;

struct BandIndex {
  int level = 0;                       // 0: no index; else depth - 5 .. depth - 2, at least 1
  std::span<const SubtreeSize> sizes;  // one per node at `level`, in stream order
};

// The number of nodes at each tree level 0..depth-1 (`counts` has at least level.depth entries).
void countNodesPerLevel(const LevelView& level, std::span<std::uint32_t> counts);

// Whether an index can be built at `index_level` for a level of `depth`: below the root, above the
// leaf parents' parents, and its subtrees at most kMaxIndexedSubtreeLevels deep.
[[nodiscard]] bool indexLevelAllowed(int depth, int index_level);

// The deepest allowed index level whose nodes fit `capacity` entries, 0 when none does.
int deepestIndexLevel(const LevelView& level, std::size_t capacity);

// Fills `storage` with the sizes of the subtrees at `index_level` and returns the index, or an
// index of level 0 when the level is not allowed or its nodes do not fit.
BandIndex buildBandIndex(const LevelView& level, int index_level, std::span<SubtreeSize> storage);

}  // namespace octopoint

// Band rendering: a frame drawn as horizontal bands of a few rows into a small band buffer, each
// band handed to the display driver as soon as it is finished (like LVGL's partial mode and its
// flush_cb). What a microcontroller does whose RAM cannot hold a whole frame (docs/device.md).
//
// A band of rows [y0, y0 + B) is the whole frame's FrameSetup with root.y reduced by y0 << F and
// height B (bandFrameSetup); the camera's per-level vectors are unchanged. So the decoders and
// their hierarchical clipping draw it unchanged (subtrees outside the band are skipped, leaves
// outside it dropped by the per-pixel clip), every leaf lands on the same pixel as in the whole
// frame, and the concatenated bands are bit-identical to the whole frame for every fixed variant
// (tests/core/band_renderer_test.cpp proves it at every band height). The float references rebuild
// their set-up from the camera and do not draw bands.
//
// Hole filling reads two rows above and below each pixel: with it, each band is drawn with those
// neighbour rows as margins (band buffer rows B + 4), filled by fillHoleRows, and only its own rows
// are sent, so the filled bands are bit-identical to the filled whole frame too.
//
// With a BandIndex (octopoint/bands.h) a band does not walk the whole tree: the levels above
// the index level are walked (cheap: few nodes), and only the subtrees at the index level that
// meet the band are drawn, each by the same decoder as a tree of its own (its stream is a valid
// stream of depth - level, its root its centre): the additions are the same, so are the pixels.
//
// Nothing here allocates: the band buffers and the fill history are the caller's.

namespace octopoint {

// A band's set-up: `frame`'s with root.y reduced by y0 << F and height `rows`. Refuses (kOverflow)
// a band whose shifted coordinates could leave 32 bits, and rows outside the frame (kBadViewport).
[[nodiscard]] CameraError bandFrameSetup(const FrameSetup& frame, std::int32_t y0,
                                         std::int32_t rows, FrameSetup* band);

// Whether `variant` can draw bands (every fixed variant; the float references cannot).
[[nodiscard]] bool supportsBands(Variant variant);

// Where the finished bands go.
struct BandSink {
  void* user = nullptr;
  // A finished band: frame rows [y0, y0 + rows), `rows` * width RGB565 pixels, row-major, each a
  // 16-bit word in the CPU's byte order (swap for a big-endian SPI panel as LVGL's
  // LV_COLOR_16_SWAP does). The bytes live in the band buffer until `wait` says the flush is done.
  void (*flush)(void* user, std::int32_t y0, std::int32_t rows,
                std::span<const std::uint8_t> rgb565) = nullptr;
  // Optional, for flushes that finish later (DMA): returns once the flush that last read `buffer`
  // has finished. Called before a buffer is drawn into again. Without it a flush must be finished
  // when flush returns.
  void (*wait)(void* user, std::span<const std::uint8_t> buffer) = nullptr;
};

struct BandConfig {
  Variant variant = Variant::kFixedFast;
  std::int32_t band_rows = 24;
  bool fill = false;  // hole filling (octopoint/render.h), as the whole frame's `fill`
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
  kRefused,             // what renderLevel refuses (octopoint/render.h: a level of another
                        // depth than the set-up's, an implausible level, a set-up buildFrameSetup
                        // would not make), or an index no tree of the level's depth has or that
                        // does not fit the level (its entries or sizes: found on the first band)
};

const char* describe(BandError error);

// Draws one frame of `level` band by band, top to bottom, and hands each band to `sink`. `index`
// may be empty (level 0). `palette` is the model's palette in RGB565 (makeRgb565Palette).
[[nodiscard]] BandError renderBands(const LevelView& level, const FrameSetup& setup,
                                    const BandConfig& config, const BandIndex& index,
                                    const Rgb565Palette& palette, const BandBuffers& buffers,
                                    const BandSink& sink);

// renderBands with smooth splats (octopoint/smooth.h, docs/splats.md "Smooth splats"): each band's
// box frame is blended before it becomes RGB565, bit-identical to the whole frame's blend
// (SmoothSplats::resolveToRgb565 of renderSmooth's frame). A band needs no margin: a pixel's blend
// reads its own nearest depth and the leaves within the kernel's reach, which the blend's own walk
// of the level finds whatever band it draws. `smooth` must be made for frames `setup.width` wide
// and at least `config.band_rows` high (16 bytes a pixel of a band); `colours` is the model's
// palette (paletteOf). Colour frames only, without hole filling (kRefused). A device without a
// heap makes `smooth` in its own memory (SmoothSplats::Memory; docs/device.md).
[[nodiscard]] BandError renderSmoothBands(const LevelView& level, const FrameSetup& setup,
                                          const BandConfig& config, const BandIndex& index,
                                          const Rgb565Palette& palette, const PaletteRgb& colours,
                                          const BandBuffers& buffers, SmoothSplats& smooth,
                                          const BandSink& sink);

}  // namespace octopoint

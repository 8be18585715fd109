#pragma once
// octopoint/framebuffer.h: The framebuffer (depth key and palette index per pixel) and its
// conversions to RGB565. The manual of the whole library is octopoint/octopoint.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/model.h"

// A frame of palette indices with its z-buffer, packed into one 32-bit word per pixel: the depth
// key (FrameSetup::depthKey, 24 bits, smaller is nearer) in the high bits, the palette index in the
// low 8. A frame drawn for a style that lights the model (octopoint/styles.h) also carries each
// pixel's normal index: PixelPayload::kColourNormal keeps the depth key's top 16 bits, the normal
// index and the palette index. Nearest-wins is then one unsigned comparison of whole words, and
// equal depths go to the smaller palette index: the frame is the same whatever order the points
// arrive in, which lets decoders visit, batch and reorder freely and still draw bit-identical
// frames. One array instead of two halves the memory a plotted point touches. Memory is allocated
// once, at construction; a frame only clears and writes it, so drawing never allocates.
//
// A frame keeps the rectangle its writers may have written since the last clear (drawnRect):
// every pixel outside it is kEmpty, so clear() empties that rectangle only, and a frame's clear
// costs what was drawn, not the frame's size (a zoomed-out model on a 1920x1080 frame covers a
// few percent of it). Writers say where they write: the decoders through PlotTarget with the
// set-up's bounds (renderer/framebuffer_plot.h), O(1) per frame; pixelData() without bounds makes
// the whole frame count as drawn. Readers see kEmpty outside, as if every pixel had been cleared.

namespace octopoint {

// Columns [x_begin, x_end) and rows [y_begin, y_end) of a frame; empty when either range is.
struct PixelRect {
  std::int32_t x_begin = 0;
  std::int32_t x_end = 0;
  std::int32_t y_begin = 0;
  std::int32_t y_end = 0;

  bool empty() const { return x_begin >= x_end || y_begin >= y_end; }
};

// What a pixel word holds besides the depth (FrameView::clear chooses it for a frame).
enum class PixelPayload : std::uint8_t {
  kColour,        // bits 31..8: depth key; 7..0: palette index
  kColourNormal,  // bits 31..16: the depth key's top 16 bits; 15..8: normal index; 7..0: palette
                  // index
};

// A frame's pixels in memory someone else owns: what the decoders, the hole filler and the band
// renderer (octopoint/bands.h) draw into. A band renderer points it at a caller-provided band
// buffer, so drawing on a device needs no heap.
class FrameView {
 public:
  static constexpr std::uint32_t kEmpty = 0xFFFF'FFFF;  // no point: farther than any real word
  // Key 2^24 - 1 is left to kEmpty, so that a real point's word is always below it.
  static constexpr std::uint32_t kMaxDepthKey = (std::uint32_t{1} << 24) - 2;

  static constexpr std::uint32_t pack(std::uint32_t depth_key, std::uint8_t colour_index) {
    return depth_key << 8 | colour_index;
  }
  // In a kColourNormal frame the key's low 8 bits are the normal index: within 255 of the key.
  static constexpr std::uint32_t depthKeyOf(std::uint32_t word) { return word >> 8; }
  static constexpr std::uint8_t colourIndexOf(std::uint32_t word) {
    return static_cast<std::uint8_t>(word & 0xFF);
  }
  // PixelPayload::kColourNormal: the depth key keeps 16 bits (one step is 256 of kColour's), the
  // normal index takes the freed byte. The word of a leaf with `payload` = palette index | normal
  // index << 8 is then the key's top 16 bits above the payload: one mask, no extra shift. Normal
  // indices stop at 254 (format::kMaxNormals), so no word equals kEmpty.
  static constexpr std::uint32_t kColourNormalKeyMask = 0xFFFF'0000;
  static constexpr std::uint32_t packColourNormal(std::uint32_t depth_key, std::uint32_t payload) {
    return (depth_key << 8 & kColourNormalKeyMask) | payload;
  }
  // The word of a leaf whose payload (palette index, and normal index << 8 where the frame
  // carries normals) is `payload`, for a frame of payload `kPayload`.
  template <PixelPayload kPayload>
  static constexpr std::uint32_t packLeaf(std::uint32_t depth_key, std::uint32_t payload) {
    if constexpr (kPayload == PixelPayload::kColour) return depth_key << 8 | payload;
    return packColourNormal(depth_key, payload);
  }
  // Only meaningful in a PixelPayload::kColourNormal frame.
  static constexpr std::uint8_t normalIndexOf(std::uint32_t word) {
    return static_cast<std::uint8_t>(word >> 8 & 0xFF);
  }

  // `pixels` holds width * height words, row-major. What they hold is not known, so the whole view
  // counts as drawn until the first clear.
  FrameView(std::uint32_t* pixels, std::int32_t width, std::int32_t height)
      : pixel_(pixels), width_(width), height_(height), drawn_{0, width, 0, height} {}

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  // Empties every pixel, by writing kEmpty over drawnRect() only (the rest already is), and sets
  // what the next drawing writes besides the depth: a frame that is to be lit or outlined with
  // creases (octopoint/styles.h) needs kColourNormal, and a model with normals
  // (ModelView::hasNormals) to draw into it.
  void clear(PixelPayload payload = PixelPayload::kColour);
  PixelPayload payload() const { return payload_; }
  // The pixels written since the last clear may lie only in here; every other pixel is kEmpty.
  const PixelRect& drawnRect() const { return drawn_; }

  // Keeps the nearest point per pixel; off-screen points are dropped. `depth_key` <= kMaxDepthKey.
  void plot(std::int32_t x, std::int32_t y, std::uint32_t depth_key, std::uint8_t colour_index) {
    if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width_) ||
        static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height_)) {
      return;
    }
    widenDrawnRect({x, x + 1, y, y + 1});
    std::uint32_t& word = pixel_[indexOf(x, y)];
    const std::uint32_t candidate = pack(depth_key, colour_index);
    if (candidate < word) word = candidate;
  }

  bool covered(std::int32_t x, std::int32_t y) const { return pixelAt(x, y) != kEmpty; }
  std::uint32_t pixelAt(std::int32_t x, std::int32_t y) const { return pixel_[indexOf(x, y)]; }
  std::uint32_t depthKeyAt(std::int32_t x, std::int32_t y) const {
    return depthKeyOf(pixelAt(x, y));
  }
  std::uint8_t colourIndexAt(std::int32_t x, std::int32_t y) const {
    return colourIndexOf(pixelAt(x, y));
  }
  std::uint8_t normalIndexAt(std::int32_t x, std::int32_t y) const {  // kColourNormal frames
    return normalIndexOf(pixelAt(x, y));
  }
  // Row-major packed words, kEmpty where nothing was drawn.
  std::span<const std::uint32_t> pixels() const { return {pixel_, pixelCount()}; }
  // Raw write access for a writer that writes only inside `bounds` (clipped to the frame here):
  // the decoders' plotters (renderer/framebuffer_plot.h) with their set-up's bounds, the hole
  // filler inside drawnRect(). Widens drawnRect() to include them.
  std::uint32_t* pixelsToDraw(const PixelRect& bounds) {
    widenDrawnRect(bounds);
    return pixel_;
  }
  // Raw write access anywhere: the whole frame counts as drawn until the next clear.
  std::uint32_t* pixelData() { return pixelsToDraw({0, width_, 0, height_}); }

 protected:
  std::size_t pixelCount() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }
  std::size_t indexOf(std::int32_t x, std::int32_t y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }

  void widenDrawnRect(const PixelRect& bounds);

  std::uint32_t* pixel_;
  std::int32_t width_;
  std::int32_t height_;
  PixelRect drawn_;  // see drawnRect(); empty: the whole frame is kEmpty
  PixelPayload payload_ = PixelPayload::kColour;
};

// Sets `count` words to `value`: a frame's clear, also on bare metal (where memset is a byte loop).
void fillWords(std::uint32_t* words, std::size_t count, std::uint32_t value);

// A frame that owns its pixels (allocated once, at construction, all kEmpty: nothing drawn yet).
class Framebuffer : public FrameView {
 public:
  // A frame of width x height pixels, each 1..kMaxViewportSide (octopoint/camera.h); any other size
  // gives an empty 0 x 0 frame, which every drawing call refuses (it fits no frame set-up).
  Framebuffer(std::int32_t width, std::int32_t height);
  // A frame of the set-up's size: the size given once, where the set-up was built.
  explicit Framebuffer(const FrameSetup& setup);
  Framebuffer(const Framebuffer& other);
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(const Framebuffer& other);
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  ~Framebuffer() = default;

 private:
  std::vector<std::uint32_t> storage_;
};

// Turns a frame into RGB888 (3 bytes per pixel, row-major): covered pixels get their palette
// colour, empty ones `background`. `rgb` must hold at least width * height * 3 bytes: otherwise
// nothing is written and the result is false.
[[nodiscard]] bool resolveToRgb(const FrameView& frame, const ModelView& model, Rgb background,
                                std::span<std::uint8_t> rgb);

}  // namespace octopoint

// RGB565, the pixel format of the small SPI panels (ILI9341, ST7789) a microcontroller drives: five
// bits of red, six of green, five of blue in one 16-bit word. Band rendering
// (octopoint/bands.h) converts each finished band to it in place, through a 256-entry table
// built once per model at set-up, so a pixel costs one table load.

namespace octopoint {

constexpr std::uint16_t toRgb565(Rgb colour) {
  return static_cast<std::uint16_t>((colour.r >> 3) << 11 | (colour.g >> 2) << 5 | colour.b >> 3);
}

struct Rgb565Palette {
  std::array<std::uint16_t, 256> colour{};  // by palette index
  std::uint16_t background = 0;             // for pixels without a point
  // No leaf names index 255 (the model has at most 255 colours). An empty pixel's word
  // (FrameView::kEmpty) has 255 in its palette-index byte, so with colour[255] == background the
  // conversion needs no emptiness test: one table load per pixel (makeRgb565Palette sets both).
  bool last_index_unused = false;
};

Rgb565Palette makeRgb565Palette(const ModelView& model, Rgb background);

// Converts `count` packed pixel words to RGB565 halfwords in the CPU's byte order, writing halfword
// i to bytes 2i and 2i + 1 of `out` (2-byte aligned). `out` may be the words' own memory (then the
// band becomes its RGB565 image in its first half): halfword i lands in bytes a word that was
// already read held.
void packedToRgb565(const std::uint32_t* words, std::size_t count, const Rgb565Palette& palette,
                    std::uint8_t* out);

}  // namespace octopoint

#pragma once
// A frame of palette indices with its z-buffer, packed into one 32-bit word per pixel: the depth
// key (FrameSetup::depthKey, 24 bits, smaller is nearer) in the high bits, the palette index in the
// low 8. Nearest-wins is then one unsigned comparison of whole words, and equal depths go to the
// smaller palette index: the frame is the same whatever order the points arrive in, which lets
// decoders visit, batch and reorder freely and still draw bit-identical frames. One array instead
// of two halves the memory a plotted point touches. Memory is allocated once, at construction; a
// frame only clears and writes it, so drawing never allocates.

#include <cstdint>
#include <span>
#include <vector>

#include "renderer/camera.h"
#include "renderer/model.h"

namespace octopoint {

// A frame's pixels in memory someone else owns: what the decoders, the hole filler and the band
// renderer (renderer/band_renderer.h) draw into. A band renderer points it at a caller-provided band
// buffer, so drawing on a device needs no heap.
class FrameView {
 public:
  static constexpr std::uint32_t kEmpty = 0xFFFF'FFFF;  // no point: farther than any real word
  // Key 2^24 - 1 is left to kEmpty, so that a real point's word is always below it.
  static constexpr std::uint32_t kMaxDepthKey = (std::uint32_t{1} << 24) - 2;

  static constexpr std::uint32_t pack(std::uint32_t depth_key, std::uint8_t colour_index) {
    return depth_key << 8 | colour_index;
  }
  static constexpr std::uint32_t depthKeyOf(std::uint32_t word) { return word >> 8; }
  static constexpr std::uint8_t colourIndexOf(std::uint32_t word) {
    return static_cast<std::uint8_t>(word & 0xFF);
  }

  // `pixels` holds width * height words, row-major.
  FrameView(std::uint32_t* pixels, std::int32_t width, std::int32_t height)
      : pixel_(pixels), width_(width), height_(height) {}

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  void clear();

  // Keeps the nearest point per pixel; off-screen points are dropped. `depth_key` <= kMaxDepthKey.
  void plot(std::int32_t x, std::int32_t y, std::uint32_t depth_key, std::uint8_t colour_index) {
    if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width_) ||
        static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height_)) {
      return;
    }
    std::uint32_t& word = pixel_[indexOf(x, y)];
    const std::uint32_t candidate = pack(depth_key, colour_index);
    if (candidate < word) word = candidate;
  }

  bool covered(std::int32_t x, std::int32_t y) const { return pixelAt(x, y) != kEmpty; }
  std::uint32_t pixelAt(std::int32_t x, std::int32_t y) const { return pixel_[indexOf(x, y)]; }
  std::uint32_t depthKeyAt(std::int32_t x, std::int32_t y) const { return depthKeyOf(pixelAt(x, y)); }
  std::uint8_t colourIndexAt(std::int32_t x, std::int32_t y) const {
    return colourIndexOf(pixelAt(x, y));
  }
  // Row-major packed words, kEmpty where nothing was drawn.
  std::span<const std::uint32_t> pixels() const { return {pixel_, pixelCount()}; }
  // Raw access for the decoders' plotters (renderer/framebuffer_plot.h) and the hole filler.
  std::uint32_t* pixelData() { return pixel_; }

 protected:
  std::size_t pixelCount() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }
  std::size_t indexOf(std::int32_t x, std::int32_t y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }

  std::uint32_t* pixel_;
  std::int32_t width_;
  std::int32_t height_;
};

// A frame that owns its pixels (allocated once, at construction).
class Framebuffer : public FrameView {
 public:
  // A frame of width x height pixels, each 1..kMaxViewportSide (renderer/camera.h); any other size
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
bool resolveToRgb(const FrameView& frame, const ModelView& model, Rgb background,
                  std::span<std::uint8_t> rgb);

}  // namespace octopoint

#pragma once
// A frame of palette indices with its z-buffer. Memory is allocated once, at construction; a
// frame only clears and writes it, so drawing never allocates.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "renderer/model.h"

namespace octopoint {

class Framebuffer {
 public:
  static constexpr std::int32_t kEmptyDepth = std::numeric_limits<std::int32_t>::max();

  Framebuffer(std::int32_t width, std::int32_t height);

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  void clear();

  // Keeps the nearest point per pixel (smaller z is nearer); off-screen points are dropped.
  void plot(std::int32_t x, std::int32_t y, std::int32_t z, std::uint8_t colour_index) {
    if (static_cast<std::uint32_t>(x) >= static_cast<std::uint32_t>(width_) ||
        static_cast<std::uint32_t>(y) >= static_cast<std::uint32_t>(height_)) {
      return;
    }
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                           static_cast<std::size_t>(x);
    if (z < depth_[at]) {
      depth_[at] = z;
      colour_index_[at] = colour_index;
    }
  }

  bool covered(std::int32_t x, std::int32_t y) const { return depthAt(x, y) != kEmptyDepth; }
  std::int32_t depthAt(std::int32_t x, std::int32_t y) const { return depth_[indexOf(x, y)]; }
  std::uint8_t colourIndexAt(std::int32_t x, std::int32_t y) const {
    return colour_index_[indexOf(x, y)];
  }
  std::span<const std::uint8_t> colourIndices() const { return colour_index_; }
  // Raw access for the decoders' plotters (renderer/framebuffer_plot.h).
  std::uint8_t* colourIndexData() { return colour_index_.data(); }
  std::int32_t* depthData() { return depth_.data(); }
  std::span<const std::int32_t> depths() const { return depth_; }

 private:
  std::size_t indexOf(std::int32_t x, std::int32_t y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }

  std::int32_t width_;
  std::int32_t height_;
  std::vector<std::uint8_t> colour_index_;
  std::vector<std::int32_t> depth_;
};

// Turns a frame into RGB888 (3 bytes per pixel, row-major): covered pixels get their palette
// colour, empty ones `background`. `rgb` must hold width * height * 3 bytes.
void resolveToRgb(const Framebuffer& frame, const ModelView& model, Rgb background,
                  std::span<std::uint8_t> rgb);

}  // namespace octopoint

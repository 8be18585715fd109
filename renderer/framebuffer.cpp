#include "renderer/framebuffer.h"

#include <algorithm>
#include <cassert>

namespace octopoint {

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height)
    : width_(width),
      height_(height),
      colour_index_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0),
      depth_(colour_index_.size(), kEmptyDepth) {
  assert(width > 0 && height > 0);
}

void Framebuffer::clear() {
  std::fill(colour_index_.begin(), colour_index_.end(), std::uint8_t{0});
  std::fill(depth_.begin(), depth_.end(), kEmptyDepth);
}

void resolveToRgb(const Framebuffer& frame, const ModelView& model, Rgb background,
                  std::span<std::uint8_t> rgb) {
  const std::span<const std::uint8_t> indices = frame.colourIndices();
  const std::span<const std::int32_t> depths = frame.depths();
  assert(rgb.size() >= indices.size() * 3);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const Rgb colour =
        depths[i] == Framebuffer::kEmptyDepth ? background : model.paletteColour(indices[i]);
    rgb[3 * i + 0] = colour.r;
    rgb[3 * i + 1] = colour.g;
    rgb[3 * i + 2] = colour.b;
  }
}

}  // namespace octopoint

#include "renderer/framebuffer.h"

#include <algorithm>
#include <cassert>

namespace octopoint {

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height)
    : width_(width),
      height_(height),
      pixel_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kEmpty) {
  assert(width > 0 && height > 0);
}

void Framebuffer::clear() { std::fill(pixel_.begin(), pixel_.end(), kEmpty); }

void resolveToRgb(const Framebuffer& frame, const ModelView& model, Rgb background,
                  std::span<std::uint8_t> rgb) {
  const std::span<const std::uint32_t> pixels = frame.pixels();
  assert(rgb.size() >= pixels.size() * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const Rgb colour = pixels[i] == Framebuffer::kEmpty
                           ? background
                           : model.paletteColour(Framebuffer::colourIndexOf(pixels[i]));
    rgb[3 * i + 0] = colour.r;
    rgb[3 * i + 1] = colour.g;
    rgb[3 * i + 2] = colour.b;
  }
}

}  // namespace octopoint

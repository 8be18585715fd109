#include "renderer/framebuffer.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace octopoint {

void FrameView::clear() { std::fill(pixel_, pixel_ + pixelCount(), kEmpty); }

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height)
    : FrameView(nullptr, width, height),
      storage_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kEmpty) {
  assert(width > 0 && height > 0);
  pixel_ = storage_.data();
}

// The view's pointer always names this object's own storage, never the source's.
Framebuffer::Framebuffer(const Framebuffer& other) : FrameView(other), storage_(other.storage_) {
  pixel_ = storage_.data();
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : FrameView(other), storage_(std::move(other.storage_)) {
  pixel_ = storage_.data();
  other.pixel_ = nullptr;
  other.width_ = other.height_ = 0;
}

Framebuffer& Framebuffer::operator=(const Framebuffer& other) {
  if (this != &other) {
    FrameView::operator=(other);
    storage_ = other.storage_;
    pixel_ = storage_.data();
  }
  return *this;
}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    FrameView::operator=(other);
    storage_ = std::move(other.storage_);
    pixel_ = storage_.data();
    other.pixel_ = nullptr;
    other.width_ = other.height_ = 0;
  }
  return *this;
}

void resolveToRgb(const FrameView& frame, const ModelView& model, Rgb background,
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

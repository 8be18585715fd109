#include "renderer/framebuffer.h"

#include <algorithm>
#include <utility>

namespace octopoint {

void FrameView::clear() { std::fill(pixel_, pixel_ + pixelCount(), kEmpty); }

namespace {

bool validSize(std::int32_t width, std::int32_t height) {
  return width >= 1 && width <= kMaxViewportSide && height >= 1 && height <= kMaxViewportSide;
}

}  // namespace

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height)
    : FrameView(nullptr, validSize(width, height) ? width : 0, validSize(width, height) ? height : 0),
      storage_(pixelCount(), kEmpty) {
  pixel_ = storage_.data();
}

Framebuffer::Framebuffer(const FrameSetup& setup) : Framebuffer(setup.width, setup.height) {}

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

bool resolveToRgb(const FrameView& frame, const ModelView& model, Rgb background,
                  std::span<std::uint8_t> rgb) {
  const std::span<const std::uint32_t> pixels = frame.pixels();
  if (rgb.size() < pixels.size() * 3) return false;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const Rgb colour = pixels[i] == Framebuffer::kEmpty
                           ? background
                           : model.paletteColour(Framebuffer::colourIndexOf(pixels[i]));
    rgb[3 * i + 0] = colour.r;
    rgb[3 * i + 1] = colour.g;
    rgb[3 * i + 2] = colour.b;
  }
  return true;
}

}  // namespace octopoint

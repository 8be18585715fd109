#include "octopoint/framebuffer.h"

#include <algorithm>
#include <utility>

namespace octopoint {

void FrameView::clear(PixelPayload payload) {
  payload_ = payload;
  if (drawn_.empty()) return;
  const auto columns = static_cast<std::size_t>(drawn_.x_end - drawn_.x_begin);
  std::uint32_t* const first = pixel_ + indexOf(drawn_.x_begin, drawn_.y_begin);
  const auto rows = static_cast<std::size_t>(drawn_.y_end - drawn_.y_begin);
  if (columns == static_cast<std::size_t>(width_)) {  // whole rows: one contiguous run
    fillWords(first, columns * rows, kEmpty);
  } else {
    for (std::size_t row = 0; row < rows; ++row) {
      std::uint32_t* const begin = first + row * static_cast<std::size_t>(width_);
      fillWords(begin, columns, kEmpty);
    }
  }
  drawn_ = PixelRect{};
}

void FrameView::widenDrawnRect(const PixelRect& bounds) {
  const PixelRect clipped{std::max<std::int32_t>(bounds.x_begin, 0), std::min(bounds.x_end, width_),
                          std::max<std::int32_t>(bounds.y_begin, 0),
                          std::min(bounds.y_end, height_)};
  if (clipped.empty()) return;
  if (drawn_.empty()) {
    drawn_ = clipped;
    return;
  }
  drawn_ =
      PixelRect{std::min(drawn_.x_begin, clipped.x_begin), std::max(drawn_.x_end, clipped.x_end),
                std::min(drawn_.y_begin, clipped.y_begin), std::max(drawn_.y_end, clipped.y_end)};
}

void fillWords(std::uint32_t* words, std::size_t count, std::uint32_t value) {
  // Eight stores a step with constant offsets: on a Cortex-M0+ 1.5 instructions a word instead of
  // 3 (the bare-metal build keeps GCC from turning this into newlib nano's byte-wise memset,
  // cmake/toolchain-arm-none-eabi.cmake).
  std::uint32_t* const end = words + count;
  for (; end - words >= 8; words += 8) {
    words[0] = value;
    words[1] = value;
    words[2] = value;
    words[3] = value;
    words[4] = value;
    words[5] = value;
    words[6] = value;
    words[7] = value;
  }
  for (; words != end; ++words) *words = value;
}

namespace {

bool validSize(std::int32_t width, std::int32_t height) {
  return width >= 1 && width <= kMaxViewportSide && height >= 1 && height <= kMaxViewportSide;
}

}  // namespace

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height)
    : FrameView(nullptr, validSize(width, height) ? width : 0,
                validSize(width, height) ? height : 0),
      storage_(pixelCount(), kEmpty) {
  pixel_ = storage_.data();
  drawn_ = PixelRect{};  // every pixel starts kEmpty
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
  other.drawn_ = PixelRect{};
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
    other.drawn_ = PixelRect{};
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

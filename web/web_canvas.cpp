// The frame, the pixels and the message the page's two models share (web/web_canvas.h).
#include "web/web_canvas.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <utility>

namespace octopoint::web {

Framebuffer& Canvas::sized(std::int32_t width, std::int32_t height) {
  if (!frame || frame->width() != width || frame->height() != height) {
    frame.emplace(width, height);
    rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    stale_ = PixelRect{0, width, 0, height};  // what rgba holds is not this size's frame
  }
  return *frame;
}

bool sizeAllowed(std::int32_t width, std::int32_t height) {
  // The most pixels octopoint-render writes in a frame (it allows sides up to 8192).
  constexpr std::int64_t kMaxPixels = std::int64_t{4096} * 4096;
  return width >= 1 && height >= 1 && width <= kMaxViewportSide && height <= kMaxViewportSide &&
         std::int64_t{width} * height <= kMaxPixels;
}

namespace {

// A pixel's R, G, B and A bytes as one word in memory order, whatever the CPU's byte order.
std::uint32_t rgbaWord(Rgb colour) {
  const std::array<std::uint8_t, 4> bytes{colour.r, colour.g, colour.b, 255};
  std::uint32_t word = 0;
  std::memcpy(&word, bytes.data(), bytes.size());
  return word;
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x_begin, b.x_begin), std::max(a.x_end, b.x_end),
          std::min(a.y_begin, b.y_begin), std::max(a.y_end, b.y_end)};
}

// Writes `paint(word)` for every pixel of `rect` of `frame` into the same place of `out`.
template <typename Paint>
void paintRect(const FrameView& frame, const PixelRect& rect, std::uint32_t* out, Paint paint) {
  const auto width = static_cast<std::size_t>(frame.width());
  const std::uint32_t* const words = frame.pixels().data();
  for (std::int32_t y = rect.y_begin; y < rect.y_end; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    const std::uint32_t* const end = words + row + static_cast<std::size_t>(rect.x_end);
    std::uint32_t* to = out + row + static_cast<std::size_t>(rect.x_begin);
    for (const std::uint32_t* word = words + row + static_cast<std::size_t>(rect.x_begin);
         word != end; ++word, ++to) {
      *to = paint(*word);
    }
  }
}

}  // namespace

void Canvas::resolveColour(const ModelView& model, Rgb background) {
  const FrameView& drawn = *frame;
  std::array<std::uint32_t, 256> colour{};
  for (int i = 0; i < model.paletteCount(); ++i) {
    colour[static_cast<std::size_t>(i)] = rgbaWord(model.paletteColour(i));
  }
  const std::uint32_t back = rgbaWord(background);
  if (back != background_) stale_ = PixelRect{0, drawn.width(), 0, drawn.height()};
  const PixelRect rect = unite(stale_, drawn.drawnRect());
  if (model.paletteCount() < 256) {
    // An empty pixel's word (FrameView::kEmpty) has 255 in its palette-index byte, which no leaf
    // names in a model of fewer colours: with entry 255 the background, no test for emptiness.
    colour[255] = back;
    paintRect(drawn, rect, rgba.data(),
              [&colour](std::uint32_t word) { return colour[FrameView::colourIndexOf(word)]; });
  } else {
    paintRect(drawn, rect, rgba.data(), [&colour, back](std::uint32_t word) {
      return word == FrameView::kEmpty ? back : colour[FrameView::colourIndexOf(word)];
    });
  }
  stale_ = drawn.drawnRect();
  background_ = back;
}

std::span<std::uint8_t> Canvas::rgbToWrite() {
  rgb.resize(rgba.size() * 3);
  return rgb;
}

void Canvas::toRgba() {
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    rgba[i] = rgbaWord(Rgb{rgb[i * 3 + 0], rgb[i * 3 + 1], rgb[i * 3 + 2]});
  }
  stale_ = PixelRect{0, frame->width(), 0, frame->height()};  // not (only) the background
}

Canvas& canvas() {
  static Canvas instance;
  return instance;
}

namespace {
std::string g_error;
}  // namespace

const char* errorText() { return g_error.c_str(); }

int fail(std::string message) {
  g_error = std::move(message);
  return -1;
}

int succeed() {
  g_error.clear();
  return 0;
}

}  // namespace octopoint::web

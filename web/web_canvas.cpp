// The frame, the pixels and the message the page's two models share (web/web_canvas.h).
#include "web/web_canvas.h"

#include <string>
#include <utility>

namespace octopoint::web {

Framebuffer& Canvas::sized(std::int32_t width, std::int32_t height) {
  if (!frame || frame->width() != width || frame->height() != height) frame.emplace(width, height);
  rgb.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  return *frame;
}

bool sizeAllowed(std::int32_t width, std::int32_t height) {
  // The most pixels octopoint-render writes in a frame (it allows sides up to 8192).
  constexpr std::int64_t kMaxPixels = std::int64_t{4096} * 4096;
  return width >= 1 && height >= 1 && width <= kMaxViewportSide && height <= kMaxViewportSide &&
         std::int64_t{width} * height <= kMaxPixels;
}

void Canvas::toRgba() {
  const std::size_t pixels = rgb.size() / 3;
  rgba.resize(pixels * 4);
  for (std::size_t i = 0; i < pixels; ++i) {
    rgba[i * 4 + 0] = rgb[i * 3 + 0];
    rgba[i * 4 + 1] = rgb[i * 3 + 1];
    rgba[i * 4 + 2] = rgb[i * 3 + 2];
    rgba[i * 4 + 3] = 255;
  }
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

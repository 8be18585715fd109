// The frame, the pixels and the message the page's two models share (web/web_canvas.h).
#include "web/web_canvas.h"

#include <string>
#include <utility>

namespace octopoint::web {

Framebuffer& Canvas::sized(const Camera& camera) {
  if (!frame || frame->width() != camera.width || frame->height() != camera.height)
    frame.emplace(camera.width, camera.height);
  rgb.resize(static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height) * 3);
  return *frame;
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

#include "tools/view_window.h"

#include <SDL2/SDL_syswm.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

namespace octopoint {
namespace {

std::string sdlError(const std::string& what) { return what + ": " + SDL_GetError(); }

std::int64_t steadyMilliseconds() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

// Left to itself, SDL tries every video driver it has and ends with "offscreen", an invisible
// window, when there is no display. Unless the user picks a driver (SDL_VIDEODRIVER), take the one
// the environment names, or refuse.
void chooseVideoDriver() {
  const auto set = [](const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0';
  };
  if (set("SDL_VIDEODRIVER")) return;
  if (set("DISPLAY")) {
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
  } else if (set("WAYLAND_DISPLAY")) {
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "wayland");
  } else {
    throw WindowError(
        "cannot open a window: no display (neither DISPLAY nor WAYLAND_DISPLAY is set; "
        "SDL_VIDEODRIVER picks another SDL video driver, e.g. kmsdrm)");
  }
}

ViewWindow::ViewWindow(const std::string& title, int width, int height, int min_width,
                       int min_height) {
  chooseVideoDriver();
  // The window surface in memory (X11: shared memory images), not behind an OpenGL renderer: SDL
  // would otherwise recreate the window with an OpenGL visual at the first present (a new window
  // id under scripts/viewer-smoke's feet), and the pixels would go through a GPU driver.
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) throw WindowError(sdlError("cannot open a window"));
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, width,
                             height, SDL_WINDOW_RESIZABLE);
  if (window_ == nullptr) {
    const std::string message = sdlError("cannot open a window");
    SDL_Quit();
    throw WindowError(message);
  }
  SDL_SetWindowMinimumSize(window_, min_width, min_height);
  wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  SDL_SysWMinfo info;
  SDL_VERSION(&info.version);
  if (SDL_GetWindowWMInfo(window_, &info) == SDL_TRUE && info.subsystem == SDL_SYSWM_X11)
    x11_fd_ = ConnectionNumber(info.info.x11.display);
}

ViewWindow::~ViewWindow() {
  SDL_DestroyWindow(window_);
  SDL_Quit();
  if (wake_fd_ >= 0) close(wake_fd_);
}

void ViewWindow::sleep(std::int64_t at_most_ms) {
  if (x11_fd_ < 0 || wake_fd_ < 0) {
    SDL_Delay(static_cast<std::uint32_t>(std::min<std::int64_t>(at_most_ms, kWakePollMs)));
    return;
  }
  pollfd fds[2] = {{x11_fd_, POLLIN, 0}, {wake_fd_, POLLIN, 0}};
  if (poll(fds, 2, static_cast<int>(at_most_ms)) > 0 && (fds[1].revents & POLLIN) != 0) {
    std::uint64_t count = 0;  // drained: a wake already taken by its flag must not spin the poll
    static_cast<void>(read(wake_fd_, &count, sizeof count));
  }
}

std::optional<WindowEvent> ViewWindow::next(int timeout_ms) {
  const std::int64_t deadline_ms = steadyMilliseconds() + std::max(0, timeout_ms);
  SDL_Event event;
  while (true) {
    if (wake_requested_.exchange(false)) return WindowEvent{};  // its kind is kWake
    if (SDL_PollEvent(&event) != 0) {
      if (std::optional<WindowEvent> translated = translate(event)) return translated;
      continue;
    }
    const std::int64_t left_ms = deadline_ms - steadyMilliseconds();
    if (left_ms <= 0) return std::nullopt;
    sleep(left_ms);
  }
}

std::optional<WindowEvent> ViewWindow::translate(const SDL_Event& event) {
  using Kind = WindowEvent::Kind;
  WindowEvent out;
  switch (event.type) {
    case SDL_KEYDOWN:
    case SDL_KEYUP:
      out.kind = event.type == SDL_KEYDOWN ? Kind::kKeyDown : Kind::kKeyUp;
      out.key = event.key.keysym.sym;
      out.repeat = event.key.repeat != 0;
      return out;
    case SDL_MOUSEWHEEL: {
      const float sign = event.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -1.0f : 1.0f;
      wheel_remainder_ += sign * event.wheel.preciseY;
      const float steps = std::trunc(wheel_remainder_);
      wheel_remainder_ -= steps;
      if (steps == 0) return std::nullopt;
      out.kind = Kind::kWheel;
      out.wheel_steps = static_cast<int>(steps);
      return out;
    }
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      if (event.button.button != SDL_BUTTON_LEFT) return std::nullopt;
      out.kind = event.type == SDL_MOUSEBUTTONDOWN ? Kind::kDragStart : Kind::kDragEnd;
      return out;
    case SDL_MOUSEMOTION:
      if ((event.motion.state & SDL_BUTTON_LMASK) == 0) return std::nullopt;
      out.kind = Kind::kDrag;
      out.dx = event.motion.xrel;
      out.dy = event.motion.yrel;
      return out;
    case SDL_WINDOWEVENT:
      switch (event.window.event) {
        case SDL_WINDOWEVENT_SIZE_CHANGED:
          out.kind = Kind::kResized;
          out.width = event.window.data1;
          out.height = event.window.data2;
          return out;
        case SDL_WINDOWEVENT_EXPOSED:
          out.kind = Kind::kExposed;
          return out;
        case SDL_WINDOWEVENT_FOCUS_LOST:
          out.kind = Kind::kFocusLost;
          return out;
        default:
          return std::nullopt;
      }
    case SDL_QUIT:
      out.kind = Kind::kClose;
      return out;
    default:
      return std::nullopt;
  }
}

void ViewWindow::wake() {
  if (wake_requested_.exchange(true) || wake_fd_ < 0) return;
  const std::uint64_t one = 1;
  static_cast<void>(write(wake_fd_, &one, sizeof one));
}

int ViewWindow::width() const {
  int width = 0;
  SDL_GetWindowSize(window_, &width, nullptr);
  return width;
}

int ViewWindow::height() const {
  int height = 0;
  SDL_GetWindowSize(window_, nullptr, &height);
  return height;
}

void ViewWindow::present(const std::uint8_t* rgb, int width, int height, std::size_t stride,
                         std::uint32_t background) {
  SDL_Surface* surface = SDL_GetWindowSurface(window_);
  if (surface == nullptr) throw WindowError(sdlError("cannot draw into the window"));
  const int shown_width = std::min(width, surface->w);
  const int shown_height = std::min(height, surface->h);
  if (shown_width < surface->w || shown_height < surface->h) {
    SDL_FillRect(surface, nullptr,
                 SDL_MapRGB(surface->format, background >> 16 & 0xFF, background >> 8 & 0xFF,
                            background & 0xFF));
  }
  if (SDL_MUSTLOCK(surface)) SDL_LockSurface(surface);
  const int converted = SDL_ConvertPixels(shown_width, shown_height, SDL_PIXELFORMAT_RGB24, rgb,
                                          static_cast<int>(stride), surface->format->format,
                                          surface->pixels, surface->pitch);
  if (SDL_MUSTLOCK(surface)) SDL_UnlockSurface(surface);
  if (converted != 0 || SDL_UpdateWindowSurface(window_) != 0) {
    throw WindowError(sdlError("cannot draw into the window"));
  }
}

}  // namespace octopoint

#pragma once
// The viewer's window on SDL2: a resizable window, its events (keys going down and up, the mouse
// wheel, drags with the left mouse button, size changes), a wake-up any thread may send, and
// presenting an RGB image.
//
// SDL2 rather than OpenCV's highgui because highgui reports key presses only: "a key is held" had
// to be guessed from the keyboard's auto-repeat, so every hold began with a stutter. SDL2 reports
// each key's press and release (auto-repeats flagged as such), which is what the dual-resolution
// renderer's L/H logic runs on. The window is a plain software surface: no GPU, no OpenGL, so it
// shows the same pixels on a desktop, over ssh -X and under Xvfb.

#include <SDL2/SDL.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace octopoint {

struct WindowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WindowEvent {
  enum class Kind : std::uint8_t {
    kKeyDown,    // key (repeat: an auto-repeat of a key already down)
    kKeyUp,      // key
    kWheel,      // wheel_steps notches, > 0 away from the user
    kDragStart,  // the left mouse button went down
    kDrag,       // the mouse moved dx, dy pixels (> 0 right and down) with the left button down
    kDragEnd,    // the left mouse button went up
    kResized,    // the window is now width x height pixels
    kExposed,    // the window must be drawn again
    kFocusLost,  // keys held now will not report their release to us
    kWake,       // wake() was called
    kClose,      // the window was closed (or the process was interrupted)
  };
  Kind kind = Kind::kWake;
  SDL_Keycode key = SDLK_UNKNOWN;
  bool repeat = false;
  int wheel_steps = 0;
  int dx = 0;
  int dy = 0;
  int width = 0;
  int height = 0;
};

// Picks SDL's video driver from the environment (DISPLAY: x11, WAYLAND_DISPLAY: wayland) unless
// SDL_VIDEODRIVER names one; throws WindowError (one line) when there is no display. The window
// calls it; so may a caller that wants to know before it does anything slow.
void chooseVideoDriver();

class ViewWindow {
 public:
  // Opens a resizable window of width x height pixels that cannot be made smaller than
  // min_width x min_height. Throws WindowError (one line) when there is no display.
  ViewWindow(const std::string& title, int width, int height, int min_width, int min_height);
  ~ViewWindow();
  ViewWindow(const ViewWindow&) = delete;
  ViewWindow& operator=(const ViewWindow&) = delete;

  // The next event, waiting at most `timeout_ms` (0: only what is already queued); nullopt when
  // none came. Events the viewer has no use for (mouse motion without the button, ...) are skipped.
  std::optional<WindowEvent> next(int timeout_ms);

  // From any thread: makes next() return a kWake event soon. Wakes that come while one is still
  // pending are merged into it. It sets a flag and writes to an eventfd: it calls no SDL.
  void wake();

  // next() does not wait in SDL_WaitEventTimeout. In SDL 2.26's X11 wait, every event pushed
  // while it waits, whether by another thread (SDL_PushEvent) or by the wait itself dispatching
  // the key that quits, wakes it with an XSendEvent to the window on SDL's second X connection,
  // which the X server may process after the window's XDestroyWindow on the first: BadWindow, and
  // Xlib ends the process with exit 1 at SDL_Quit. Instead next() takes what SDL_PollEvent has
  // (which never arms that wake-up, so nothing is ever sent on the second connection:
  // net.viewer_url_smoke checks it under strace), then sleeps in poll() on the X connection and
  // wake()'s eventfd; with another video driver (no X connection to watch) it sleeps at most
  // kWakePollMs at a time.
  static constexpr int kWakePollMs = 2;

  int width() const;
  int height() const;

  // Shows a width x height RGB888 image (rows `stride` bytes apart) at the window's top left; the
  // part of the window it does not cover is filled with `background` (0xRRGGBB).
  void present(const std::uint8_t* rgb, int width, int height, std::size_t stride,
               std::uint32_t background);

 private:
  std::optional<WindowEvent> translate(const SDL_Event& event);
  // Sleeps until the X connection has input or wake() is called, at most `at_most_ms` (see
  // kWakePollMs).
  void sleep(std::int64_t at_most_ms);

  SDL_Window* window_ = nullptr;
  std::atomic<bool> wake_requested_{false};
  int wake_fd_ = -1;           // an eventfd wake() writes to (-1: none could be made)
  int x11_fd_ = -1;            // the X connection SDL reads its events from (-1: not X11)
  float wheel_remainder_ = 0;  // trackpads scroll in fractions of a notch
};

}  // namespace octopoint

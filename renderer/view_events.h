#pragma once
// What drives the interactive renderer: timed view events from an event source, either the
// viewer's window (app/view_window.cpp: SDL2 key presses and releases, wheel, resizes) or a
// scripted timeline (tests, benchmarks).

#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/clock.h"

namespace octopoint {

// Keys that move the view while held; the view turns at a fixed speed in degrees per second.
enum class NavigationKey : std::uint8_t { kYawLeft, kYawRight, kPitchUp, kPitchDown };
inline constexpr int kNavigationKeyCount = 4;

enum class ViewEventKind : std::uint8_t {
  kPress,           // a navigation key goes down (repeats of a held key are ignored)
  kRelease,         // a navigation key goes up
  kTick,            // the frame tick (every kTickPeriodMicroseconds): the fine frame may start
  kZoomIn,          // one zoom step in
  kZoomOut,         // one zoom step out
  kToggleFill,      // hole filling on/off
  kReset,           // back to the initial view
  kResize,          // the frame becomes width x height pixels (the window was resized)
  kContentChanged,  // the model has more in it (a streamed chunk arrived): the fine frame is due
                    // again, without changing the view or aborting a fine frame under way
  kQuit,            // the source has ended
};

inline constexpr std::int64_t kTickPeriodMicroseconds = 100'000;

struct ViewEvent {
  std::int64_t time_us = 0;  // on the renderer's clock
  ViewEventKind kind = ViewEventKind::kTick;
  NavigationKey key = NavigationKey::kYawLeft;  // for kPress and kRelease
  std::int32_t width = 0;                       // for kResize: the new frame size
  std::int32_t height = 0;
};

class EventSource {
 public:
  virtual ~EventSource() = default;
  // The next event, waiting at most `max_wait_ms` for it; nullopt when none came in that time.
  // After kQuit the source is finished.
  virtual std::optional<ViewEvent> next(std::int32_t max_wait_ms) = 0;
};

// A scripted list of events played on a ManualClock: next() sets the clock to the event's time
// and returns it at once, with a kTick inserted at every multiple of kTickPeriodMicroseconds from
// 0 to `end_us` (an event at the same time as a tick comes first), then kQuit at `end_us`.
class ScriptedTimeline final : public EventSource {
 public:
  ScriptedTimeline(std::vector<ViewEvent> events, std::int64_t end_us, ManualClock& clock);
  std::optional<ViewEvent> next(std::int32_t max_wait_ms) override;

 private:
  std::vector<ViewEvent> events_;
  std::size_t next_ = 0;
  ManualClock& clock_;
};

}  // namespace octopoint

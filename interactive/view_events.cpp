#include <algorithm>

#include "octopoint/interactive.h"

namespace octopoint {

ScriptedTimeline::ScriptedTimeline(std::vector<ViewEvent> events, std::int64_t end_us,
                                   ManualClock& clock)
    : events_(std::move(events)), clock_(clock) {
  for (std::int64_t tick_us = 0; tick_us <= end_us; tick_us += kTickPeriodMicroseconds) {
    events_.push_back({tick_us, ViewEventKind::kTick, NavigationKey::kYawLeft});
  }
  // Stable: scripted events stay in their order, and ahead of a tick at the same time.
  std::stable_sort(events_.begin(), events_.end(),
                   [](const ViewEvent& a, const ViewEvent& b) { return a.time_us < b.time_us; });
  events_.push_back({end_us, ViewEventKind::kQuit, NavigationKey::kYawLeft});
}

std::optional<ViewEvent> ScriptedTimeline::next(
    std::int32_t /*max_wait_ms: a script never waits*/) {
  if (next_ >= events_.size()) return ViewEvent{events_.back().time_us, ViewEventKind::kQuit};
  const ViewEvent event = events_[next_++];
  clock_.set(event.time_us);
  return event;
}

}  // namespace octopoint

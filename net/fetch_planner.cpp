#include "net/fetch_planner.h"

#include <algorithm>

namespace octopoint::net {
namespace {

constexpr std::size_t kPriorityWindow = 512;  // items considered per request

std::uint64_t itemKey(const FetchItem& item) {
  return (item.kind == FetchItem::Kind::kRecordTable ? std::uint64_t{1} << 63 : 0) |
         std::uint64_t(item.level) << 32 | item.index;
}

}  // namespace

FetchPlanner::FetchPlanner(const FetchPlanOptions& options) : options_(options) {
  priority_.resize(kPriorityWindow);
}

bool FetchPlanner::isFree(const FetchItem& item) const {
  return !in_flight_.contains(itemKey(item));
}

FetchPlanner::Outcome FetchPlanner::next(ProgressiveModel& model, const Camera& view,
                                         std::uint64_t budget, FetchRange& range) {
  return plan(
      [&](bool include_invisible) {
        return model.fetchPriority(view, include_invisible, priority_);
      },
      budget, range);
}

FetchPlanner::Outcome FetchPlanner::next(ProgressiveModel& model, const PerspectiveView& view,
                                         std::uint64_t budget, FetchRange& range) {
  return plan(
      [&](bool include_invisible) {
        return perspective_order_.order(model, view, include_invisible, priority_);
      },
      budget, range);
}

FetchPlanner::Outcome FetchPlanner::next(std::span<const FetchItem> priority, std::uint64_t budget,
                                         FetchRange& range) {
  priority_.assign(priority.begin(), priority.end());
  priority_.resize(std::max(priority_.size(), kPriorityWindow));  // the other orders' room
  return plan([&](bool) { return priority.size(); }, budget, range);
}

template <typename Priority>
FetchPlanner::Outcome FetchPlanner::plan(const Priority& priority, std::uint64_t budget,
                                         FetchRange& range) {
  std::size_t count = priority(false);
  const auto free = [&](const FetchItem& item) { return isFree(item); };
  auto first =
      std::find_if(priority_.begin(), priority_.begin() + static_cast<std::ptrdiff_t>(count), free);
  if (first == priority_.begin() + static_cast<std::ptrdiff_t>(count) &&
      options_.prefetch_invisible) {
    count = priority(true);
    first = std::find_if(priority_.begin(), priority_.begin() + static_cast<std::ptrdiff_t>(count),
                         free);
  }
  if (first == priority_.begin() + static_cast<std::ptrdiff_t>(count)) return Outcome::kNothing;
  // Extend the most urgent item with the wanted items that follow it in the file, across gaps
  // smaller than merge_gap_bytes, up to max_request_bytes.
  const FetchItem lead = *first;
  sorted_.assign(priority_.begin(), priority_.begin() + static_cast<std::ptrdiff_t>(count));
  std::sort(sorted_.begin(), sorted_.end(),
            [](const FetchItem& a, const FetchItem& b) { return a.offset < b.offset; });
  range.offset = lead.offset;
  range.items.assign(1, lead);
  std::uint64_t end = lead.offset + lead.bytes;
  for (auto it = std::upper_bound(
           sorted_.begin(), sorted_.end(), lead.offset,
           [](std::uint64_t at, const FetchItem&item) { return at < item.offset; });
       it != sorted_.end(); ++it) {
    if (!free(*it) || it->offset < end || it->offset - end > options_.merge_gap_bytes ||
        it->offset + it->bytes - range.offset > options_.max_request_bytes) {
      break;
    }
    end = it->offset + it->bytes;
    range.items.push_back(*it);
  }
  range.size = std::min(end - range.offset, budget);
  while (!range.items.empty() &&
         range.items.back().offset + range.items.back().bytes > range.offset + range.size) {
    range.items.pop_back();  // beyond the budget: not asked for
  }
  // What is left of the budget cannot hold the most urgent item: its bytes would be of no use.
  if (range.items.empty()) return Outcome::kBudgetTooSmall;
  for (const FetchItem& item : range.items) in_flight_.insert(itemKey(item));
  return Outcome::kRange;
}

std::size_t FetchPlanner::deliver(
    ProgressiveModel& model, const FetchRange& range, std::span<const std::uint8_t> arrived,
    std::size_t next, const std::function<void(const FetchItem&, const ChunkedIssue&)>& taken) {
  while (next < range.items.size()) {
    const FetchItem& item = range.items[next];
    const std::uint64_t end = item.offset + item.bytes - range.offset;
    if (end > arrived.size()) break;
    const ChunkedIssue issue =
        model.accept(item, arrived.subspan(item.offset - range.offset, item.bytes));
    in_flight_.erase(itemKey(item));
    ++next;
    taken(item, issue);
  }
  return next;
}

void FetchPlanner::abandon(const FetchRange& range, std::size_t next) {
  for (std::size_t i = next; i < range.items.size(); ++i) in_flight_.erase(itemKey(range.items[i]));
}

}  // namespace octopoint::net

#pragma once
// Which byte range a stream asks for next (octopoint/http.h, "Streams a chunked model"): the
// model's priority order for the view (ProgressiveModel::fetchPriority), the most urgent item not
// in flight, extended with the wanted items that follow it in the file, so that a request is one
// range covering neighbouring wanted items. Transport-free, so that the native client
// (net/model_stream.cpp) and the web page's module (web/octopoint_web_stream.cpp) ask for the same
// ranges in the same order.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_set>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/progressive.h"
#include "renderer/perspective.h"
#include "renderer/perspective_fetch.h"

namespace octopoint::net {

struct FetchPlanOptions {
  std::uint64_t max_request_bytes = 256 * 1024;  // so that a turn of the view is soon obeyed
  std::uint64_t merge_gap_bytes = 2048;  // fetch a gap this small rather than make a new request
  bool prefetch_invisible = true;        // once the view is complete, fetch the rest
};

// One request: a byte range and the record tables and chunks lying whole in it, in file order.
struct FetchRange {
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
  std::vector<FetchItem> items;
};

class FetchPlanner {
 public:
  enum class Outcome {
    kRange,           // `range` is the next request; its items are in flight until done()
    kNothing,         // nothing to ask for now (all wanted items are in flight, or none is left)
    kBudgetTooSmall,  // what is left of the byte budget cannot hold the most urgent item
  };

  explicit FetchPlanner(const FetchPlanOptions& options);

  // The next request for `view`, at most `budget` bytes: the most urgent item of the model's
  // priority order that is not in flight (the visible ones; the invisible ones too when
  // prefetch_invisible and every visible one is in flight or held), extended with the wanted items
  // that follow it in the file across gaps of at most merge_gap_bytes, up to max_request_bytes.
  Outcome next(ProgressiveModel& model, const Camera& view, std::uint64_t budget,
               FetchRange& range);
  // The same for a perspective view: the order of renderer/perspective_fetch.h (nearest and
  // largest on screen first, each region only as fine as its distance asks).
  Outcome next(ProgressiveModel& model, const PerspectiveView& view, std::uint64_t budget,
               FetchRange& range);
  // The same for an order the caller made (a scene's, merged over the instances of the model:
  // net/scene_fetch_order.h), most urgent first; every item in it counts as wanted.
  Outcome next(std::span<const FetchItem> priority, std::uint64_t budget, FetchRange& range);

  // Hands `model` every item of `range` from index `next` on whose bytes have all arrived
  // (`arrived` holds the range's first bytes), in order, and takes each out of flight; `taken`
  // sees each item with the model's verdict. Returns the index of the first item still incomplete.
  std::size_t deliver(ProgressiveModel& model, const FetchRange& range,
                      std::span<const std::uint8_t> arrived, std::size_t next,
                      const std::function<void(const FetchItem&, const ChunkedIssue&)>& taken);

  // The request for `range` ended: its items from `next` on did not all arrive and may be asked
  // for again.
  void abandon(const FetchRange& range, std::size_t next);

  std::size_t inFlight() const { return in_flight_.size(); }

 private:
  bool isFree(const FetchItem& item) const;
  // next() given the priority order: `priority(include_invisible)` fills priority_, says how many.
  template <typename Priority>
  Outcome plan(const Priority& priority, std::uint64_t budget, FetchRange& range);

  FetchPlanOptions options_;
  std::unordered_set<std::uint64_t> in_flight_;
  std::vector<FetchItem> priority_, sorted_;
  PerspectiveFetchOrder perspective_order_;
};

}  // namespace octopoint::net

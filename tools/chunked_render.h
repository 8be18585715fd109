#pragma once
// Drawing a chunked model (format version 3 or 5) in octopoint-render: read whole from a file, or
// streamed from an HTTP URL (octopoint/http.h) for as long as the view needs or a byte budget
// allows (`--url URL --bytes N`).

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "octopoint/camera.h"
#include "octopoint/http.h"
#include "octopoint/progressive.h"
#include "octopoint/render.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"

namespace octopoint {

// The view as octopoint-render draws a level: the frame, hole filling when asked (or smooth
// splats, docs/splats.md: what the model holds blended), the palette to an 8-bit BGR image.
cv::Mat renderChunkedView(ProgressiveModel& model, const Camera& camera, Variant variant, bool fill,
                          Rgb background, ProgressiveDrawStats* stats,
                          SplatMode splats = SplatMode::kBox);

struct UrlFetchOptions {
  std::uint64_t bytes = 0;         // stop after this many bytes (0: whatever the view needs)
  int timeout_seconds = 60;        // give up waiting after this long, and draw what arrived
  std::uint64_t point_budget = 0;  // draw at most about this many points (0: no budget)
};

// ", N chunks one depth coarser for the point budget" when the budget drew any so, else "".
std::string overBudgetNote(const ProgressiveDrawStats& stats);

// Streams `url` for `camera`, then draws what arrived. With a byte budget the client uses one
// connection, so that the same N bytes always arrive in the same order. Throws ModelLoadError (one
// line) when not even the head arrived. `report` gets a one-line summary.
cv::Mat renderFromUrl(const std::string& url, const Camera& camera, Variant variant, bool fill,
                      Rgb background, const UrlFetchOptions& options, std::string* report,
                      SplatMode splats = SplatMode::kBox);

// A chunked model streamed from an HTTP URL for perspective views (--url with --perspective,
// --eye or --path): the head first, then for each view what that view needs, in the perspective
// fetch order (renderer/perspective_fetch.h), until the stream settles, the byte budget is spent
// or the timeout passes; each view is drawn from the parts held then (renderer/chunked_assembly.h:
// every region at the finest depth held there). One connection with a byte budget, as
// renderFromUrl.
class PerspectiveUrlSource {
 public:
  // Waits for the head: ModelLoadError (one line) when it does not come.
  PerspectiveUrlSource(const std::string& url, const UrlFetchOptions& options);
  ~PerspectiveUrlSource();
  PerspectiveUrlSource(const PerspectiveUrlSource&) = delete;
  PerspectiveUrlSource& operator=(const PerspectiveUrlSource&) = delete;

  // The model as the head gives it (its base), for its cube's placement and palette.
  const ModelView& headModel() const { return *head_parts_.parts.front()->view; }
  // Fetches what `view` needs, then returns the parts held (valid until the next call).
  const HeldParts& follow(const PerspectiveView& view);
  // "N of M bytes in R requests, C chunks held, view complete" (or "K still wanted").
  std::string report() const;

 private:
  std::string url_text_;
  UrlFetchOptions options_;
  std::unique_ptr<net::ModelStream> stream_;
  HeldParts head_parts_, parts_;
  net::StreamStatus last_;
};

}  // namespace octopoint

#include "tools/chunked_render.h"

#include <opencv2/imgproc.hpp>

#include "octopoint/framebuffer.h"
#include "octopoint/http.h"
#include "octopoint/render.h"
#include "tools/model_source.h"

namespace octopoint {

cv::Mat renderChunkedView(ProgressiveModel& model, const Camera& camera, Variant variant, bool fill,
                          Rgb background, ProgressiveDrawStats* stats, SplatMode splats) {
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  ProgressiveDrawStats drawn;
  cv::Mat rgb(camera.height, camera.width, CV_8UC3);
  if (splats == SplatMode::kSmooth) {  // octopoint-render refuses --fill with it
    SmoothSplats smooth(camera.width, camera.height);
    const PaletteRgb palette = paletteOf(model.baseModel());
    if (!model.drawSmooth(camera, variant, frame, smooth, palette, &drawn) ||
        !smooth.resolveToRgb(frame, palette, background, {rgb.data, rgb.total() * 3})) {
      throw ModelLoadError("camera refused: coordinates would overflow");
    }
    if (stats != nullptr) *stats = drawn;
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    return bgr;
  }
  if (!model.draw(camera, variant, frame, &drawn))
    throw ModelLoadError("camera refused: coordinates would overflow");
  if (fill) {
    FrameSetup setup;
    // The model drew at this depth with this camera, so the set-up is accepted and the fill fits.
    if (buildFrameSetup(camera, drawn.drawn_depth, kDefaultFractionBits, &setup) !=
            CameraError::kNone ||
        HoleFiller(frame.width()).fill(frame, bridgeDepthLimit(setup)).refused) {
      throw ModelLoadError("hole filling refused the frame");
    }
  }
  if (stats != nullptr) *stats = drawn;
  if (!resolveToRgb(frame, model.baseModel(), background, {rgb.data, rgb.total() * 3}))
    throw ModelLoadError("the image is smaller than the frame");
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

namespace {

net::HttpUrl parseUrl(const std::string& text) {
  std::string why;
  const std::optional<net::HttpUrl> url = net::parseHttpUrl(text, &why);
  if (!url) throw ModelLoadError("--url: '" + text + "': " + why);
  return *url;
}

net::StreamOptions streamOptions(const UrlFetchOptions& options) {
  net::StreamOptions stream_options;
  stream_options.byte_budget = options.bytes;
  stream_options.connections = options.bytes > 0 ? 1 : 2;
  stream_options.prefetch_invisible = false;
  // A server that refuses, errs or lies three times in a row is reported at once, not waited for.
  stream_options.give_up_after = 3;
  if (options.bytes > 0)
    stream_options.first_request_bytes = std::min<std::uint64_t>(options.bytes, 4096);
  return stream_options;
}

// A stream that failed (a lie about the file, a server that kept refusing) or settled without
// the view (its chunks damaged every time they came) would draw an incomplete picture as if it
// were the file's: refused instead. Only a byte budget or the timeout leaves a view unfinished.
void refuseUnfinished(const net::StreamStatus& status, const std::string& url,
                      const UrlFetchOptions& options) {
  if (status.failed) throw ModelLoadError(status.error);
  if (status.settled && !status.view_complete && options.bytes == 0) {
    throw ModelLoadError(
        url + ": " + std::to_string(status.chunks_pending) + " of the view's chunks came damaged " +
        std::to_string(ProgressiveModel::kMaxChunkAttempts) + " times (" +
        std::to_string(status.refused_items) + " refused; last: " + status.error + ")");
  }
}

std::string headMissing(const std::string& url, const UrlFetchOptions& options,
                        const net::StreamStatus& status) {
  return url + ": the head did not arrive" +
         (options.bytes > 0 ? " within " + std::to_string(options.bytes) + " bytes"
                            : std::string()) +
         (status.error.empty() ? std::string() : " (" + status.error + ")");
}

std::string streamReport(const net::StreamStatus& status) {
  return std::to_string(status.bytes_received) + " of " + std::to_string(status.file_bytes) +
         " bytes in " + std::to_string(status.requests) + " requests, " +
         std::to_string(status.chunks_held) + " chunks held, " +
         (status.view_complete ? "view complete"
                               : std::to_string(status.chunks_pending) + " still wanted");
}

}  // namespace

cv::Mat renderFromUrl(const std::string& url_text, const Camera& camera, Variant variant, bool fill,
                      Rgb background, const UrlFetchOptions& options, std::string* report,
                      SplatMode splats) {
  const net::HttpUrl url = parseUrl(url_text);
  net::ModelStream stream(url, streamOptions(options));
  stream.setView(camera);
  stream.start();
  const net::StreamStatus status =
      stream.waitUntilSettled(std::chrono::seconds(options.timeout_seconds));
  stream.stop();
  refuseUnfinished(status, url.text(), options);
  cv::Mat image;
  ProgressiveDrawStats stats;
  stream.withModel([&](ProgressiveModel* model) {
    if (model == nullptr) return;
    model->setPointBudget(options.point_budget);
    image = renderChunkedView(*model, camera, variant, fill, background, &stats, splats);
  });
  if (image.empty()) throw ModelLoadError(headMissing(url.text(), options, status));
  if (report != nullptr) {
    *report = streamReport(status) + ", depth " + std::to_string(stats.drawn_depth) + " drawn, " +
              std::to_string(stats.coarser_pieces) + " regions coarser" + overBudgetNote(stats);
  }
  return image;
}

std::string overBudgetNote(const ProgressiveDrawStats& stats) {
  if (stats.over_budget_chunks == 0) return {};
  return ", " + std::to_string(stats.over_budget_chunks) +
         " chunks one depth coarser for the point budget";
}

PerspectiveUrlSource::PerspectiveUrlSource(const std::string& url_text,
                                           const UrlFetchOptions& options)
    : url_text_(url_text), options_(options) {
  const net::HttpUrl url = parseUrl(url_text);
  url_text_ = url.text();
  stream_ = std::make_unique<net::ModelStream>(url, streamOptions(options));
  stream_->clearView();  // the views need the head (an eye in the scan's units, its cube)
  stream_->start();
  last_ = stream_->waitUntilSettled(std::chrono::seconds(options.timeout_seconds));
  if (last_.failed) throw ModelLoadError(last_.error);
  stream_->withModel([&](ProgressiveModel* model) {
    if (model != nullptr) head_parts_ = assembleHeldParts(*model);
  });
  if (head_parts_.parts.empty()) throw ModelLoadError(headMissing(url_text_, options, last_));
}

PerspectiveUrlSource::~PerspectiveUrlSource() = default;

const HeldParts& PerspectiveUrlSource::follow(const PerspectiveView& view) {
  stream_->setView(view);
  last_ = stream_->waitUntilSettled(std::chrono::seconds(options_.timeout_seconds));
  refuseUnfinished(last_, url_text_, options_);
  stream_->withModel([&](ProgressiveModel* model) { parts_ = assembleHeldParts(*model); });
  return parts_;
}

std::string PerspectiveUrlSource::report() const { return streamReport(last_); }

}  // namespace octopoint

#pragma once
// octopoint/http.h: Streaming a chunked model over HTTP byte ranges into a ProgressiveModel
// (octopoint::net). The manual of the whole library is octopoint/octopoint.h.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "octopoint/camera.h"
#include "octopoint/progressive.h"

namespace octopoint {
struct PerspectiveView;  // renderer/perspective.h
}

// An http:// URL as the client takes it: http://HOST[:PORT]/PATH. No https, no user info.

namespace octopoint::net {

struct HttpUrl {
  std::string host;  // a name, an IPv4 address, or an IPv6 address without its brackets
  int port = 80;
  std::string path;  // starts with '/'
  std::string text() const;
};

// nullopt, with `error` saying why in a few words, when `text` is not such a URL.
[[nodiscard]] std::optional<HttpUrl> parseHttpUrl(std::string_view text, std::string* error);

}  // namespace octopoint::net

// Fetching byte ranges of one file over HTTP/1.1 (octopoint's own client over POSIX sockets,
// bounded everywhere: docs/robustness.md, "The HTTP client"), from any static server with Range
// support (octopoint-serve, nginx, ...), trusting nothing the server says: the status must be 206
// with a Content-Range naming the bytes asked for (or cut at the file's end, or 200 with the whole
// file when it starts at 0 and is no longer than asked), the body must be exactly that long (a
// longer or endless body is cut off and refused), and it must arrive at a useful rate (cut off
// otherwise). One connection, kept alive; no redirect followed, no Transfer-Encoding accepted. A
// refused or broken connection, an error status or a lie ends the fetch at once, saying in words
// what the server did.

namespace octopoint::net {

struct RangeTimeouts {
  int connect_seconds = 5;
  int read_seconds = 10;                     // no byte for this long: the fetch fails
  std::uint64_t min_bytes_per_second = 256;  // a body slower than this (after 10 s of grace) fails
};

enum class FetchStatus {
  kOk,
  kConnectionFailed,  // could not connect, or the connection broke
  kHttpStatus,        // the server answered with another status (404, 416, 503, ...)
  kBadResponse,       // a Content-Range or Content-Length that is not what was asked
  kTooLong,           // more bytes than asked (an endless or oversized body)
  kTooShort,          // the body ended early
  kTooSlow,           // below the minimum rate, or stalled
  kCancelled,         // the caller's cancel flag
};

const char* describe(FetchStatus status);

struct FetchResult {
  FetchStatus status = FetchStatus::kOk;
  int http_status = 0;
  std::uint64_t bytes = 0;      // body bytes received (passed to the sink)
  std::uint64_t file_size = 0;  // from Content-Range, when the server said
  std::string message;          // one line for logs
};

class RangeClient {
 public:
  RangeClient(const HttpUrl& url, const RangeTimeouts& timeouts);
  ~RangeClient();
  RangeClient(const RangeClient&) = delete;
  RangeClient& operator=(const RangeClient&) = delete;

  // Fetches bytes [offset, offset + size) of the URL's file. `sink(offset_of_piece, piece)` sees
  // the body as it arrives, in order; returning false from it cancels. `cancel`, when given and
  // set, ends the fetch at the next piece.
  [[nodiscard]] FetchResult fetch(
      std::uint64_t offset, std::uint64_t size,
      const std::function<bool(std::uint64_t, std::span<const std::uint8_t>)>& sink,
      const std::atomic<bool>* cancel = nullptr);
  // From another thread: breaks the connection, so that a fetch blocked on it ends at once.
  void abort();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octopoint::net

// Streams a chunked model (octopoint/progressive.h) over HTTP into a ProgressiveModel: first the
// head (one request for the first bytes of the file), then the byte ranges the model asks for the
// current view, most urgent first (ProgressiveModel::fetchPriority), a few requests in flight, each
// request one range covering neighbouring wanted items. Every table and chunk is handed to the
// model the moment its last byte arrives, so a slow link refines the picture within a request.
//
// It survives what a network does: a failed or short request is retried after a back-off (100 ms,
// doubling to 2 s, for as long as it runs: when the server comes back, the stream resumes; or,
// with StreamOptions::give_up_after, until that many have failed in a row); a chunk
// that arrives damaged is refused by the model and fetched again, at most
// ProgressiveModel::kMaxChunkAttempts times in all; responses of the wrong length or endless ones
// are cut off (octopoint/http.h). Only a head that is not a chunked model, or a file that changed
// size, ends it for good.
//
// Threads: `connections` workers fetch; the model is fed and asked only under the stream's lock.
// Drawing threads take that lock only to copy a snapshot of which chunks are drawable (snapshot(),
// one byte per chunk), then draw it without the lock: a frame and the arrival of chunks never wait
// on each other for longer than that copy, or than accepting one chunk.

namespace octopoint::net {

struct StreamOptions {
  int connections = 2;                           // requests in flight
  std::uint64_t byte_budget = 0;                 // stop after this many bytes (0: no limit)
  std::uint64_t first_request_bytes = 4096;      // the head fits this in files the preparer writes
  std::uint64_t max_request_bytes = 256 * 1024;  // so that a turn of the view is soon obeyed
  std::uint64_t merge_gap_bytes = 2048;          // fetch a gap this small rather than a new request
  bool prefetch_invisible = true;                // once the view is complete, fetch the rest
  // End the stream (failed) after this many failed requests in a row that were not slowness:
  // a refused connection, an error status, a response that lies. 0: retry for as long as it runs
  // (a viewer waiting for its server to come back); a one-shot client wants a few.
  int give_up_after = 0;
  RangeTimeouts timeouts;
};

struct StreamStatus {
  bool head_known = false;
  bool failed = false;  // nothing more will come (see error)
  std::string error;    // why it failed, or the last transport error
  std::uint64_t bytes_received = 0;
  std::uint64_t file_bytes = 0;
  std::uint32_t chunks_held = 0;
  std::uint32_t chunks_pending = 0;  // the view's tables and chunks not held yet
  std::uint32_t requests = 0;
  std::uint32_t failed_requests = 0;
  std::uint32_t refused_items = 0;  // tables and chunks the model refused (damaged)
  bool view_complete = false;
  bool settled = false;  // nothing in flight and nothing more to fetch (or the budget is spent)
};

class ModelStream {
 public:
  ModelStream(const HttpUrl& url, const StreamOptions& options);
  ~ModelStream();  // stops
  ModelStream(const ModelStream&) = delete;
  ModelStream& operator=(const ModelStream&) = delete;

  void start();
  void stop();
  // The view the fetch order follows; takes effect for the next request. A perspective view
  // follows renderer/perspective_fetch.h's order (nearest and largest on screen first, each region
  // only as fine as its distance asks). clearView(): no view, nothing fetched but the head (set
  // before start() when the view needs the head, as an eye placed in the scan's units does).
  void setView(const Camera& camera);
  void setView(const PerspectiveView& view);
  void clearView();
  [[nodiscard]] StreamStatus status();
  // Calls `use(model)` under the stream's lock; `model` is null until the head has arrived.
  void withModel(const std::function<void(ProgressiveModel*)>& use);
  // Copies which chunks the model holds now into `frame` under the lock (ProgressiveModel::
  // snapshot) and returns the model to draw it with, model->draw(frame, ...), without the lock;
  // null until the head has arrived. The model lives as long as the stream; its head and base
  // model (baseModel(), for the palette) never change.
  const ProgressiveModel* snapshot(ProgressiveFrame& frame);
  // The model once the head has arrived (null before), for its head and base model, which never
  // change; anything else only under withModel.
  const ProgressiveModel* model();
  // Called under the lock after each table or chunk the model accepted, with the bytes received so
  // far (for measurements).
  void onAccepted(std::function<void(ProgressiveModel&, std::uint64_t bytes_received)> callback);
  // Waits until settled or failed, or `timeout`; returns the status then.
  [[nodiscard]] StreamStatus waitUntilSettled(std::chrono::milliseconds timeout);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octopoint::net

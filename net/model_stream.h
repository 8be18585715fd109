#pragma once
// Streams a chunked model (renderer/chunked_format.h) over HTTP into a ProgressiveModel: first the
// head (one request for the first bytes of the file), then the byte ranges the model asks for the
// current view, most urgent first (ProgressiveModel::fetchPriority), a few requests in flight, each
// request one range covering neighbouring wanted items. Every table and chunk is handed to the
// model the moment its last byte arrives, so a slow link refines the picture within a request.
//
// It survives what a network does: a failed or short request is retried after a back-off (100 ms,
// doubling to 2 s, for as long as it runs: when the server comes back, the stream resumes); a chunk
// that arrives damaged is refused by the model and fetched again, at most
// ProgressiveModel::kMaxChunkAttempts times in all; responses of the wrong length or endless ones
// are cut off (net/range_client.h). Only a head that is not a chunked model, or a file that changed
// size, ends it for good.
//
// Threads: `connections` workers fetch; the model is fed and asked only under the stream's lock.
// Drawing threads take that lock only to copy a snapshot of which chunks are drawable (snapshot(),
// one byte per chunk), then draw it without the lock: a frame and the arrival of chunks never wait
// on each other for longer than that copy, or than accepting one chunk.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "net/http_url.h"
#include "net/range_client.h"
#include "renderer/camera.h"
#include "renderer/progressive_model.h"

namespace octopoint::net {

struct StreamOptions {
  int connections = 2;                           // requests in flight
  std::uint64_t byte_budget = 0;                 // stop after this many bytes (0: no limit)
  std::uint64_t first_request_bytes = 4096;      // the head fits this in files the preparer writes
  std::uint64_t max_request_bytes = 256 * 1024;  // so that a turn of the view is soon obeyed
  std::uint64_t merge_gap_bytes = 2048;          // fetch a gap this small rather than a new request
  bool prefetch_invisible = true;                // once the view is complete, fetch the rest
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
  // The view the fetch order follows; takes effect for the next request.
  void setView(const Camera& camera);
  StreamStatus status();
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
  StreamStatus waitUntilSettled(std::chrono::milliseconds timeout);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octopoint::net

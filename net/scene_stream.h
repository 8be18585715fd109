#pragma once
// Streams a scene's models over HTTP byte ranges (docs/city.md, "Walking over a slow link"): per
// distinct model a ProgressiveModel (octopoint/progressive.h) fed from its chunked file beside the
// scene file, every model's heads, record tables and chunks fetched in one order for the walk
// (net/scene_fetch_order.h: the eye's cell's set or the instances in view first, nearest first;
// then what lies ahead), over a few connections (each one request at a time). Each table and chunk
// is handed to its model the moment its last byte arrives.
//
// Threads: `connections` workers fetch; the models are fed and asked only under the stream's lock.
// A drawing thread reads them under it (withModels) when content() has moved: re-assembling what
// is held (renderer/held_scene.h) only when something new arrived.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "net/scene_fetch_order.h"
#include "octopoint/http.h"
#include "octopoint/scene.h"

namespace octopoint::net {

struct SceneStreamOptions {
  int connections = 2;                          // requests in flight
  std::uint64_t first_request_bytes = 4096;     // a model's head fits this (the preparer's)
  std::uint64_t max_request_bytes = 32 * 1024;  // so that a turn of the view is soon obeyed
  std::uint64_t merge_gap_bytes = 2048;         // fetch a gap this small rather than a new request
  RangeTimeouts timeouts;
};

struct SceneStreamStatus {
  bool failed = false;  // a head that is not a chunked model: nothing more will come
  std::string error;    // why, or the last transport error
  std::uint64_t bytes_received = 0;
  std::uint32_t requests = 0, failed_requests = 0, refused_items = 0;
  std::uint32_t heads_known = 0;
  std::uint32_t pending = 0;  // heads, tables and chunks the tiers want that are not held
  bool settled = false;       // nothing in flight and nothing wanted
};

class SceneStream {
 public:
  // `folder`: the scene file's folder (its path ending in '/'); `model_files` the scene's models,
  // each a chunked file in it; `instances` the scene's.
  SceneStream(const HttpUrl& folder, const std::vector<std::string>& model_files,
              std::vector<SceneInstance> instances, const SceneStreamOptions& options);
  ~SceneStream();  // stops
  SceneStream(const SceneStream&) = delete;
  SceneStream& operator=(const SceneStream&) = delete;

  void start();
  void stop();
  // The fetch order's tiers, most urgent first; taken for the next request.
  void setTiers(std::vector<SceneFetchTier> tiers);
  // Bumped for every head, table and chunk a model accepted.
  std::uint64_t content() const { return content_.load(); }
  // Calls `use(models)` under the lock: models[m] is null until model m's head has arrived.
  void withModels(const std::function<void(std::span<ProgressiveModel* const>)>& use);
  [[nodiscard]] SceneStreamStatus status();  // works out the order: not for every frame
  std::uint64_t bytesReceived();
  // Waits until settled or failed, or `timeout`; the status then.
  [[nodiscard]] SceneStreamStatus waitUntilSettled(std::chrono::milliseconds timeout);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::atomic<std::uint64_t> content_{0};
};

}  // namespace octopoint::net

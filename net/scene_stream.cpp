#include "net/scene_stream.h"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "net/fetch_planner.h"
#include "net/head_read.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;

// One request: a model's head bytes, or a byte range of its tables and chunks (FetchPlanner).
// Bytes its head request already brought (it reads past the head) are not asked for again.
struct Plan : FetchRange {
  std::uint32_t model = 0;
  bool head = false;
  std::vector<std::uint8_t> known;  // the bytes from `offset` on that are already here
};

// One model's stream: its head's bytes while they come, then its model and its requests in flight.
struct Streamed {
  HttpUrl url;
  HeadRead head;  // the file's first bytes
  std::optional<ProgressiveModel> model;
  std::optional<FetchPlanner> planner;
};

}  // namespace

class SceneStream::Impl {
 public:
  Impl(SceneStream& owner, const HttpUrl& folder, const std::vector<std::string>& files,
       std::vector<SceneInstance> instances, const SceneStreamOptions& options)
      : owner_(owner), options_(options), instances_(std::move(instances)) {
    for (const std::string& file : files) {
      Streamed streamed;
      streamed.url = folder;
      streamed.url.path += file;
      streamed.planner.emplace(
          FetchPlanOptions{options.max_request_bytes, options.merge_gap_bytes, false});
      models_.push_back(std::move(streamed));
    }
    pointers_.assign(models_.size(), nullptr);
  }
  ~Impl() { stop(); }

  void start() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!threads_.empty()) return;
    for (int i = 0; i < std::max(options_.connections, 1); ++i)
      threads_.emplace_back([this] { work(); });
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      for (RangeClient* client : clients_) client->abort();
    }
    cv_.notify_all();
    for (std::thread& thread : threads_) thread.join();
    threads_.clear();
  }

  void setTiers(std::vector<SceneFetchTier> tiers) {
    std::lock_guard<std::mutex> lock(mutex_);
    tiers_ = std::move(tiers);
    cv_.notify_all();
  }

  void withModels(const std::function<void(std::span<ProgressiveModel* const>)>& use) {
    std::lock_guard<std::mutex> lock(mutex_);
    use(pointers_);
  }

  SceneStreamStatus status() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statusLocked();
  }

  std::uint64_t bytesReceived() {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_;
  }

  SceneStreamStatus waitUntilSettled(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto deadline = Clock::now() + timeout;
    while (Clock::now() < deadline) {
      SceneStreamStatus now = statusLocked();
      if (now.failed || now.settled) return now;
      cv_.wait_until(lock, std::min(deadline, Clock::now() + std::chrono::milliseconds(50)));
    }
    return statusLocked();
  }

 private:
  SceneStreamStatus statusLocked() {
    SceneStreamStatus status;
    status.failed = failed_;
    status.error = error_;
    status.bytes_received = received_;
    status.requests = requests_;
    status.failed_requests = failed_requests_;
    status.refused_items = refused_items_;
    for (const Streamed& streamed : models_) status.heads_known += streamed.model ? 1 : 0;
    order_.order(pointers_, instances_, tiers_, entries_);
    status.pending = static_cast<std::uint32_t>(entries_.size());
    status.settled = busy_ == 0 && entries_.empty();
    return status;
  }

  void accepted() {
    owner_.content_.fetch_add(1);
    cv_.notify_all();
  }

  // Under the lock: the next request, or false when there is none to make now.
  bool nextPlan(Plan& plan) {
    order_.order(pointers_, instances_, tiers_, entries_);
    // Each model's wanted items in the order's order; the models by their most urgent item.
    per_model_.resize(models_.size());
    for (std::vector<FetchItem>& items : per_model_) items.clear();
    model_order_.clear();
    for (const SceneFetchEntry& entry : entries_) {
      if (std::find(model_order_.begin(), model_order_.end(), entry.model) == model_order_.end())
        model_order_.push_back(entry.model);
      if (!entry.head) per_model_[entry.model].push_back(entry.item);
    }
    for (const std::uint32_t m : model_order_) {
      Streamed& streamed = models_[m];
      plan.model = m;
      if (!streamed.model) {
        if (streamed.head.in_flight) continue;
        const HeadRead::Range range = streamed.head.nextRange(options_.first_request_bytes);
        plan.head = true;
        plan.offset = range.offset;
        plan.size = range.size;
        streamed.head.in_flight = true;
        return true;
      }
      if (streamed.planner->next(per_model_[m], UINT64_MAX, plan) != FetchPlanner::Outcome::kRange)
        continue;  // every item it wants is in flight
      plan.known = streamed.head.known(plan.offset, plan.size);
      return true;
    }
    return false;
  }

  // Under the lock: model m's head request's next bytes; makes its model once they hold the
  // whole head.
  void takeHead(std::uint32_t m, std::span<const std::uint8_t> piece) {
    Streamed& streamed = models_[m];
    ChunkedIssue issue;
    std::optional<ProgressiveModel> model = streamed.head.take(piece, &issue);
    if (streamed.head.failed()) return fail(describeAt(streamed.url.text(), issue));
    if (!model) return;
    streamed.model = std::move(model);
    pointers_[m] = &*streamed.model;
    // Whatever followed the head in its request: tables and chunks lying whole in it (a part
    // refused here is fetched again later as an item of its own).
    static_cast<void>(streamed.model->acceptBytes(0, streamed.head.bytes(), &issue));
    accepted();
  }

  void fail(const std::string& why) {
    failed_ = true;
    error_ = why;
    cv_.notify_all();
  }

  void work() {
    std::vector<std::unique_ptr<RangeClient>> clients(models_.size());  // one per file, kept alive
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_ && !failed_) {
      if (Clock::now() < retry_after_) {
        cv_.wait_until(lock, retry_after_);
        continue;
      }
      Plan plan;
      if (!nextPlan(plan)) {
        cv_.wait_for(lock, std::chrono::milliseconds(50));
        continue;
      }
      Streamed& streamed = models_[plan.model];
      std::unique_ptr<RangeClient>& client = clients[plan.model];
      if (!client) {
        client = std::make_unique<RangeClient>(streamed.url, options_.timeouts);
        clients_.push_back(client.get());
      }
      std::vector<std::uint8_t> buffer = std::move(plan.known);
      std::size_t next = 0;
      const auto deliver = [&] {
        next = streamed.planner->deliver(*streamed.model, plan, buffer, next,
                                         [this](const FetchItem&, const ChunkedIssue& issue) {
                                           if (issue.error != ChunkedError::kNone) {
                                             ++refused_items_;
                                           } else {
                                             accepted();
                                           }
                                         });
      };
      if (!plan.head) deliver();
      const std::uint64_t fetch_offset = plan.offset + buffer.size();
      const std::uint64_t fetch_size = plan.size - buffer.size();
      if (fetch_size == 0) {
        streamed.planner->abandon(plan, next);
        continue;
      }
      ++busy_;
      ++requests_;
      lock.unlock();
      const FetchResult result = client->fetch(
          fetch_offset, fetch_size,
          [&](std::uint64_t, std::span<const std::uint8_t> piece) {
            std::lock_guard<std::mutex> guard(mutex_);
            received_ += piece.size();
            if (plan.head) {
              takeHead(plan.model, piece);
            } else {
              buffer.insert(buffer.end(), piece.begin(), piece.end());
              deliver();
            }
            return !stopping_ && !failed_;
          },
          &stopping_);
      lock.lock();
      --busy_;
      if (plan.head) {
        streamed.head.in_flight = false;
      } else {
        streamed.planner->abandon(plan, next);
      }
      if (result.status != FetchStatus::kOk && !stopping_ && !failed_) {
        ++failed_requests_;
        error_ = streamed.url.text() + ": " + result.message;
        if (plan.head && result.status == FetchStatus::kHttpStatus &&
            headMissing(result.http_status)) {
          fail(error_);  // no such model: nothing will come
        }
        retry_after_ = Clock::now() + std::chrono::milliseconds(200);
      }
      cv_.notify_all();
    }
    for (const std::unique_ptr<RangeClient>& client : clients) {
      if (client) clients_.erase(std::find(clients_.begin(), clients_.end(), client.get()));
    }
  }

  SceneStream& owner_;
  SceneStreamOptions options_;
  std::vector<SceneInstance> instances_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable cv_;
  // Under mutex_:
  std::vector<Streamed> models_;
  std::vector<ProgressiveModel*> pointers_;  // models_[m].model, or null
  std::vector<RangeClient*> clients_;
  std::vector<SceneFetchTier> tiers_;
  SceneFetchOrder order_;
  std::vector<SceneFetchEntry> entries_;
  std::vector<std::vector<FetchItem>> per_model_;
  std::vector<std::uint32_t> model_order_;
  std::uint64_t received_ = 0;
  int busy_ = 0;
  bool failed_ = false;
  std::string error_;
  Clock::time_point retry_after_{};
  std::uint32_t requests_ = 0, failed_requests_ = 0, refused_items_ = 0;
};

SceneStream::SceneStream(const HttpUrl& folder, const std::vector<std::string>& model_files,
                         std::vector<SceneInstance> instances, const SceneStreamOptions& options)
    : impl_(std::make_unique<Impl>(*this, folder, model_files, std::move(instances), options)) {}
SceneStream::~SceneStream() { impl_->stop(); }
void SceneStream::start() { impl_->start(); }
void SceneStream::stop() { impl_->stop(); }
void SceneStream::setTiers(std::vector<SceneFetchTier> tiers) { impl_->setTiers(std::move(tiers)); }
void SceneStream::withModels(const std::function<void(std::span<ProgressiveModel* const>)>& use) {
  impl_->withModels(use);
}
SceneStreamStatus SceneStream::status() { return impl_->status(); }
std::uint64_t SceneStream::bytesReceived() { return impl_->bytesReceived(); }
SceneStreamStatus SceneStream::waitUntilSettled(std::chrono::milliseconds timeout) {
  return impl_->waitUntilSettled(timeout);
}

}  // namespace octopoint::net

#include <algorithm>
#include <atomic>
#include <thread>
#include <variant>
#include <vector>

#include "net/fetch_planner.h"
#include "net/head_read.h"
#include "octopoint/http.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;

// One request: the head's first bytes, or a byte range of tables and chunks (FetchPlanner). Bytes
// the first request already brought (it reads past the head) are not asked for again: `known`
// holds them, and the request starts after them.
struct Plan : FetchRange {
  bool head = false;
  std::vector<std::uint8_t> known;  // the bytes from `offset` on that are already here
};

// The view the fetch order follows: none (the head only), orthographic or perspective.
using StreamView = std::variant<std::monostate, Camera, PerspectiveView>;

FetchPlanOptions planOptions(const StreamOptions& options) {
  return {options.max_request_bytes, options.merge_gap_bytes, options.prefetch_invisible};
}

}  // namespace

class ModelStream::Impl {
 public:
  Impl(const HttpUrl& url, const StreamOptions& options)
      : url_(url), options_(options), planner_(planOptions(options)) {}
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

  void setView(const StreamView& view) {
    std::lock_guard<std::mutex> lock(mutex_);
    view_ = view;
    cv_.notify_all();
  }

  StreamStatus status() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statusLocked();
  }

  void withModel(const std::function<void(ProgressiveModel*)>& use) {
    std::lock_guard<std::mutex> lock(mutex_);
    use(model_ ? &*model_ : nullptr);
  }

  const ProgressiveModel* model() {
    std::lock_guard<std::mutex> lock(mutex_);
    return model_ ? &*model_ : nullptr;
  }

  const ProgressiveModel* snapshot(ProgressiveFrame& frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!model_) return nullptr;
    model_->snapshot(frame);
    return &*model_;
  }

  void onAccepted(std::function<void(ProgressiveModel&, std::uint64_t)> callback) {
    std::lock_guard<std::mutex> lock(mutex_);
    on_accepted_ = std::move(callback);
  }

  StreamStatus waitUntilSettled(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto deadline = Clock::now() + timeout;
    while (Clock::now() < deadline) {
      StreamStatus now = statusLocked();
      if (now.failed || now.settled) return now;
      cv_.wait_until(lock, std::min(deadline, Clock::now() + std::chrono::milliseconds(50)));
    }
    return statusLocked();
  }

 private:
  std::uint64_t budgetLeft() const {
    if (options_.byte_budget == 0) return UINT64_MAX;
    if (budget_spent_) return 0;
    const std::uint64_t used = received_ + outstanding_;
    return used >= options_.byte_budget ? 0 : options_.byte_budget - used;
  }

  StreamStatus statusLocked() {
    StreamStatus status;
    status.head_known = model_.has_value();
    status.failed = failed_;
    status.error = error_;
    status.bytes_received = received_;
    status.requests = requests_;
    status.failed_requests = failed_requests_;
    status.refused_items = refused_items_;
    if (model_) {
      status.file_bytes = model_->head().file_bytes;
      status.chunks_held = model_->chunksIn(ChunkState::kHeld);
      std::size_t pending = 0, wanted = 0;
      if (const Camera* camera = std::get_if<Camera>(&view_)) {
        model_->fetchPriority(*camera, false, {}, &pending);
        status.view_complete = model_->viewComplete(*camera);
        model_->fetchPriority(*camera, options_.prefetch_invisible, {}, &wanted);
      } else if (const PerspectiveView* view = std::get_if<PerspectiveView>(&view_)) {
        // The perspective view is complete when nothing it sees is left to fetch.
        static_cast<void>(status_order_.order(*model_, *view, false, {}, &pending));
        status.view_complete = pending == 0;
        static_cast<void>(
            status_order_.order(*model_, *view, options_.prefetch_invisible, {}, &wanted));
      } else {
        status.view_complete = true;  // no view yet: the head is all there is to fetch
      }
      status.chunks_pending = static_cast<std::uint32_t>(pending);
      status.settled = busy_ == 0 && (wanted == 0 || budgetLeft() == 0);
    } else {
      status.settled = failed_ || (busy_ == 0 && budgetLeft() == 0);
    }
    return status;
  }

  void fail(const std::string& why) {
    failed_ = true;
    error_ = why;
    cv_.notify_all();
  }

  // Under the lock: the next request, or false when there is none to make now.
  bool nextPlan(Plan& plan) {
    const std::uint64_t budget = budgetLeft();
    if (budget == 0) return false;
    if (!model_) {
      if (head_.in_flight) return false;
      const HeadRead::Range range = head_.nextRange(options_.first_request_bytes);
      plan.head = true;
      plan.offset = range.offset;
      plan.size = std::min(range.size, budget);
      head_.in_flight = true;
      return true;
    }
    if (std::holds_alternative<std::monostate>(view_)) return false;
    const FetchPlanner::Outcome outcome =
        std::holds_alternative<Camera>(view_)
            ? planner_.next(*model_, std::get<Camera>(view_), budget, plan)
            : planner_.next(*model_, std::get<PerspectiveView>(view_), budget, plan);
    switch (outcome) {
      case FetchPlanner::Outcome::kRange:
        break;
      case FetchPlanner::Outcome::kNothing:
        return false;
      case FetchPlanner::Outcome::kBudgetTooSmall:
        // The most urgent item's bytes would be of no use, and when the head already brought them
        // all the plan would ask for nothing and be made again at once, for ever. The budget
        // counts as spent, and the stream settles.
        budget_spent_ = true;
        return false;
    }
    plan.known = head_.known(plan.offset, plan.size);
    return true;
  }

  // Under the lock: the head request's next bytes; makes the model once they hold the whole head.
  void takeHead(std::span<const std::uint8_t> piece) {
    ChunkedIssue issue;
    std::optional<ProgressiveModel> model = head_.take(piece, &issue);
    if (head_.failed()) return fail(describeAt(url_.text(), issue));
    if (model) {
      model_ = std::move(model);
      if (on_accepted_) on_accepted_(*model_, received_);
    }
    if (model_) {
      // Whatever followed the head in the first request: tables and chunks lying whole in it.
      const std::uint32_t before = model_->chunksIn(ChunkState::kHeld);
      // A part refused here is fetched again later as an item of its own: where it stopped and
      // why are not needed.
      static_cast<void>(model_->acceptBytes(0, head_.bytes(), &issue));
      if (on_accepted_ && model_->chunksIn(ChunkState::kHeld) != before)
        on_accepted_(*model_, received_);
    }
  }

  // Under the lock: hands the model every planned item whose bytes have all arrived.
  void deliver(const Plan& plan, const std::vector<std::uint8_t>& buffer, std::size_t& next) {
    next = planner_.deliver(*model_, plan, buffer, next,
                            [this](const FetchItem&, const ChunkedIssue& issue) {
                              if (issue.error != ChunkedError::kNone) {
                                ++refused_items_;
                                error_ = std::string("refused: ") + describe(issue.error);
                              } else if (on_accepted_) {
                                on_accepted_(*model_, received_);
                              }
                            });
  }

  void work() {
    RangeClient client(url_, options_.timeouts);
    std::unique_lock<std::mutex> lock(mutex_);
    clients_.push_back(&client);
    while (!stopping_ && !failed_) {
      if (Clock::now() < retry_after_) {
        cv_.wait_until(lock, retry_after_);
        continue;
      }
      Plan plan;
      if (!nextPlan(plan)) {
        cv_.wait_for(lock, std::chrono::milliseconds(100));
        continue;
      }
      std::vector<std::uint8_t> buffer = std::move(plan.known);
      std::size_t next = 0;
      if (!plan.head) deliver(plan, buffer, next);
      const std::uint64_t fetch_offset = plan.offset + buffer.size();
      const std::uint64_t fetch_size = plan.size - buffer.size();
      if (fetch_size == 0) {
        planner_.abandon(plan, next);
        continue;
      }
      ++busy_;
      ++requests_;
      outstanding_ += fetch_size;
      lock.unlock();
      const FetchResult result = client.fetch(
          fetch_offset, fetch_size,
          [&](std::uint64_t, std::span<const std::uint8_t> piece) {
            std::lock_guard<std::mutex> guard(mutex_);
            received_ += piece.size();
            outstanding_ -= piece.size();
            if (plan.head) {
              takeHead(piece);
            } else {
              buffer.insert(buffer.end(), piece.begin(), piece.end());
              deliver(plan, buffer, next);
            }
            return !stopping_ && !failed_;
          },
          &stopping_);
      lock.lock();
      outstanding_ -= fetch_size - result.bytes;
      --busy_;
      planner_.abandon(plan, next);
      if (plan.head) head_.in_flight = false;
      if (result.status == FetchStatus::kOk) {
        backoff_ = std::chrono::milliseconds(0);
        failures_in_a_row_ = 0;
      } else if (!stopping_ && !failed_) {
        ++failed_requests_;
        error_ = url_.text() + ": " + result.message;
        if (plan.head && result.status == FetchStatus::kHttpStatus &&
            headMissing(result.http_status)) {
          fail(error_);
        }
        // Slowness is the --timeout's to judge; anything else is the server's answer.
        if (!failed_ && result.status != FetchStatus::kTooSlow &&
            result.status != FetchStatus::kCancelled && options_.give_up_after > 0 &&
            ++failures_in_a_row_ >= options_.give_up_after) {
          fail(error_ + " (" + std::to_string(failures_in_a_row_) + " times in a row)");
        }
        backoff_ = std::clamp(backoff_ * 2, std::chrono::milliseconds(100),
                              std::chrono::milliseconds(2000));
        retry_after_ = Clock::now() + backoff_;
      }
      if (model_ && result.file_size != 0 && result.file_size != model_->head().file_bytes) {
        fail(url_.text() + ": the file is " + std::to_string(result.file_size) +
             " bytes now, not the " + std::to_string(model_->head().file_bytes) +
             " its head says: it changed");
      }
      cv_.notify_all();
    }
    clients_.erase(std::find(clients_.begin(), clients_.end(), &client));
  }

  HttpUrl url_;
  StreamOptions options_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable cv_;
  // Under mutex_:
  std::vector<RangeClient*> clients_;
  std::optional<ProgressiveModel> model_;
  HeadRead head_;  // the file's first bytes
  StreamView view_ = Camera{};
  FetchPlanner planner_;
  PerspectiveFetchOrder status_order_;  // statusLocked's count of a perspective view's items
  std::uint64_t received_ = 0, outstanding_ = 0;
  bool budget_spent_ = false;  // the budget left cannot hold the next item
  int busy_ = 0;
  bool failed_ = false;
  std::string error_;
  std::chrono::milliseconds backoff_{0};
  int failures_in_a_row_ = 0;
  Clock::time_point retry_after_{};
  std::uint32_t requests_ = 0, failed_requests_ = 0, refused_items_ = 0;
  std::function<void(ProgressiveModel&, std::uint64_t)> on_accepted_;
};

ModelStream::ModelStream(const HttpUrl& url, const StreamOptions& options)
    : impl_(std::make_unique<Impl>(url, options)) {}
ModelStream::~ModelStream() = default;
void ModelStream::start() { impl_->start(); }
void ModelStream::stop() { impl_->stop(); }
void ModelStream::setView(const Camera& camera) { impl_->setView(camera); }
void ModelStream::setView(const PerspectiveView& view) { impl_->setView(view); }
void ModelStream::clearView() { impl_->setView(std::monostate{}); }
StreamStatus ModelStream::status() { return impl_->status(); }
void ModelStream::withModel(const std::function<void(ProgressiveModel*)>& use) {
  impl_->withModel(use);
}
const ProgressiveModel* ModelStream::snapshot(ProgressiveFrame& frame) {
  return impl_->snapshot(frame);
}
const ProgressiveModel* ModelStream::model() { return impl_->model(); }
void ModelStream::onAccepted(std::function<void(ProgressiveModel&, std::uint64_t)> callback) {
  impl_->onAccepted(std::move(callback));
}
StreamStatus ModelStream::waitUntilSettled(std::chrono::milliseconds timeout) {
  return impl_->waitUntilSettled(timeout);
}

}  // namespace octopoint::net

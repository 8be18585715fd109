#include "codegen/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace octopoint::prepare {

unsigned threadCount(unsigned requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

void parallelFor(unsigned threads, std::size_t count,
                 const std::function<void(std::size_t, unsigned)>& task,
                 const std::function<void()>& tick) {
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_failure{kNone};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  const auto work = [&](unsigned worker) {
    for (;;) {
      const std::size_t index = next.fetch_add(1);
      if (index >= count || index > first_failure.load()) return;
      try {
        task(index, worker);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (index < first_failure.load()) {
          first_failure.store(index);
          failure = std::current_exception();
        }
      }
      if (worker == 0 && tick) tick();
    }
  };
  const unsigned helpers =
      static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1))) - 1;
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (unsigned worker = 1; worker <= helpers; ++worker) {
    try {
      pool.emplace_back(work, worker);
    } catch (const std::system_error&) {
      break;  // a process or address-space limit: the threads already started do all the work
    }
  }
  work(0);
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace octopoint::prepare

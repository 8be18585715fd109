#pragma once
// Work spread over threads so that the outcome does not depend on how many there are: tasks are
// numbered, handed out in ascending order, and when tasks fail the error reported is always the
// one of the lowest-numbered failing task (tasks after it are skipped, all before it have run).

#include <cstddef>
#include <functional>

namespace octopoint::prepare {

// The number of threads to use: `requested`, or every core when it is 0.
unsigned threadCount(unsigned requested);

// Runs task(index, worker) for every index in [0, count) on `threads` threads (the caller is
// worker 0; workers are numbered 0..threads-1, so per-worker state can live in a vector). The
// caller calls tick() between its tasks, for progress. Rethrows the lowest index's exception.
// Threads the system refuses to start (a process or address-space limit) are done without: the
// ones that started, at least the caller, run every task, and the outcome is the same.
void parallelFor(unsigned threads, std::size_t count,
                 const std::function<void(std::size_t, unsigned)>& task,
                 const std::function<void()>& tick = {});

}  // namespace octopoint::prepare

// The one parallel loop of the jobs: a table's rows, a points file's batch and Python's
// evaluate over arrays each call body(i) for i in [0, n) on a few threads. Indices are
// handed out in order, in blocks; the first failure (the lowest index whose body threw)
// stops the hand-out and is returned, not thrown, once every thread has joined, so the
// caller says what was kept; a caller's stop (an interrupt, a Python KeyboardInterrupt)
// is polled by the calling thread while the workers run.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace viscor::jobs {

/// How parallel_for runs.
struct parallel_for_options {
  unsigned threads = 1;    ///< workers (at most one per index); 1: the calling thread alone
  std::size_t block = 1;   ///< indices handed to a worker at a time
  /// Checked by a worker before each index: false stops the hand-out (a row budget, a
  /// signal). Empty: always go on. Must be cheap and thread-safe.
  std::function<bool()> keep_going;
  /// Called by the calling thread every poll_interval while workers run (progress, a
  /// Python signal check); false stops the hand-out. Empty: the calling thread works too.
  std::function<bool()> poll;
  std::chrono::milliseconds poll_interval{200};
};

/// What a parallel_for did.
struct parallel_for_result {
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::size_t failed_at = none;  ///< the lowest index whose body threw, or none
  std::exception_ptr failure;    ///< its exception
  bool stopped = false;          ///< keep_going or poll stopped the hand-out
  /// True when some body threw (failed_at and failure say which and what).
  bool failed() const { return failed_at != none; }
};

/// Calls body(i) for every i in [0, n) (body must be thread-safe for distinct i) and
/// returns the first failure and whether it was stopped; indices after a failure or a
/// stop may be left uncalled, indices already handed out finish.
template <class Body>
parallel_for_result parallel_for(std::size_t n, Body&& body, const parallel_for_options& options = {}) {
  parallel_for_result result;
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  const std::size_t block = std::max<std::size_t>(1, options.block);
  auto worker = [&] {
    for (;;) {
      if (stop) return;
      const std::size_t first = next.fetch_add(block);
      if (first >= n) return;
      for (std::size_t i = first; i < std::min(n, first + block); ++i) {
        if (options.keep_going && !options.keep_going()) {
          stop = true;
          std::lock_guard lock(mutex);
          result.stopped = true;
          return;
        }
        try {
          body(i);
        } catch (...) {
          std::lock_guard lock(mutex);
          if (i < result.failed_at) result.failed_at = i, result.failure = std::current_exception();
          stop = true;
          return;
        }
      }
    }
  };

  const std::size_t threads = std::clamp<std::size_t>(options.threads, 1, std::max<std::size_t>(1, n));
  if (threads == 1 && !options.poll) {
    worker();
    return result;
  }
  // With a poll the calling thread only coordinates; without one it is a worker too.
  const std::size_t spawned = options.poll ? threads : threads - 1;
  std::size_t running = spawned;
  std::condition_variable finished;
  std::vector<std::thread> pool;
  pool.reserve(spawned);
  for (std::size_t t = 0; t < spawned; ++t)
    pool.emplace_back([&] {
      worker();
      std::lock_guard lock(mutex);
      --running;
      finished.notify_all();
    });
  if (options.poll) {
    std::unique_lock lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, options.poll_interval);
      if (stop) continue;
      lock.unlock();  // the poll may take its time (Python takes the GIL)
      const bool go_on = options.poll();
      lock.lock();
      if (!go_on) stop = true, result.stopped = true;
    }
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  return result;
}

}  // namespace viscor::jobs

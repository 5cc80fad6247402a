// Timing one surrogate evaluation at a time, for benchmarks/surrogate_bench.cpp and
// `viscor bench --surrogate` (docs/performance.md, "Surrogates", has the figures).
//
// An evaluation costs ~40-200 ns, so a median and a maximum per evaluation need a
// clock read around each call that costs little and is itself measured:
//   * the clock is the time-stamp counter (rdtsc, constant rate on x86-64), fenced
//     by lfence on both sides so that the timed call neither starts before the first
//     read nor finishes after the second; its rate is calibrated against
//     std::chrono::steady_clock. Elsewhere: steady_clock. The counter's granularity
//     is measured and reported (on AMD Zen it steps ~10 ns at a time);
//   * the inputs are laundered through an empty asm statement after the first read
//     and the result before the second, so the compiler can neither hoist the
//     evaluation out of the timed region nor drop it (unlaundered, per-point counters
//     print ~2 ns: the repeats of a point are hoisted);
//   * the median of an empty timed region (same fences, same laundering) is
//     subtracted from every timing;
//   * every pass times each point once, in an order shuffled afresh for each pass
//     (a random stream: the branch predictors and caches see a new neighbour each
//     time). The median is over all timings. The maximum is over the points of each
//     point's least timing: an interrupt or a preemption (microseconds to
//     milliseconds) lands on some timing of a point, not on all of its passes, so the
//     slowest point is the evaluation's own worst case; the largest single timing is
//     kept as raw_max_ns and is such an interruption.
// A fenced call cannot overlap the next one, so this is the latency of one
// evaluation, more than the mean per evaluation in a stream of independent calls
// (stream_mean_ns, in CPU time of the thread), where the processor overlaps
// consecutive calls.
#pragma once

#include <viscor/surrogate/cor_surrogate.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <random>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace viscor::surrogate {

/// A point (gamma, g) at which an evaluation is timed.
struct timing_point {
  double gamma = 0, g = 0;
};

/// `count` fixed-seed random points in the surrogate's domain: gamma uniform in
/// [0, gamma_max]; g log-uniform in [1e-3, g_max] for half of them, uniform in
/// [g_min, 10] for the other half (a uniform g would put nearly every point at large
/// g, where nearly every point sticks).
inline std::vector<timing_point> timing_points(const cor_surrogate& s, std::size_t count, std::uint64_t seed = 2024) {
  std::mt19937_64 rng(seed);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<timing_point> points(count);
  for (auto& p : points) {
    p.gamma = s.gamma_max * u();
    p.g = u() < 0.5 ? std::exp(std::log(1e-3) + (std::log(s.g_max) - std::log(1e-3)) * u()) : s.g_min + (10 - s.g_min) * u();
  }
  return points;
}

/// The points at which the surrogate's outcome is `outcome`, in their order.
inline std::vector<timing_point> points_with_outcome(const cor_surrogate& s, const std::vector<timing_point>& points,
                                                     impact_outcome outcome) {
  std::vector<timing_point> kept;
  for (const auto& p : points)
    if (s(p.gamma, p.g).outcome == outcome) kept.push_back(p);
  return kept;
}

namespace detail {

// Makes the compiler assume x was read and changed here (no instruction is emitted).
template <class T>
inline void launder(T& x) noexcept {
#if defined(__GNUC__) || defined(__clang__)
  asm volatile("" : "+m"(x) : : "memory");
#else
  volatile T copy = x;
  x = copy;
#endif
}

// Clock ticks, fenced so that no earlier instruction is still running and no later
// one has started when the counter is read.
inline std::uint64_t fenced_ticks() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  _mm_lfence();
  const std::uint64_t t = __rdtsc();
  _mm_lfence();
  return t;
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

// The same clock, read without fences (to measure its step).
inline std::uint64_t raw_ticks() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

// Nanoseconds per tick of fenced_ticks, calibrated against steady_clock over ~20 ms.
inline double ns_per_tick() {
#if defined(__x86_64__) || defined(__i386__)
  static const double ns = [] {
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t k0 = fenced_ticks();
    while (std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(20)) {
    }
    const auto t1 = std::chrono::steady_clock::now();
    const std::uint64_t k1 = fenced_ticks();
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(k1 - k0);
  }();
  return ns;
#else
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::duration(1)).count();
#endif
}

// Nanoseconds of CPU time of the calling thread (POSIX; elsewhere wall time): on a
// shared machine a stream of calls is preempted, and wall time would count the wait.
inline double thread_cpu_ns() noexcept {
#if defined(__unix__) || defined(__APPLE__)
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
#else
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

inline double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace detail

/// Per-evaluation times of one function over a point set (nanoseconds).
struct evaluation_times {
  std::size_t points = 0;  ///< points timed
  int passes = 0;          ///< timings per point
  double median_ns = 0;    ///< median of all timings
  double p99_ns = 0;       ///< 99th percentile of all timings
  double max_ns = 0;       ///< the slowest point: the largest over the points of a point's least timing
  double raw_max_ns = 0;   ///< the largest single timing (interrupts included)
  double overhead_ns = 0;  ///< the median empty timed region, subtracted from every timing
  double resolution_ns = 0;  ///< the clock's smallest step
};

/// Times f(gamma, g) (which returns a double) at every point, one fenced call at a
/// time, `passes` times in orders shuffled from `seed`; see the header's comment.
template <class F>
evaluation_times time_each_evaluation(F&& f, const std::vector<timing_point>& points, int passes,
                                      std::uint64_t seed = 7) {
  const double ns = detail::ns_per_tick();
  evaluation_times out;
  out.points = points.size(), out.passes = passes;
  if (points.empty() || passes < 1) return out;
  {  // the clock's step: the least nonzero difference of successive unfenced reads
    std::uint64_t step = ~std::uint64_t{0}, last = detail::raw_ticks();
    for (int k = 0; k < 10000; ++k) {
      const std::uint64_t t = detail::raw_ticks();
      if (t != last) step = std::min(step, t - last);
      last = t;
    }
    out.resolution_ns = static_cast<double>(step) * ns;
  }
  {  // the overhead: the same timed region around no call
    std::vector<double> empty(4096);
    double x = 0;
    for (auto& t : empty) {
      const std::uint64_t t0 = detail::fenced_ticks();
      detail::launder(x);
      const std::uint64_t t1 = detail::fenced_ticks();
      t = static_cast<double>(t1 - t0) * ns;
    }
    out.overhead_ns = detail::median_of(empty);
  }
  std::vector<double> least(points.size(), HUGE_VAL), all;
  all.reserve(points.size() * static_cast<std::size_t>(passes));
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::mt19937_64 rng(seed);
  for (int pass = 0; pass < passes; ++pass) {
    std::shuffle(order.begin(), order.end(), rng);
    for (const std::size_t i : order) {
      double gamma = points[i].gamma, g = points[i].g;
      const std::uint64_t t0 = detail::fenced_ticks();
      detail::launder(gamma);
      detail::launder(g);
      double e = f(gamma, g);
      detail::launder(e);
      const std::uint64_t t1 = detail::fenced_ticks();
      const double t = std::max(0.0, static_cast<double>(t1 - t0) * ns - out.overhead_ns);
      least[i] = std::min(least[i], t);
      all.push_back(t);
    }
  }
  std::sort(all.begin(), all.end());
  out.median_ns = all[all.size() / 2];
  out.p99_ns = all[std::min(all.size() - 1, all.size() * 99 / 100)];
  out.raw_max_ns = all.back();
  out.max_ns = *std::max_element(least.begin(), least.end());
  return out;
}

/// Mean nanoseconds per call of f(gamma, g) over a stream of the points (no clock
/// read between calls, so the processor overlaps independent calls), `passes`
/// times over the points; the least of the passes' means, in CPU time of the thread.
template <class F>
double stream_mean_ns(F&& f, const std::vector<timing_point>& points, int passes) {
  double best = HUGE_VAL;
  if (points.empty()) return 0;
  for (int pass = 0; pass < passes; ++pass) {
    const double start = detail::thread_cpu_ns();
    for (const auto& p : points) {
      double gamma = p.gamma, g = p.g;
      detail::launder(gamma);
      detail::launder(g);
      double e = f(gamma, g);
      detail::launder(e);
    }
    best = std::min(best, (detail::thread_cpu_ns() - start) / static_cast<double>(points.size()));
  }
  return best;
}

}  // namespace viscor::surrogate

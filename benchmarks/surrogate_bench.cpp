// Time per CoR evaluation of the committed surrogates (reference_data/surrogates/)
// against the Taylor solve in double, in the same run; docs/performance.md
// ("Surrogates") has the figures and the method.
//
// Points: 16,384 fixed-seed random points in the domain (surrogate::timing_points:
// gamma uniform in [0, 1], g half log-uniform in [1e-3, 1e4], half uniform in
// [-0.5, 10]), timed as two streams: /mixed, all of them (about 78% stick), and
// /rebound, those where the bead rebounds (the 2-D Chebyshev sum; a stick needs none).
//   BM_surrogate/<law>/<stream>: Google Benchmark's time is one pass over the stream;
//     time_per_eval = that time / points. Counters from single fenced evaluations
//     (surrogate_timing.hpp: 9 passes in shuffled orders): median_ns (of all
//     timings), p99_ns, max_ns (the slowest point's least timing), raw_max_ns (the
//     largest single timing, an interrupt); stream_mean_ns (the least of 9 passes'
//     means); taylor_mean_ns and taylor_over_surrogate = taylor_mean_ns / stream_mean_ns.
//   BM_taylor_double/<law>/<stream>: solve_impact<double> on the stream's first 256
//     points (mean per point = time / 256); counter mean_ns: the least of 3 passes'
//     means, read by BM_surrogate (so run it first).
//   BM_gamma_for/<law>: the inverse on 1024 random (e, g) (mean per call = time / 1024).
// Run: ./build/benchmarks/surrogate_bench (Release, -DVISCOR_BUILD_BENCHMARKS=ON).
// $VISCOR_SURROGATE_DIR, if set, is searched instead of reference_data/surrogates
// (as by the CLI), e.g. to time a fit before it is verified and committed.
#include <viscor/core/contact_law.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_timing.hpp>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using viscor::surrogate::cor_surrogate;
using viscor::surrogate::timing_point;

constexpr std::size_t stream_points = 16384, taylor_points = 256;
constexpr int passes = 9;

const cor_surrogate* load(const std::string& law) {
  static std::map<std::string, cor_surrogate> cache;
  auto it = cache.find(law);
  if (it == cache.end()) {
    const char* dir = std::getenv("VISCOR_SURROGATE_DIR");
    const std::string path = (dir && *dir ? std::string(dir) : std::string(VISCOR_SOURCE_DIR) + "/reference_data/surrogates") +
                             "/" + law + ".surrogate";
    if (!std::filesystem::exists(path)) return nullptr;
    it = cache.emplace(law, viscor::surrogate::read_cor_surrogate(path)).first;
  }
  return &it->second;
}

// The stream's points: all of them, or the rebounds only.
std::vector<timing_point> stream(const cor_surrogate& s, bool rebound_only) {
  const auto all = viscor::surrogate::timing_points(s, stream_points);
  return rebound_only ? viscor::surrogate::points_with_outcome(s, all, viscor::impact_outcome::rebound) : all;
}

std::map<std::string, double> taylor_ns;  // law/stream -> mean per point; filled by BM_taylor_double

void BM_taylor_double(benchmark::State& state, const std::string& law_name, bool rebound_only) {
  const cor_surrogate* s = load(law_name);
  if (!s) return state.SkipWithError("no committed surrogate");
  const auto law = viscor::law_by_name(law_name);
  auto points = stream(*s, rebound_only);
  points.resize(std::min(points.size(), taylor_points));
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize(viscor::solve_impact<double>(law, p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
  const double mean = viscor::surrogate::stream_mean_ns(
      [&](double gamma, double g) { return viscor::solve_impact<double>(law, gamma, g).e; }, points, 3);
  taylor_ns[law_name + (rebound_only ? "/rebound" : "/mixed")] = mean;
  state.counters["mean_ns"] = mean;
}

void BM_surrogate(benchmark::State& state, const std::string& law_name, bool rebound_only) {
  const cor_surrogate* s = load(law_name);
  if (!s) return state.SkipWithError("no committed surrogate");
  const auto points = stream(*s, rebound_only);
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize((*s)(p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
  state.counters["points"] = static_cast<double>(points.size());
  state.counters["time_per_eval"] = benchmark::Counter(static_cast<double>(points.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  const auto f = [s](double gamma, double g) { return (*s)(gamma, g).e; };
  const auto t = viscor::surrogate::time_each_evaluation(f, points, passes);
  state.counters["median_ns"] = t.median_ns;
  state.counters["p99_ns"] = t.p99_ns;
  state.counters["max_ns"] = t.max_ns;
  state.counters["raw_max_ns"] = t.raw_max_ns;
  const double mean = viscor::surrogate::stream_mean_ns(f, points, passes);
  state.counters["stream_mean_ns"] = mean;
  const auto taylor = taylor_ns.find(law_name + (rebound_only ? "/rebound" : "/mixed"));
  if (taylor != taylor_ns.end()) {
    state.counters["taylor_mean_ns"] = taylor->second;
    state.counters["taylor_over_surrogate"] = taylor->second / mean;
  }
}

// The inverse: gamma_for(e, g) over 1024 fixed-seed random (e, g) (e in [0.01, 1),
// g as for the evaluations); the mean per call is Google Benchmark's time / 1024.
void BM_gamma_for(benchmark::State& state, const std::string& law_name) {
  const cor_surrogate* s = load(law_name);
  if (!s) return state.SkipWithError("no committed surrogate");
  const auto points = viscor::surrogate::timing_points(*s, 1024);
  std::mt19937_64 rng(77);
  std::vector<double> targets;
  for (std::size_t i = 0; i < points.size(); ++i) targets.push_back(0.01 + 0.98999 * static_cast<double>(rng() >> 11) * 0x1.0p-53);
  for (auto _ : state)
    for (std::size_t i = 0; i < points.size(); ++i) benchmark::DoNotOptimize(s->gamma_for(targets[i], points[i].g));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}

const int registered = [] {
  for (const char* law : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"}) {
    for (const bool rebound_only : {false, true}) {
      const std::string suffix = std::string("/") + law + (rebound_only ? "/rebound" : "/mixed");
      benchmark::RegisterBenchmark(("BM_taylor_double" + suffix).c_str(), BM_taylor_double, std::string(law), rebound_only)
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("BM_surrogate" + suffix).c_str(), BM_surrogate, std::string(law), rebound_only)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark((std::string("BM_gamma_for/") + law).c_str(), BM_gamma_for, std::string(law))
        ->Unit(benchmark::kMicrosecond);
  }
  return 0;
}();

}  // namespace

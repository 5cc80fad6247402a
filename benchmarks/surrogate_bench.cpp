// Time per CoR evaluation of the committed surrogates (reference_data/surrogates/)
// against the Taylor solve in double, in the same run.
//   BM_surrogate/<law>:   a stream of 4096 fixed-seed random points in the domain
//                         (mean ns per evaluation = Google Benchmark's time / 4096);
//                         counters median_ns and max_ns: per point, the time of 64
//                         repeated evaluations / 64, median and maximum over 2048 points;
//   BM_taylor_double/<law>: solve_impact<double> on 64 of the same points (mean);
//   counter ratio on BM_surrogate: mean Taylor time / median surrogate time.
// Run: ./build/benchmarks/surrogate_bench (Release, -DVISCOR_BUILD_BENCHMARKS=ON).
#include <viscor/core/contact_law.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using viscor::surrogate::cor_surrogate;

struct point {
  double gamma, g;
};

std::vector<point> random_points(const cor_surrogate& s, std::size_t n) {
  std::mt19937_64 rng(2024);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<point> p(n);
  for (auto& q : p) {
    q.gamma = s.gamma_max * u();
    // half the loads log-uniform over (1e-3, g_max), half uniform over (g_min, 10)
    q.g = u() < 0.5 ? std::exp(std::log(1e-3) + (std::log(s.g_max) - std::log(1e-3)) * u()) : s.g_min + (10 - s.g_min) * u();
  }
  return p;
}

const cor_surrogate* load(const std::string& law) {
  static std::map<std::string, cor_surrogate> cache;
  auto it = cache.find(law);
  if (it == cache.end()) {
    const std::string path = std::string(VISCOR_SOURCE_DIR) + "/reference_data/surrogates/" + law + ".surrogate";
    if (!std::filesystem::exists(path)) return nullptr;
    it = cache.emplace(law, viscor::surrogate::read_cor_surrogate(path)).first;
  }
  return &it->second;
}

std::map<std::string, double> taylor_ns;  // filled by BM_taylor_double, read by BM_surrogate

void BM_taylor_double(benchmark::State& state, const std::string& law_name) {
  const cor_surrogate* s = load(law_name);
  if (!s) return state.SkipWithError("no committed surrogate");
  const auto law = viscor::law_by_name(law_name);
  const auto points = random_points(*s, 64);
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize(viscor::solve_impact<double>(law, p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
  const auto start = std::chrono::steady_clock::now();
  for (const auto& p : points) benchmark::DoNotOptimize(viscor::solve_impact<double>(law, p.gamma, p.g).e);
  taylor_ns[law_name] = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                        static_cast<double>(points.size());
  state.counters["mean_ns"] = taylor_ns[law_name];
}

void BM_surrogate(benchmark::State& state, const std::string& law_name) {
  const cor_surrogate* s = load(law_name);
  if (!s) return state.SkipWithError("no committed surrogate");
  const auto points = random_points(*s, 4096);
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize((*s)(p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
  // Per point: 64 repeated evaluations timed together.
  std::vector<double> per_point;
  for (std::size_t i = 0; i < 2048; ++i) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < 64; ++k) {
      double gamma = points[i].gamma;
      benchmark::DoNotOptimize(gamma);
      benchmark::DoNotOptimize((*s)(gamma, points[i].g).e);
    }
    per_point.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / 64);
  }
  std::sort(per_point.begin(), per_point.end());
  state.counters["median_ns"] = per_point[per_point.size() / 2];
  state.counters["max_ns"] = per_point.back();
  if (taylor_ns.count(law_name)) state.counters["taylor_over_surrogate"] = taylor_ns[law_name] / per_point[per_point.size() / 2];
}

const int registered = [] {
  for (const char* law : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"}) {
    benchmark::RegisterBenchmark((std::string("BM_taylor_double/") + law).c_str(), BM_taylor_double, std::string(law))
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_surrogate/") + law).c_str(), BM_surrogate, std::string(law))
        ->Unit(benchmark::kMicrosecond);
  }
  return 0;
}();

}  // namespace

// Time per CoR of solve_impact (Taylor method) in double-double against float128 and
// MPFR at 30 digits, on the points of the bench table of docs/performance.md (five
// named laws x gamma in {1e-3, 1e-2, 0.1} x g in {0, 0.05, 1}: one iteration solves
// all 45; the counter per_cor is the time per CoR) and on the two Kuwabara-Kono points
// of solve_impact_bench. Needs QD (target viscor::double_double). Reproduce with
//   cmake -S . -B build -DVISCOR_BUILD_BENCHMARKS=ON && cmake --build build --target double_double_bench
//   ./build/benchmarks/double_double_bench
#include <viscor/core/double_double.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <string>
#include <vector>

namespace {

using namespace viscor;

struct bench_point {
  contact_law law;
  std::string gamma, g;
};

std::vector<bench_point> table_points() {
  std::vector<bench_point> points;
  for (const char* law : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"})
    for (const char* gamma : {"1e-3", "1e-2", "0.1"})
      for (const char* g : {"0", "0.05", "1"}) points.push_back({law_by_name(law), gamma, g});
  return points;
}

// The 45 points of the bench table, all solved per iteration.
template <class Real>
void solve_table_points(benchmark::State& state) {
  const std::vector<bench_point> points = table_points();
  std::vector<std::array<Real, 2>> inputs;
  for (const bench_point& p : points) inputs.push_back({parse_real<Real>(p.gamma, "gamma"), parse_real<Real>(p.g, "g")});
  for (auto _ : state) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const impact_result<Real> r = solve_impact<Real>(points[i].law, inputs[i][0], inputs[i][1]);
      benchmark::DoNotOptimize(r.e);
    }
  }
  state.counters["per_cor"] = benchmark::Counter(static_cast<double>(points.size()),
                                                 benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// arg 0: gamma = 0.05, g = 1;  arg 1: gamma = 1e-3, g = 0.05 (Kuwabara-Kono, as solve_impact_bench).
template <class Real>
void solve_kuwabara_kono(benchmark::State& state) {
  const contact_law law = law_by_name("kuwabara_kono");
  const bool first = state.range(0) == 0;
  const Real gamma = parse_real<Real>(first ? "0.05" : "1e-3", "gamma");
  const Real g = parse_real<Real>(first ? "1" : "0.05", "g");
  for (auto _ : state) {
    const impact_result<Real> r = solve_impact<Real>(law, gamma, g);
    benchmark::DoNotOptimize(r.e);
  }
  state.SetLabel(first ? "gamma=0.05 g=1" : "gamma=1e-3 g=0.05");
}

#if VISCOR_HAS_MPFR
// Run-time MPFR at 30 digits, the bench table's "mpfr 30" row.
template <void (*F)(benchmark::State&)>
void at_30_digits(benchmark::State& state) {
  scoped_precision digits(30);
  F(state);
}
#endif

BENCHMARK_TEMPLATE(solve_table_points, double_double)->Unit(benchmark::kMillisecond);
#if VISCOR_HAS_FLOAT128
BENCHMARK_TEMPLATE(solve_table_points, quad)->Unit(benchmark::kMillisecond);
#endif
#if VISCOR_HAS_MPFR
BENCHMARK_TEMPLATE(at_30_digits, solve_table_points<mpfr_real>)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK_TEMPLATE(solve_kuwabara_kono, double_double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
#if VISCOR_HAS_FLOAT128
BENCHMARK_TEMPLATE(solve_kuwabara_kono, quad)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
#endif
#if VISCOR_HAS_MPFR
BENCHMARK_TEMPLATE(at_30_digits, solve_kuwabara_kono<mpfr_real>)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace

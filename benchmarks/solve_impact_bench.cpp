// Time per CoR of solve_impact (Taylor method) for Kuwabara-Kono at the two
// parameter points of the timing targets (docs/performance.md), per scalar type. Reproduce with
//   cmake -S . -B build -DVISCOR_BUILD_BENCHMARKS=ON && cmake --build build --target solve_impact_bench
//   ./build/benchmarks/solve_impact_bench
// (the 1000-digit case is opt-in: --benchmark_filter=1000 --benchmark_min_time=1x... see below).
#include <viscor/impact/solve_impact.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace viscor;

// arg 0: gamma = 0.05, g = 1;  arg 1: gamma = 1e-3, g = 0.05
template <class Real>
void solve_kuwabara_kono(benchmark::State& state) {
  const contact_law law = law_by_name("kuwabara_kono");
  const bool first = state.range(0) == 0;
  const Real gamma = parse_real<Real>(first ? "0.05" : "1e-3", "gamma");
  const Real g = parse_real<Real>(first ? "1" : "0.05", "g");
  std::size_t steps = 0;
  for (auto _ : state) {
    const impact_result<Real> r = solve_impact<Real>(law, gamma, g);
    benchmark::DoNotOptimize(r.e);
    steps = r.steps;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.SetLabel(first ? "gamma=0.05 g=1" : "gamma=1e-3 g=0.05");
}

BENCHMARK_TEMPLATE(solve_kuwabara_kono, double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(solve_kuwabara_kono, long double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
#if VISCOR_HAS_FLOAT128
BENCHMARK_TEMPLATE(solve_kuwabara_kono, quad)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
#endif
#if VISCOR_HAS_MPFR
BENCHMARK_TEMPLATE(solve_kuwabara_kono, mpfr_50)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(solve_kuwabara_kono, mpfr_100)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// 1000 digits: one iteration each (tens of seconds).
void solve_kuwabara_kono_1000_digits(benchmark::State& state) {
  scoped_precision digits(1000);
  solve_kuwabara_kono<mpfr_real>(state);
}
BENCHMARK(solve_kuwabara_kono_1000_digits)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);
#endif

}  // namespace

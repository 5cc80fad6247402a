// Cost of viscor::certify relative to one Taylor solve (target: <= 4x at
// 50 and 100 digits), with the adaptive solve alone for reference; Kuwabara-Kono at
// the two points of the solve_impact benchmark. Reproduce with
//   cmake -S . -B build -DVISCOR_BUILD_BENCHMARKS=ON && cmake --build build --target certification_bench
//   ./build/benchmarks/certification_bench
// and divide the certify time by the taylor time of the same type and point.
#include <viscor/certify/certification.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace viscor;

// arg 0: gamma = 0.05, g = 1;  arg 1: gamma = 1e-3, g = 0.05
template <class Real>
std::pair<Real, Real> point(const benchmark::State& state) {
  const bool first = state.range(0) == 0;
  return {parse_real<Real>(first ? "0.05" : "1e-3", "gamma"), parse_real<Real>(first ? "1" : "0.05", "g")};
}

template <class Real>
void taylor(benchmark::State& state) {
  const auto [gamma, g] = point<Real>(state);
  const contact_law law = law_by_name("kuwabara_kono");
  for (auto _ : state) benchmark::DoNotOptimize(solve_impact_taylor<Real>(law, gamma, g, {}).e);
}

template <class Real>
void adaptive(benchmark::State& state) {
  const auto [gamma, g] = point<Real>(state);
  const contact_law law = law_by_name("kuwabara_kono");
  for (auto _ : state) benchmark::DoNotOptimize(solve_impact_adaptive<Real>(law, gamma, g, {}).e);
}

template <class Real>
void certification(benchmark::State& state) {
  const auto [gamma, g] = point<Real>(state);
  const contact_law law = law_by_name("kuwabara_kono");
  int digits = 0;
  for (auto _ : state) {
    const auto c = certify<Real>(law, gamma, g);
    benchmark::DoNotOptimize(c.e);
    digits = c.digits;
  }
  state.counters["certified_digits"] = digits;
}

BENCHMARK_TEMPLATE(taylor, double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(adaptive, double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(certification, double)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
#if VISCOR_HAS_MPFR
BENCHMARK_TEMPLATE(taylor, mpfr_50)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(adaptive, mpfr_50)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(certification, mpfr_50)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(taylor, mpfr_100)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(adaptive, mpfr_100)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(certification, mpfr_100)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

// Time per evaluation of each approximate CoR formula (approximations.hpp), with
// the per-law constants built once, next to the time of the CoR integrated by
// solve_impact, so the speed-accuracy trade is visible. Targets in
// double: small g and large g <= 100 ns; Prop. 2 with Chebyshev-Beta
// coefficients <= 5 us; with tanh-sinh coefficients <= 50 us. Reproduce with
//   cmake -S . -B build -DVISCOR_BUILD_BENCHMARKS=ON && cmake --build build --target approximations_bench
//   ./build/benchmarks/approximations_bench
#include <viscor/approx/approximations.hpp>
#include <viscor/exact/exact_solutions.hpp>
#if __has_include(<viscor/impact/solve_impact.hpp>)
#include <viscor/impact/solve_impact.hpp>
#define VISCOR_BENCH_SOLVE_IMPACT 1
#endif

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace viscor;

// The g of a benchmark argument: the report's values and two large loads.
double g_of(std::int64_t arg) {
  static const double values[] = {0.0, 0.05, 1.0, 10.0, 1e3, 1e6};
  return values[arg];
}

template <class Real>
const cor_approximations<Real>& kuwabara_kono() {
  static const cor_approximations<Real> approx(law_by_name("kuwabara_kono"));
  return approx;
}

template <class Real>
void small_g(benchmark::State& state) {
  const auto& approx = kuwabara_kono<Real>();
  Real gamma = Real(1) / 20, g = Real(1) / 20;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(g);
    benchmark::DoNotOptimize(approx.small_g(gamma, g));
  }
}

template <class Real>
void large_g(benchmark::State& state) {
  const auto& approx = kuwabara_kono<Real>();
  Real gamma = Real(1) / 20, g = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(g);
    benchmark::DoNotOptimize(approx.large_g(gamma, g));
  }
}

template <class Real>
void schwager_poschel(benchmark::State& state) {
  const auto& approx = kuwabara_kono<Real>();
  Real gamma = Real(1) / 20, g = Real(1) / 20;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(g);
    benchmark::DoNotOptimize(approx.schwager_poschel(gamma, g));
  }
}

template <class Real>
void prop2(benchmark::State& state, coefficient_source source) {
  const auto& approx = kuwabara_kono<Real>();
  Real gamma = Real(1) / 20, g = Real(g_of(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(g);
    benchmark::DoNotOptimize(approx.prop2(gamma, g, source).e);
  }
  state.SetLabel("g=" + std::to_string(g_of(state.range(0))));
}

template <class Real>
void prop2_exact_at_zero(benchmark::State& state) { prop2<Real>(state, coefficient_source::exact_at_zero); }
template <class Real>
void prop2_chebyshev_beta(benchmark::State& state) { prop2<Real>(state, coefficient_source::chebyshev_beta); }
template <class Real>
void prop2_numeric(benchmark::State& state) { prop2<Real>(state, coefficient_source::numeric); }

template <class Real>
void build_constants(benchmark::State& state) {
  const contact_law law = law_by_name("kuwabara_kono");
  for (auto _ : state) {
    const cor_approximations<Real> approx(law);
    benchmark::DoNotOptimize(approx.closed_forms().C2);
  }
}

template <class Real>
void theta_of_g_only(benchmark::State& state) {
  Real alpha = Real(3) / 2, g = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(g);
    benchmark::DoNotOptimize(theta_of_g(alpha, g));
  }
}

#ifdef VISCOR_BENCH_SOLVE_IMPACT
// The CoR the approximations approximate, integrated to working precision.
template <class Real>
void solve_impact_reference(benchmark::State& state) {
  const contact_law law = law_by_name("kuwabara_kono");
  Real gamma = Real(1) / 20, g = Real(g_of(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(solve_impact<Real>(law, gamma, g).e);
  }
  state.SetLabel("g=" + std::to_string(g_of(state.range(0))));
}
BENCHMARK_TEMPLATE(solve_impact_reference, double)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
#endif

// A closed-form exact CoR (linear law, any g), for scale.
void exact_linear_law(benchmark::State& state) {
  const contact_law law = law_by_name("linear");
  double gamma = 0.05, g = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(exact_cor(law, gamma, g)->e);
  }
}
BENCHMARK(exact_linear_law)->Unit(benchmark::kMicrosecond);

BENCHMARK_TEMPLATE(small_g, double);
BENCHMARK_TEMPLATE(large_g, double);
BENCHMARK_TEMPLATE(schwager_poschel, double);
BENCHMARK_TEMPLATE(prop2_exact_at_zero, double)->Arg(0);
BENCHMARK_TEMPLATE(prop2_chebyshev_beta, double)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(prop2_numeric, double)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(theta_of_g_only, double);
BENCHMARK_TEMPLATE(build_constants, double)->Unit(benchmark::kMicrosecond);

// The same formulas at high precision, where they separate formula error from rounding.
BENCHMARK_TEMPLATE(small_g, mpfr_50);
BENCHMARK_TEMPLATE(prop2_chebyshev_beta, mpfr_50)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(prop2_numeric, mpfr_50)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(prop2_numeric, mpfr_100)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

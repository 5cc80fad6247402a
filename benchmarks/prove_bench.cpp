// Cost of a proof (viscor::enclose, include/viscor/enclose/) against the Taylor solve
// (solve_impact) at the same precision, for the points of docs/performance.md
// ("Proven enclosures"): the linear law at gamma = 0.05, g = 0.5 (prove_linear_impact)
// and the two laws with alpha - (beta - 1) an integer, Kuwabara-Kono and Hunt-Crossley,
// (gamma = 0.05 and 0.02, g = 1; prove_impact), at 30 and 50 digits.
// The Taylor solve runs in the type `viscor cor --digits D` uses (float128 at 30
// digits, MPFR at 50) and, for a like-for-like arithmetic, in MPFR at D digits.
// Reproduce with
//   cmake -S . -B build -DVISCOR_BUILD_BENCHMARKS=ON && cmake --build build --target prove_bench
//   ./build/benchmarks/prove_bench
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/enclose/enclose.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace viscor;

struct bench_point {
  const char* law;
  const char* gamma;
  const char* g;
};

// arg 0: linear, gamma = 0.05, g = 0.5; arg 1: Kuwabara-Kono, gamma = 0.05, g = 1;
// arg 2: Hunt-Crossley, gamma = 0.02, g = 1 (at gamma = 0.05 it sticks).
constexpr bench_point points[] = {
    {"linear", "0.05", "0.5"}, {"kuwabara_kono", "0.05", "1"}, {"hunt_crossley", "0.02", "1"}};

std::string label(const bench_point& p, int digits, const std::string& how) {
  return std::string(p.law) + " gamma=" + p.gamma + " g=" + p.g + " digits=" + std::to_string(digits) + " " + how;
}

/// viscor::enclose: the proof and its decimal bounds, as `viscor prove` and table method "proven" run it.
void prove(benchmark::State& state) {
  const bench_point& p = points[state.range(0)];
  const int digits = static_cast<int>(state.range(1));
  const contact_law law = law_by_name(p.law);
  std::size_t steps = 0;
  int proven_digits = 0;
  for (auto _ : state) {
    const proofs::cor_enclosure r = viscor::enclose(law, p.gamma, p.g, digits);
    benchmark::DoNotOptimize(r.e.digits);
    steps = r.balls.steps;
    proven_digits = r.e.digits;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["proven_digits"] = proven_digits;
  state.SetLabel(label(p, digits, "proof"));
}

template <class Real>
void taylor_loop(benchmark::State& state, const bench_point& p) {
  const contact_law law = law_by_name(p.law);
  const Real gamma = parse_real<Real>(p.gamma, "gamma"), g = parse_real<Real>(p.g, "g");
  std::size_t steps = 0;
  for (auto _ : state) {
    const impact_result<Real> r = solve_impact<Real>(law, gamma, g);
    benchmark::DoNotOptimize(r.e);
    steps = r.steps;
  }
  state.counters["steps"] = static_cast<double>(steps);
}

/// The Taylor solve in the working type of `viscor cor --digits D` (with_working_precision).
void taylor(benchmark::State& state) {
  const bench_point& p = points[state.range(0)];
  const int digits = static_cast<int>(state.range(1));
  with_working_precision(digits, [&]<class Real>() { taylor_loop<Real>(state, p); });
  state.SetLabel(label(p, digits, "taylor " + to_string(scalar_for_digits(digits))));
}

#if VISCOR_HAS_MPFR
/// The Taylor solve in MPFR at D digits (the proof's own arithmetic is MPFR-like: Arb balls).
void taylor_mpfr(benchmark::State& state) {
  const bench_point& p = points[state.range(0)];
  const int digits = static_cast<int>(state.range(1));
  scoped_precision precision(digits);
  taylor_loop<mpfr_real>(state, p);
  state.SetLabel(label(p, digits, "taylor mpfr"));
}
BENCHMARK(taylor_mpfr)->ArgsProduct({{0, 1, 2}, {30, 50}})->Unit(benchmark::kMillisecond);
#endif

BENCHMARK(prove)->ArgsProduct({{0, 1, 2}, {30, 50}})->Unit(benchmark::kMillisecond);
BENCHMARK(taylor)->ArgsProduct({{0, 1, 2}, {30, 50}})->Unit(benchmark::kMillisecond);

}  // namespace

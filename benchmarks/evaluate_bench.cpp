// Accuracy-driven evaluation (evaluate.hpp) and calibration (calibration.hpp):
// cost per CoR at a stated tolerance, without error maps (so the Taylor solve or
// certify does the work), for Kuwabara-Kono at the report's steel-bead point.
// `viscor bench` reports the same trade with accuracies and with error maps.
#include <viscor/scenes/calibration.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/certify/extern_templates.hpp>

#include <benchmark/benchmark.h>

namespace {

const viscor::contact_law law = viscor::law_by_name("kuwabara_kono");

// Tolerance 10^-k with the scalar type a scene at that tolerance would use.
void evaluate_at(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  viscor::with_working_precision(k <= 12 ? 15 : k + 3, [&]<class Real>() {
    using std::pow;
    const viscor::evaluator<Real> ev(law);
    const Real gamma = Real(66) / 1000, g = Real(5) / 10000, tol = pow(Real(10), -k);
    for (auto _ : state) benchmark::DoNotOptimize(ev(gamma, g, tol).e);
  });
}
BENCHMARK(evaluate_at)->Arg(4)->Arg(10)->Arg(14)->Arg(20)->Arg(30)->Arg(40)->Unit(benchmark::kMicrosecond);

void calibrate_steel_bead(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(viscor::calibrate_gamma0(law, 2.05e-3, 6.9716e9, 0.246, 9.8, 0.0, 0.893).gamma0);
}
BENCHMARK(calibrate_steel_bead)->Unit(benchmark::kMicrosecond);

}  // namespace

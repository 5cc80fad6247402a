// Time per evaluation of the C export of the committed surrogates
// (examples/c_export/viscor_surrogates.c, compiled as C99 by the C compiler, baseline
// target, no FMA instruction: every fma a libm call) next to the library's
// cor_surrogate (run-time FMA path where the CPU has it) on the same points;
// docs/performance.md ("Surrogates", "The C export") has the figures.
//   BM_library/<law>/<stream>, BM_exported_c/<law>/<stream>: one pass over the stream of
//     surrogate_bench (16,384 timing_points; /rebound: the rebounds among them);
//     Google Benchmark's time is one pass, time per evaluation = time / points
//     (items_per_second is its inverse).
//   BM_library_gamma_for/<law>, BM_exported_c_gamma_for/<law>: the inverse on the 1024
//     (e, g) of surrogate_bench's BM_gamma_for.
//   BM_exported_c_cor_physical/<law>, BM_exported_c_damping_for/<law>: the physical entry
//     points (viscor_cor_physical; viscor_damping_for, a target e -> gamma0) on the 1024
//     impacts below (m* and k from viscor_contact_of), each with the damping that gives
//     its target, so cor_physical meets the rebounds a deck is calibrated for.
//   BM_exported_c_damping_entry/<model>, BM_exported_c_dem_deck/<model>: each DEM code's
//     entries (viscor_dem_damping_entry; viscor_dem_deck with the like-bead entries) on
//     1024 impacts: rigid walls, steel to polymer beads of 0.1-20 mm at 1 mm/s to 5 m/s,
//     with and without gravity, targets 0.1-0.95 (docs/dem.md, "Each code's entries").
// Run: ./build/benchmarks/surrogate_export_bench (Release, -DVISCOR_BUILD_BENCHMARKS=ON).
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_timing.hpp>

#include "viscor_surrogates.h"  // examples/c_export/ (the committed export)

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using viscor::surrogate::cor_surrogate;
using viscor::surrogate::timing_point;

const cor_surrogate& load(const std::string& law) {
  static std::map<std::string, cor_surrogate> cache;
  auto it = cache.find(law);
  if (it == cache.end())
    it = cache.emplace(law, viscor::surrogate::read_cor_surrogate(std::string(VISCOR_SOURCE_DIR) +
                                                                  "/reference_data/surrogates/" + law + ".surrogate"))
             .first;
  return it->second;
}

std::vector<timing_point> stream(const cor_surrogate& s, bool rebound_only) {
  const auto all = viscor::surrogate::timing_points(s, 16384);
  return rebound_only ? viscor::surrogate::points_with_outcome(s, all, viscor::impact_outcome::rebound) : all;
}

void BM_library(benchmark::State& state, const std::string& law, bool rebound_only) {
  const cor_surrogate& s = load(law);
  const auto points = stream(s, rebound_only);
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize(s(p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}

void BM_exported_c(benchmark::State& state, const std::string& law, bool rebound_only) {
  const viscor_surrogate* c = viscor_surrogate_named(law.c_str());
  if (!c) return state.SkipWithError("law not in the export");
  const auto points = stream(load(law), rebound_only);
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize(viscor_cor_at(c, p.gamma, p.g).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}

// The (e, g) of surrogate_bench's BM_gamma_for.
std::pair<std::vector<double>, std::vector<timing_point>> inverse_inputs(const cor_surrogate& s) {
  const auto points = viscor::surrogate::timing_points(s, 1024);
  std::mt19937_64 rng(77);
  std::vector<double> targets;
  for (std::size_t i = 0; i < points.size(); ++i) targets.push_back(0.01 + 0.98999 * static_cast<double>(rng() >> 11) * 0x1.0p-53);
  return {targets, points};
}

void BM_library_gamma_for(benchmark::State& state, const std::string& law) {
  const cor_surrogate& s = load(law);
  const auto [targets, points] = inverse_inputs(s);
  for (auto _ : state)
    for (std::size_t i = 0; i < points.size(); ++i) benchmark::DoNotOptimize(s.gamma_for(targets[i], points[i].g));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}

void BM_exported_c_gamma_for(benchmark::State& state, const std::string& law) {
  const viscor_surrogate* c = viscor_surrogate_named(law.c_str());
  if (!c) return state.SkipWithError("law not in the export");
  const auto [targets, points] = inverse_inputs(load(law));
  for (auto _ : state)
    for (std::size_t i = 0; i < points.size(); ++i) benchmark::DoNotOptimize(viscor_gamma_for(c, targets[i], points[i].g));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}

// Impacts as a DEM deck has them (rigid wall), with a target each.
struct dem_input {
  viscor_dem_impact impact;
  double target;
};

std::vector<dem_input> dem_inputs() {
  std::mt19937_64 rng(56);
  auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto log_uniform = [&](double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); };
  std::vector<dem_input> out;
  for (int i = 0; i < 1024; ++i) {
    dem_input d{};
    d.impact.bead = {log_uniform(1e7, 2e11), uniform(0.2, 0.45), log_uniform(1e-4, 2e-2), uniform(1000, 8000)};
    d.impact.v0 = log_uniform(1e-3, 5);
    d.impact.gravity = i % 2 ? 9.81 : 0.0;
    d.target = uniform(0.1, 0.95);
    out.push_back(d);
  }
  return out;
}

void BM_exported_c_dem(benchmark::State& state, int model, bool whole_deck) {
  const auto inputs = dem_inputs();
  for (auto _ : state)
    for (const auto& d : inputs)
      benchmark::DoNotOptimize(whole_deck ? viscor_dem_deck(static_cast<viscor_dem_model>(model), d.target, &d.impact).damping
                                          : viscor_dem_damping_entry(static_cast<viscor_dem_model>(model), d.target, &d.impact));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * inputs.size()));
}

// viscor_cor_physical and viscor_damping_for on the impacts of dem_inputs.
struct physical_input {
  double m, k, v0, gravity, target, gamma0;
};

std::vector<physical_input> physical_inputs(const viscor_surrogate* s) {
  std::vector<physical_input> out;
  for (const auto& d : dem_inputs()) {
    const viscor_contact c = viscor_contact_of(&d.impact);
    physical_input p{c.mass, c.stiffness, d.impact.v0, c.gravity, d.target, 0};
    p.gamma0 = viscor_damping_for(s, p.target, p.m, p.k, p.v0, p.gravity, 0);
    if (std::isnan(p.gamma0)) p.gamma0 = 0;  // outside the surrogate's domain: timed as it is refused
    out.push_back(p);
  }
  return out;
}

void BM_exported_c_physical(benchmark::State& state, const std::string& law, bool inverse) {
  const viscor_surrogate* s = viscor_surrogate_named(law.c_str());
  if (!s) return state.SkipWithError("law not in the export");
  const auto inputs = physical_inputs(s);
  for (auto _ : state)
    for (const auto& p : inputs)
      benchmark::DoNotOptimize(inverse ? viscor_damping_for(s, p.target, p.m, p.k, p.v0, p.gravity, 0)
                                       : viscor_cor_physical(s, p.m, p.k, p.gamma0, p.v0, p.gravity, 0).e);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * inputs.size()));
  // seconds per call, printed with its SI prefix (e.g. 140n)
  state.counters["per_call"] = benchmark::Counter(static_cast<double>(inputs.size()),
                                                  benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

const int registered = [] {
  const std::pair<int, const char*> models[] = {{VISCOR_LAMMPS_VELOCITY, "lammps_velocity"},
                                                {VISCOR_LAMMPS_MASS_VELOCITY, "lammps_mass_velocity"},
                                                {VISCOR_LAMMPS_VISCOELASTIC, "lammps_viscoelastic"},
                                                {VISCOR_LAMMPS_TSUJI, "lammps_tsuji"},
                                                {VISCOR_LIGGGHTS_HERTZ, "liggghts_hertz"}};
  for (const auto& [model, name] : models) {
    benchmark::RegisterBenchmark((std::string("BM_exported_c_damping_entry/") + name).c_str(), BM_exported_c_dem, model,
                                 false)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_exported_c_dem_deck/") + name).c_str(), BM_exported_c_dem, model,
                                 true)->Unit(benchmark::kMicrosecond);
  }
  for (const char* law : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"}) {
    for (const bool rebound_only : {false, true}) {
      const std::string suffix = std::string("/") + law + (rebound_only ? "/rebound" : "/mixed");
      benchmark::RegisterBenchmark(("BM_library" + suffix).c_str(), BM_library, std::string(law), rebound_only)
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("BM_exported_c" + suffix).c_str(), BM_exported_c, std::string(law), rebound_only)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark((std::string("BM_exported_c_cor_physical/") + law).c_str(), BM_exported_c_physical,
                                 std::string(law), false)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_exported_c_damping_for/") + law).c_str(), BM_exported_c_physical,
                                 std::string(law), true)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_library_gamma_for/") + law).c_str(), BM_library_gamma_for,
                                 std::string(law))->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_exported_c_gamma_for/") + law).c_str(), BM_exported_c_gamma_for,
                                 std::string(law))->Unit(benchmark::kMicrosecond);
  }
  return 0;
}();

}  // namespace

// Shared by evaluate_test.cpp and evaluate_slow_test.cpp: random scene points,
// error maps built here from 30-digit solves, and the check of one evaluation's
// empirical bound against a reference computed at higher precision by other
// methods (certify, or the adaptive solver) than the Taylor solves evaluate makes.
#pragma once

#include "test_utils.hpp"

#include <viscor/scenes/error_map_builder.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/certify/extern_templates.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <memory>
#include <random>
#include <string>

namespace viscor::test {

struct scene_point {
  contact_law law;
  std::string gamma, g;  // shortest decimals of doubles: exact in every type
  int tolerance_exponent = 4;  // tolerance 10^-k
  bool relative = false;
};

inline std::string shortest_decimal(double x) { return detail::shortest(x); }

/// Random points: the five named laws, gamma log-uniform in [1e-6, 3], g = 0 (20%),
/// pulling g in [-1, 0) (15%) or log-uniform in [1e-4, 100]; tolerance 10^-k,
/// k uniform in [k_min, k_max]; a quarter with the bound relative on 1 - e.
inline std::vector<scene_point> random_points(std::uint64_t seed, int count, int k_min, int k_max) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<scene_point> out;
  for (int n = 0; n < count; ++n) {
    scene_point p;
    p.law = law_by_name(named_laws[static_cast<std::size_t>(u(rng) * named_laws.size()) % named_laws.size()].name);
    p.gamma = shortest_decimal(std::pow(10.0, -6 + u(rng) * std::log10(3e6)));
    const double which = u(rng);
    p.g = which < 0.2 ? "0" : which < 0.35 ? shortest_decimal(-u(rng)) : shortest_decimal(std::pow(10.0, -4 + 6 * u(rng)));
    p.tolerance_exponent = k_min + static_cast<int>(u(rng) * (k_max - k_min + 1));
    if (p.tolerance_exponent > k_max) p.tolerance_exponent = k_max;
    p.relative = u(rng) < 0.25;
    out.push_back(p);
  }
  return out;
}

/// Error maps of the named laws on gamma in [1e-5, 0.3] x g in [0, 10] from
/// solve_impact at 30 digits; `per_interval` samples per cell edge.
inline std::map<std::string, std::shared_ptr<error_map>> test_maps(int per_interval) {
  const std::vector<std::string> ge{"1e-5", "1e-4", "1e-3", "1e-2", "3e-2", "0.1", "0.3"};
  const std::vector<std::string> gg{"0", "0.05", "0.5", "2", "10"};
  std::map<std::string, std::shared_ptr<error_map>> maps;
  for (const auto& named : named_laws) {
    const contact_law law = law_by_name(named.name);
    error_map_spec spec;
    spec.gamma_edges = ge, spec.g_edges = gg;
    maps[law.name] = std::make_shared<error_map>(
        build_error_map(law, reference_by_solve(law, grid_nodes(ge, per_interval), grid_nodes(gg, per_interval), 30), spec));
  }
  return maps;
}

/// What was checked, for the summary.
struct check_counts {
  std::map<std::string, int> by_method;
  int checked = 0;
};

/// Evaluates p at its tolerance (double down to 1e-13, mpfr_real at 3 more digits
/// below) and checks |e - ref| <= bound <= tolerance against `reference_e` and
/// `reference_one_minus_e` (decimal text at higher precision).
template <class Reference>
::testing::AssertionResult check_point(const scene_point& p, const error_map* map, Reference reference,
                                       check_counts& counts) {
  return with_working_precision(p.tolerance_exponent <= 13 ? 15 : p.tolerance_exponent + 3,
                                [&]<class Real>() -> ::testing::AssertionResult {
    using std::abs;
    using std::pow;
    evaluate_options options;
    options.relative = p.relative;
    options.map = map;
    const Real tol = pow(Real(10), -p.tolerance_exponent);
    const evaluation<Real> r = evaluate(p.law, parse_real<Real>(p.gamma, "gamma"), parse_real<Real>(p.g, "g"), tol, options);
    ++counts.checked;
    ++counts.by_method[to_string(r.method)];
    const std::string where = p.law.describe() + ", gamma = " + p.gamma + ", g = " + p.g + ", tolerance 1e-" +
                              std::to_string(p.tolerance_exponent) + (p.relative ? " (relative on 1 - e)" : "") +
                              ", method " + to_string(r.method) + " at " + std::to_string(r.working_digits) + " digits";
    if (!(r.bound <= tol))
      return ::testing::AssertionFailure() << where << ": bound " << to_decimal_string(r.bound, 3) << " > tolerance";
    // Compare in a type wider than both.
    const int ref_digits = std::max(p.tolerance_exponent, 16) + 25;
    const auto [e_ref_text, ome_ref_text] = reference(p, ref_digits);
    const std::string e_text = to_decimal_string(r.e, roundtrip_digits<Real>() + 2);
    const std::string ome_text = to_decimal_string(r.one_minus_e, roundtrip_digits<Real>() + 2);
    const std::string bound_text = to_decimal_string(r.bound, roundtrip_digits<Real>() + 2);
    return with_working_precision(ref_digits, [&]<class Ref>() -> ::testing::AssertionResult {
      const Ref bound = parse_real<Ref>(bound_text, "bound");
      const Ref e_ref = parse_real<Ref>(e_ref_text, "e_ref"), ome_ref = parse_real<Ref>(ome_ref_text, "ome_ref");
      const Ref err = p.relative ? Ref(abs(parse_real<Ref>(ome_text, "ome") - ome_ref))
                                 : Ref(abs(parse_real<Ref>(e_text, "e") - e_ref));
      const Ref allowed = p.relative ? Ref(bound * ome_ref) : bound;
      if (err <= allowed) return ::testing::AssertionSuccess();
      return ::testing::AssertionFailure() << where << ": error " << to_decimal_string(err, 3) << " > bound "
                                           << to_decimal_string(allowed, 3) << "\n  e   = " << e_text
                                           << "\n  ref = " << e_ref_text;
    });
  });
}

/// Reference by the adaptive (GBS) method at `digits` (twice the digits or more of
/// anything checked against it): independent of the Taylor solves evaluate makes.
inline std::pair<std::string, std::string> adaptive_reference(const scene_point& p, int digits) {
  return with_working_precision(digits, [&]<class Ref>() {
    solve_options<Ref> options;
    options.method = integration_method::adaptive;
    const impact_result<Ref> r =
        solve_impact(p.law, parse_real<Ref>(p.gamma, "gamma"), parse_real<Ref>(p.g, "g"), options);
    return std::pair<std::string, std::string>(to_decimal_string(r.e), to_decimal_string(r.one_minus_e));
  });
}

/// Which references certified_reference used.
struct reference_tally {
  int certified = 0, adaptive = 0;
};
inline reference_tally& references_used() {
  static reference_tally tally;
  return tally;
}

/// certify at `digits`; where it certifies too few digits for the comparison
/// (close to the sticking threshold), the adaptive method at twice the digits.
inline std::pair<std::string, std::string> certified_reference(const scene_point& p, int digits) {
  const int needed = std::max(p.tolerance_exponent, 16) + 5;
  const auto certified = with_working_precision(digits, [&]<class Ref>() -> std::optional<std::pair<std::string, std::string>> {
    const certified_result<Ref> c = certify(p.law, parse_real<Ref>(p.gamma, "gamma"), parse_real<Ref>(p.g, "g"));
    if (!c.outcome_certified) return std::nullopt;
    if (c.outcome == impact_outcome::rebound && c.certified_digits < needed && c.certified_absolute_digits_e < needed) return std::nullopt;
    return std::pair<std::string, std::string>(to_decimal_string(c.e), to_decimal_string(c.one_minus_e));
  });
  if (certified) {
    ++references_used().certified;
    return *certified;
  }
  ++references_used().adaptive;
  return adaptive_reference(p, 2 * digits);
}

}  // namespace viscor::test

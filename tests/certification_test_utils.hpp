// Shared by certification_test.cpp and certification_slow_test.cpp: the honesty
// check (certified digits never exceed the digits that agree with an independent
// truth) and the random parameter sample. The truth is a closed form where one
// exists, else the adaptive (GBS) method at 2 x digits + 10: never the Taylor
// solver that certify's reference runs, so that the check tests the method and not
// only its convergence in precision.
#pragma once

#include <viscor/certify/certification.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/impact/adaptive_impact.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::test {

struct sample_point {
  contact_law law;
  std::string gamma, g;  ///< decimal text: exact in every type under test
  std::string describe() const { return law.describe() + ", gamma = " + gamma + ", g = " + g; }
};

/// Every exact-solution case of the foundation issue (linear law at any g; beta =
/// alpha + 1 and Tsuji at g = 0; gamma = 0).
inline std::vector<sample_point> exact_sample_points() {
  std::vector<sample_point> points;
  const contact_law linear = law_by_name("linear");
  for (const char* g : {"0", "0.05", "1", "10"})
    for (const char* gamma : {"1e-8", "1e-3", "0.1", "0.5", "1.5"}) points.push_back({linear, gamma, g});
  for (auto [p, q] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{2, 1}}) {
    const contact_law hc{exponent::rational(p, q), exponent::rational(p + q, q), ""};
    for (const char* gamma : {"1e-8", "1e-3", "0.1", "1.5"}) points.push_back({hc, gamma, "0"});
  }
  for (const char* gamma : {"1e-8", "1e-3", "0.1", "1.5"}) points.push_back({law_by_name("tsuji"), gamma, "0"});
  for (const auto& n : named_laws) points.push_back({law_by_name(n.name), "0", "1"});
  return points;
}

/// `count` random points, fixed seed: named laws or random rational exponents p/q in
/// [1, 3] (q <= 6), gamma log-uniform in [1e-8, 2], g uniform in [0, 100]; all
/// printed with 6 significant digits so that they are exact decimal inputs.
inline std::vector<sample_point> random_sample_points(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick_law(0, 7), pick_q(1, 6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<sample_point> points;
  auto text = [](double x) {
    std::ostringstream out;
    out.precision(6);
    out << x;
    return out.str();
  };
  auto random_exponent = [&] {
    const int q = pick_q(rng);
    std::uniform_int_distribution<int> pick_p(q, 3 * q);
    return exponent::rational(pick_p(rng), q);
  };
  for (int i = 0; i < count; ++i) {
    const int which = pick_law(rng);
    contact_law law = which < 5 ? law_by_name(named_laws[which].name) : contact_law{random_exponent(), random_exponent(), ""};
    const double gamma = std::pow(10.0, -8.0 + unit(rng) * (8.0 + std::log10(2.0)));
    const double g = 100.0 * unit(rng);
    points.push_back({law, text(gamma), text(g)});
  }
  return points;
}

/// Digits on which x agrees with the truth t (relative), in the reference type; 1000 if equal.
template <class Ref>
int true_digits(const Ref& x, const Ref& t) {
  using boost::math::isinf;
  using std::abs;
  using std::floor;
  using std::log10;
  if (isinf(x) || isinf(t)) return x == t ? 1000 : 0;
  if (x == t) return 1000;
  if (t == 0) return 0;
  const Ref d = floor(-log10(Ref(abs(x - t) / abs(t))));
  return d <= 0 ? 0 : static_cast<int>(d);
}

/// Certifies the point in Real and fails the test on a single over-claim: the
/// certified digits must not exceed the digits on which e, 1 - e, T_f and u_max
/// agree with the exact solution, or else with the adaptive method at 2 * digits +
/// 10 (mpfr_real; digits + 10 where that is undecided). Returns what certify said.
/// `options`: closed_form = false certifies the linear law by the integrators too.
template <class Real>
certified_result<Real> check_honesty(const sample_point& p, const certify_options& options = {}) {
  SCOPED_TRACE(p.describe() + (options.closed_form ? "" : " (integrators)"));
  const Real gamma = parse_real<Real>(p.gamma, "gamma"), g = parse_real<Real>(p.g, "g");
  const certified_result<Real> c = certify<Real>(p.law, gamma, g, options);
  const int reference_digits = 2 * decimal_digits<Real>() + 10;
  scoped_precision precision(reference_digits);
  const mpfr_real rg = detail::widen<mpfr_real>(gamma), rgg = detail::widen<mpfr_real>(g);
  impact_outcome truth_outcome;
  mpfr_real truth_e, truth_one_minus_e, truth_time, truth_u_max;
  bool time_known = true, u_max_known = true;
  std::string source;
  if (const auto exact = exact_cor<mpfr_real>(p.law, rg, rgg)) {
    truth_outcome = exact->outcome, truth_e = exact->e, truth_one_minus_e = exact->one_minus_e;
    time_known = exact->contact_time.has_value();
    if (time_known) truth_time = *exact->contact_time;
    u_max_known = exact->max_compression.has_value();
    if (u_max_known) truth_u_max = *exact->max_compression;
    source = exact->formula;
  } else {
    // NOTE: a creep up to the equilibrium can be `undecided` by the adaptive method at
    // 2 x digits + 10 (its rest test needs half of them; Tsuji gamma = 1e2, g = 1e-3 at
    // 40 digits) and decided at fewer: its outcomes are proven at any precision, so
    // the truth falls back to digits + 10 (still 10 beyond the claim).
    for (const int digits : {reference_digits, decimal_digits<Real>() + 10}) {
      scoped_precision truth_precision(digits);
      const auto t = solve_impact_adaptive<mpfr_real>(p.law, detail::widen<mpfr_real>(gamma),
                                                      detail::widen<mpfr_real>(g), solve_options<mpfr_real>{});
      truth_outcome = t.outcome, truth_e = t.e, truth_one_minus_e = t.one_minus_e;
      time_known = t.contact_time.has_value();
      if (time_known) truth_time = *t.contact_time;
      truth_u_max = t.max_compression;
      source = "adaptive at " + std::to_string(digits) + " digits";
      if (truth_outcome != impact_outcome::undecided) break;
    }
  }
  SCOPED_TRACE("truth: " + source);
  if (!c.outcome_certified) {
    EXPECT_EQ(c.certified_digits, 0) << "an uncertified outcome carries no digits";
    return c;
  }
  if (c.outcome != truth_outcome) {
    ADD_FAILURE() << "certified outcome " << to_string(c.outcome) << " but the truth is " << to_string(truth_outcome);
    return c;
  }
  int agree = 1000;
  std::string worst = "none";
  auto compare = [&](const char* what, const Real& x, const mpfr_real& t) {
    const int d = true_digits(detail::widen<mpfr_real>(x), t);
    if (d < agree) agree = d, worst = std::string(what) + " = " + to_decimal_string(x) + ", truth " + to_decimal_string(t);
  };
  if (c.outcome == impact_outcome::rebound) {
    compare("e", c.e, truth_e);
    compare("1 - e", c.one_minus_e, truth_one_minus_e);
  }
  using boost::math::isnan;
  // NaN: unknown to the certification (no digits agree)
  if (time_known && !isnan(truth_time)) compare("T_f", viscor::detail::or_nan(c.contact_time), truth_time);
  if (u_max_known) compare("u_max", c.max_compression, truth_u_max);
  EXPECT_LE(c.certified_digits, agree) << "over-claim: certified " << c.certified_digits << " digits, " << agree << " are right; " << worst;
  EXPECT_LE(c.certified_digits, decimal_digits<Real>());
  return c;
}

}  // namespace viscor::test

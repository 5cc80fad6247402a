// Shared by overdamped_test.cpp and overdamped_slow_test.cpp (the overdamped extremes).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/widen.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <boost/math/special_functions/fpclassify.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <type_traits>

namespace viscor::test {

inline constexpr const char* overdamped_laws[] = {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono",
                                                  "hunt_crossley"};

/// What these tests claim, per scalar type, as relative tolerances: contact times agree
/// (the two methods with each other, the Taylor solver with the linear law's closed
/// form), maximal compressions agree (the same pairs; and a stick under a load reaches
/// u_max >= u* (1 - compression)), and e agrees with a closed form where there is one.
/// Each is about 100x the worst disagreement measured over every comparison of
/// overdamped_test and overdamped_slow_test (2026-12-04, GCC 12 Release, x86-64): a
/// one-off build printing |x - y| / |y| at each comparison (not committed), run as
/// `build/tests/overdamped_test` and `build/tests/overdamped_slow_test`. Worst measured:
///   double:  contact time 4.7e-14 (Hertz with linear damping, gamma = 2, g = 1, the two
///            methods; 3.1e-14 against the closed form), u_max 1.0e-15 (at most 1.7e-16 below u*),
///            e 6.5e-16 against the closed form;
///   mpfr_50: contact time 2.9e-49 (the same point; 3.0e-50 against the closed form),
///            u_max 2.5e-50 (at most 2.5e-50 below u*), e 1.9e-50 against the closed form.
/// Between the two methods without a closed form, e is held to the `rel` the caller
/// of check_creep_out states. Another scalar type needs its own measurement.
template <class Real>
struct overdamped_claims {
  Real contact_time, compression, e_closed_form;
};

template <class Real>
overdamped_claims<Real> overdamped_tolerances() {
  if constexpr (std::is_same_v<Real, double>) {
    return {5e-12, 1e-13, 7e-14};
  } else {
    static_assert(std::is_same_v<Real, mpfr_50>, "measure the agreement at this type first (see above)");
    return {Real("3e-47"), Real("3e-48"), Real("2e-48")};
  }
}

/// Two results agree on a time or an overlap: both +infinity, or within `rel`; NaN
/// (a quantity the method says it does not know) agrees with anything.
template <class Real>
bool agree_or_unknown(const Real& x, const Real& y, const Real& rel) {
  using boost::math::isinf;
  using boost::math::isnan;
  using std::abs;
  if (isnan(x) || isnan(y)) return true;
  if (isinf(x) || isinf(y)) return x == y;
  return abs(x - y) <= rel * abs(y);
}

/// The same for an optional quantity (a contact time): unknown (empty) agrees with anything.
template <class Real>
bool agree_or_unknown(const std::optional<Real>& x, const std::optional<Real>& y, const Real& rel) {
  return !x || !y || agree_or_unknown(*x, *y, rel);
}

/// The same, the second quantity known.
template <class Real>
bool agree_or_unknown(const std::optional<Real>& x, const Real& y, const Real& rel) {
  return !x || agree_or_unknown(*x, y, rel);
}

/// g > 0, gamma large: both methods say stick, within a step budget far below the
/// default, and agree with each other (contact time both +inf or within the claimed
/// tolerance; u_max within it, at least u*); the linear law's closed form says the same.
template <class Real>
void check_creep_up(const char* law_name, const char* gamma_text, const char* g_text) {
  SCOPED_TRACE(std::string(law_name) + ", gamma = " + gamma_text + ", g = " + g_text);
  using boost::math::isnan;
  using std::pow;
  const contact_law law = law_by_name(law_name);
  const Real gamma = parse_real<Real>(gamma_text, "gamma"), g = parse_real<Real>(g_text, "g");
  const overdamped_claims<Real> tol = overdamped_tolerances<Real>();
  solve_options<Real> options;
  options.max_steps = 100000;  // steps bounded by the fast damping scale need over 1e6 at gamma >= 1e4, g >= 1e6
  const Real u_star = pow(g, 1 / law.alpha.template value<Real>());
  const impact_result<Real> t = solve_impact_taylor<Real>(law, gamma, g, options);
  const impact_result<Real> a = solve_impact_adaptive<Real>(law, gamma, g, options);
  for (const impact_result<Real>* r : {&t, &a}) {
    SCOPED_TRACE(std::string(to_string(r->method)));
    EXPECT_EQ(r->outcome, impact_outcome::stick);
    EXPECT_EQ(r->e, 0);
    EXPECT_GE(r->max_compression, u_star * (1 - tol.compression)) << to_decimal_string(r->max_compression);
  }
  auto agree = [](const Real& x, const Real& y, const Real& rel) {
    return !isnan(x) && !isnan(y) && agree_or_unknown(x, y, rel);
  };
  EXPECT_TRUE(t.contact_time && a.contact_time && agree(*t.contact_time, *a.contact_time, tol.contact_time))
      << to_decimal_string(viscor::detail::or_nan(t.contact_time)) << " vs "
      << to_decimal_string(viscor::detail::or_nan(a.contact_time));
  EXPECT_TRUE(agree(t.max_compression, a.max_compression, tol.compression))
      << to_decimal_string(t.max_compression) << " vs " << to_decimal_string(a.max_compression);
  if (std::string(law_name) == "linear") {
    const exact_result<Real> x = exact_linear(gamma, g);
    EXPECT_EQ(x.outcome, impact_outcome::stick);
    ASSERT_TRUE(x.contact_time.has_value());
    EXPECT_TRUE(t.contact_time && agree(*t.contact_time, *x.contact_time, tol.contact_time))
        << to_decimal_string(*x.contact_time);
    ASSERT_TRUE(x.max_compression.has_value());
    EXPECT_TRUE(agree(t.max_compression, *x.max_compression, tol.compression))
        << to_decimal_string(*x.max_compression);
  }
}

/// The truth for e where a closed form gives it: the linear law at any g, beta = alpha + 1
/// at g = 0; evaluated at 2 x digits + 20 (mpfr_real) and rounded to Real.
template <class Real>
std::optional<Real> closed_form_e(const contact_law& law, const Real& gamma, const Real& g) {
  scoped_precision precision(2 * decimal_digits<Real>() + 20);
  const auto x = exact_cor<mpfr_real>(law, detail::widen<mpfr_real>(gamma), detail::widen<mpfr_real>(g));
  if (!x) return std::nullopt;
  EXPECT_EQ(x->outcome, impact_outcome::rebound);
  return detail::narrow<Real>(x->e, 0);
}

/// g <= 0, gamma large: past maximal compression the bead creeps out along the slow
/// manifold, a stiff motion each method follows with its own implicit steps. Both must
/// rebound within a step budget far below the default (explicit steps would take
/// ~gamma/|g| of them, over 1e6); e within the claimed tolerance of the closed form
/// where there is one, else within `rel` of the other method; and no error estimate
/// below the error it estimates.
template <class Real>
void check_creep_out(const char* law_name, const char* gamma_text, const char* g_text, const Real& rel) {
  SCOPED_TRACE(std::string(law_name) + ", gamma = " + gamma_text + ", g = " + g_text);
  using std::abs;
  const contact_law law = law_by_name(law_name);
  const Real gamma = parse_real<Real>(gamma_text, "gamma"), g = parse_real<Real>(g_text, "g");
  solve_options<Real> options;
  options.max_steps = 100000;
  const impact_result<Real> t = solve_impact_taylor<Real>(law, gamma, g, options);
  const impact_result<Real> a = solve_impact_adaptive<Real>(law, gamma, g, options);
  ASSERT_EQ(t.outcome, impact_outcome::rebound) << "taylor";
  ASSERT_EQ(a.outcome, impact_outcome::rebound) << "adaptive";
  ASSERT_GT(t.e, 0);
  const std::optional<Real> exact = closed_form_e(law, gamma, g);
  for (const impact_result<Real>* r : {&t, &a}) {
    SCOPED_TRACE(std::string(to_string(r->method)) + ": e = " + to_decimal_string(r->e) +
                 ", error_estimate = " + to_decimal_string(r->error_estimate, 3));
    const Real truth = exact ? *exact : (r == &t ? a.e : t.e);
    const Real claimed = exact ? overdamped_tolerances<Real>().e_closed_form : rel;
    EXPECT_LE(abs(r->e - truth), claimed * truth) << "truth " << to_decimal_string(truth);
    if (exact) EXPECT_LE(abs(r->e - truth), r->error_estimate) << "the error estimate claims too much";
  }
  if (!exact) EXPECT_LE(abs(t.e - a.e), t.error_estimate + a.error_estimate) << "the error estimates claim too much";
}

/// One point of the overdamped box with the default options, as a user gets it (a
/// step-budget refusal throws and fails the test). The Taylor solver must decide
/// (rebound or stick); the adaptive method must say the same or `undecided`, which is
/// returned so the caller can count them. A rebound: e > 0, the two values of e within
/// the sum of their error estimates, each within its estimate of the closed form where
/// there is one. A stick: e = 0, u_max at least the equilibrium g^(1/alpha) for g > 0.
/// Both: contact time and u_max agree within the claimed tolerances; for the linear law
/// the closed form's outcome, contact time and u_max are the same.
template <class Real>
impact_outcome check_overdamped_point(const char* law_name, const char* gamma_text, const char* g_text) {
  SCOPED_TRACE(std::string(law_name) + ", gamma = " + gamma_text + ", g = " + g_text);
  using std::abs;
  using std::pow;
  const contact_law law = law_by_name(law_name);
  const Real gamma = parse_real<Real>(gamma_text, "gamma"), g = parse_real<Real>(g_text, "g");
  const overdamped_claims<Real> tol = overdamped_tolerances<Real>();
  impact_result<Real> t, a;
  try {
    t = solve_impact_taylor<Real>(law, gamma, g, solve_options<Real>{});
    a = solve_impact_adaptive<Real>(law, gamma, g, solve_options<Real>{});
  } catch (const std::exception& error) {
    ADD_FAILURE() << "refused: " << error.what();
    return impact_outcome::undecided;
  }
  EXPECT_NE(t.outcome, impact_outcome::undecided) << "taylor";
  if (a.outcome != impact_outcome::undecided) EXPECT_EQ(a.outcome, t.outcome) << "adaptive";
  const bool both = a.outcome == t.outcome;
  auto describe = [](const impact_result<Real>& r) {
    return std::string(to_string(r.method)) + ": e = " + to_decimal_string(r.e) +
           " +- " + to_decimal_string(r.error_estimate, 3) + ", T = " + to_decimal_string(viscor::detail::or_nan(r.contact_time), 12) +
           ", u_max = " + to_decimal_string(r.max_compression, 12);
  };
  SCOPED_TRACE(describe(t) + "; " + describe(a));
  if (t.outcome == impact_outcome::rebound) {
    EXPECT_GT(t.e, 0);
    if (both) EXPECT_LE(abs(t.e - a.e), t.error_estimate + a.error_estimate) << "the error estimates claim too much";
    if (const std::optional<Real> exact = closed_form_e(law, gamma, g))
      for (const impact_result<Real>* r : {&t, &a})
        if (r->outcome == impact_outcome::rebound)
          EXPECT_LE(abs(r->e - *exact), r->error_estimate)
              << to_string(r->method) << " claims too much; closed form " << to_decimal_string(*exact);
  } else if (t.outcome == impact_outcome::stick) {
    EXPECT_EQ(t.e, 0);
    if (both) EXPECT_EQ(a.e, 0);
    if (g > 0) {
      const Real u_star = pow(g, 1 / law.alpha.template value<Real>());
      EXPECT_GE(t.max_compression, u_star * (1 - tol.compression));
      if (both) EXPECT_GE(a.max_compression, u_star * (1 - tol.compression));
    }
  }
  if (both) {
    EXPECT_TRUE(agree_or_unknown(t.contact_time, a.contact_time, tol.contact_time)) << "contact times differ";
    EXPECT_TRUE(agree_or_unknown(t.max_compression, a.max_compression, tol.compression)) << "u_max differ";
  }
  if (std::string(law_name) == "linear") {
    const exact_result<Real> x = exact_linear(gamma, g);
    EXPECT_EQ(x.outcome, t.outcome) << "the closed form's outcome";
    if (x.contact_time) EXPECT_TRUE(agree_or_unknown(t.contact_time, *x.contact_time, tol.contact_time))
        << "closed form T = " << to_decimal_string(*x.contact_time);
    if (x.max_compression) EXPECT_TRUE(agree_or_unknown(t.max_compression, *x.max_compression, tol.compression))
        << "closed form u_max = " << to_decimal_string(*x.max_compression);
  }
  return a.outcome;
}

}  // namespace viscor::test

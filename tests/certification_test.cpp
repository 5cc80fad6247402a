// viscor::certify: honesty on the exact cases and a small random sample (the big
// sweeps are in certification_slow_test.cpp), the 45-digit floor at 50 digits on
// representative points, loud disagreement under a perturbed method, outcome
// disagreement, and absolute digits near the sticking threshold. The perturbation
// is a test seam (detail::certify_perturbed), not an option of certify.
#include "certification_test_utils.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>

namespace {

using namespace viscor;
using viscor::test::check_honesty;

// The linear law's points are certified by its closed form; this asks for the two integrators.
certify_options integrators_only() {
  certify_options options;
  options.closed_form = false;
  return options;
}

// Honesty is checked only where certify certifies (check_honesty returns early
// otherwise): each sweep also requires that it certifies, with digits, at least the
// points it certified when written, so that certifying nothing cannot pass.
template <class Real>
int certified_with_digits(const certified_result<Real>& c) {
  return c.outcome_certified && c.certified_digits > 0;
}

TEST(certification, honest_on_every_exact_case_in_double) {
  const auto points = test::exact_sample_points();
  int certified = 0;
  for (const auto& p : points) {
    certified += certified_with_digits(check_honesty<double>(p));
    certified += certified_with_digits(check_honesty<double>(p, integrators_only()));
  }
  EXPECT_GE(certified, 82) << "of " << 2 * points.size();
}

#if VISCOR_HAS_MPFR
TEST(certification, honest_on_exact_cases_at_50_digits) {
  const auto points = test::exact_sample_points();
  int certified = 0, checked = 0;
  for (std::size_t i = 0; i < points.size(); i += 3) {
    certified += certified_with_digits(check_honesty<mpfr_50>(points[i]));
    certified += certified_with_digits(check_honesty<mpfr_50>(points[i], integrators_only()));
    checked += 2;
  }
  EXPECT_GE(certified, 28) << "of " << checked;
}
#endif

TEST(certification, honest_on_a_random_sample_in_double) {
  int certified = 0;
  for (const auto& p : test::random_sample_points(24, 20240611u)) certified += certified_with_digits(check_honesty<double>(p));
  EXPECT_GE(certified, 24) << "of 24";
}

#if VISCOR_HAS_MPFR
TEST(certification, honest_on_a_small_random_sample_at_50_digits) {
  // The first points of the slow test's 60-point sample.
  int certified = 0;
  for (const auto& p : test::random_sample_points(6, 777u)) certified += certified_with_digits(check_honesty<mpfr_50>(p));
  EXPECT_GE(certified, 6) << "of 6";
}
#endif

// The digit counter on cases whose answer is known exactly (binary fractions: the
// relative difference is exact): floor(-log10(|a - b| / |scale|)) within [0, cap].
TEST(certification, agreement_digits_counts_whole_digits) {
  using detail::agreement_digits;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(agreement_digits(1.0, 1.0 + std::ldexp(1.0, -20), 1.0, 50), 6);   // 9.54e-7: 6.02 digits
  EXPECT_EQ(agreement_digits(1.0, 1.0 + std::ldexp(1.0, -10), 1.0, 50), 3);   // 9.77e-4: 3.01
  EXPECT_EQ(agreement_digits(1.0, 1.0 + std::ldexp(1.0, -12), 1.0, 50), 3);   // 2.44e-4: 3.61
  EXPECT_EQ(agreement_digits(1.0, 1.25, 1.0, 50), 0);                         // 0.25: 0.60
  EXPECT_EQ(agreement_digits(8.0, 8.0 + std::ldexp(1.0, -17), 8.0, 50), 6);   // relative to the scale: 9.54e-7
  EXPECT_EQ(agreement_digits(8.0, 8.0 + std::ldexp(1.0, -17), 1.0, 50), 5);   // absolute: 7.63e-6, 5.12
  EXPECT_EQ(agreement_digits(-1.0, -1.0 - std::ldexp(1.0, -20), -1.0, 50), 6);  // signs do not matter
  EXPECT_EQ(agreement_digits(1.0, 4.0, 1.0, 50), 0);                          // worse than no digit: 0, not negative
  EXPECT_EQ(agreement_digits(1.0, 1.0 + std::ldexp(1.0, -52), 1.0, 10), 10);  // capped
  EXPECT_EQ(agreement_digits(1.0, 1.0, 1.0, 17), 17);                          // equal: the cap
  EXPECT_EQ(agreement_digits(inf, inf, 1.0, 17), 17);
  EXPECT_EQ(agreement_digits(inf, 1.0, 1.0, 17), 0);
  EXPECT_EQ(agreement_digits(nan, nan, 1.0, 17), 0);
  EXPECT_EQ(agreement_digits(1.0, 1.5, 0.0, 17), 0);                          // no scale: nothing
#if VISCOR_HAS_MPFR
  EXPECT_EQ(agreement_digits(mpfr_50(1), mpfr_50(mpfr_50(1) + mpfr_50("3e-47")), mpfr_50(1), 50), 46);  // 46.52
#endif
}

#if VISCOR_HAS_MPFR
// Below the cap, the certified digits are exactly the least agreement of the Taylor
// run and of the independent check with the reference, minus the safety margin; the
// agreement is counted here by the tests' own rule (true_digits) against the reference
// solve repeated here (Taylor at the reference precision), not by certify's counter.
TEST(certification, uncapped_digits_are_the_agreement_minus_the_margin) {
  const contact_law law = law_by_name("kuwabara_kono");
  const mpfr_50 gamma("0.05"), g(1);
  const auto c = certify<mpfr_50>(law, gamma, g);
  ASSERT_TRUE(c.outcome_certified);
  ASSERT_EQ(c.computations.size(), 3u);
  ASSERT_EQ(c.computations[1].source, certified_source::taylor_reference);
  scoped_precision precision(c.computations[1].precision_digits);
  const auto ref = solve_impact_taylor<mpfr_real>(law, detail::widen<mpfr_real>(gamma), detail::widen<mpfr_real>(g), {});
  int agreement = 50;  // capped at the working digits
  for (const auto* x : {&c.computations[0], &c.computations[2]})
    for (auto [a, b] : {std::pair{x->e, ref.e}, std::pair{x->one_minus_e, ref.one_minus_e},
                        std::pair{x->contact_time.value(), ref.contact_time.value()}, std::pair{x->max_compression, ref.max_compression}})
      agreement = std::min(agreement, test::true_digits(detail::widen<mpfr_real>(a), b));
  ASSERT_LT(agreement, 50) << "the case must be uncapped";
  EXPECT_EQ(c.safety_margin, 2);
  EXPECT_EQ(c.certified_digits, agreement - 2);
}
#endif

#if VISCOR_HAS_MPFR
TEST(certification, at_least_45_digits_at_50_for_named_laws) {
  // Representative points of the acceptance grid (the full grid is in the slow test).
  for (const auto& n : named_laws) {
    for (auto [gamma, g] : {std::pair{"0.05", "1"}, std::pair{"1e-3", "0.05"}}) {
      const auto c = certify<mpfr_50>(law_by_name(n.name), mpfr_50(gamma), mpfr_50(g));
      EXPECT_TRUE(c.outcome_certified) << n.name << " gamma = " << gamma << " g = " << g;
      EXPECT_GE(c.certified_digits, 45) << n.name << " gamma = " << gamma << " g = " << g;
      EXPECT_LE(c.certified_digits, 50);
      if (std::string(n.name) == "linear") {  // certified by its closed form at two precisions
        ASSERT_EQ(c.computations.size(), 2u);
        EXPECT_EQ(c.computations[0].source, certified_source::closed_form);
        EXPECT_EQ(c.computations[1].source, certified_source::closed_form_reference);
      } else {
        ASSERT_EQ(c.computations.size(), 3u);
        EXPECT_EQ(c.computations[0].source, certified_source::taylor);
        EXPECT_EQ(c.computations[1].source, certified_source::taylor_reference);
        EXPECT_EQ(c.computations[2].source, certified_source::adaptive);
      }
      EXPECT_GT(c.computations[1].precision_digits, 50);
    }
  }
}
#endif

TEST(certification, a_perturbed_method_makes_certification_drop) {
  // A deliberately wrong damping coefficient (relative 1e-8) in one computation.
  const contact_law kk = law_by_name("kuwabara_kono");
  const auto clean = certify<double>(kk, 0.05, 1.0);
  ASSERT_TRUE(clean.outcome_certified);
  ASSERT_GE(clean.certified_digits, 12);
  for (auto which : {certified_source::taylor, certified_source::taylor_reference, certified_source::adaptive}) {
    const auto c = detail::certify_perturbed<double>(kk, 0.05, 1.0, {}, {which, "1e-8"});
    EXPECT_LE(c.certified_digits, 8) << to_string(which);
    EXPECT_LT(c.certified_digits, clean.certified_digits - 3) << to_string(which);
  }
}

#if VISCOR_HAS_MPFR
TEST(certification, a_perturbed_method_makes_certification_drop_at_50_digits) {
  const auto c = detail::certify_perturbed<mpfr_50>(law_by_name("tsuji"), mpfr_50("0.05"), mpfr_50(1), {},
                                                    {certified_source::adaptive, "1e-30"});
  EXPECT_TRUE(c.outcome_certified);
  EXPECT_LE(c.certified_digits, 30);
  EXPECT_GE(c.certified_digits, 20);  // the other two still agree: the drop is the perturbation's size
}
#endif

TEST(certification, outcome_disagreement_is_uncertified_not_averaged) {
  // Linear law, g = 1: gamma = 0.1 rebounds, gamma = 1.1 sticks; perturb the adaptive run's gamma by 10x.
  const auto c = detail::certify_perturbed<double>(law_by_name("linear"), 0.1, 1.0, integrators_only(),
                                                   {certified_source::adaptive, "10"});
  EXPECT_FALSE(c.outcome_certified);
  EXPECT_EQ(c.certified_digits, 0);
  EXPECT_EQ(c.certified_absolute_digits_e, 0);
  EXPECT_TRUE(c.near_sticking);
  EXPECT_EQ(c.computations[2].outcome, impact_outcome::stick);
  EXPECT_EQ(c.computations[0].outcome, impact_outcome::rebound);
}

TEST(certification, near_the_sticking_threshold_absolute_digits_are_reported) {
  // Linear law, g = 0, gamma just below 2: e = exp(-xi pi/omega) ~ 7e-5.
  const auto c = certify<double>(law_by_name("linear"), 1.9, 0.0);
  ASSERT_TRUE(c.outcome_certified);
  EXPECT_EQ(c.outcome, impact_outcome::rebound);
  EXPECT_TRUE(c.near_sticking);
  EXPECT_GE(c.certified_absolute_digits_e, 13);
  const auto exact = exact_linear(1.9, 0.0);
  using std::abs;
  EXPECT_LE(abs(c.e - exact.e), std::pow(10.0, -c.certified_absolute_digits_e));
}

TEST(certification, an_undecided_outcome_is_uncertified) {
  // Linear law, g = 0, gamma = 1.9999: e ~ 4e-137, which the adaptive method cannot
  // tell from a creep into u = 0 (undecided, contact_time unknown) in double nor at the
  // 20-digit reference precision it is repeated at.
  const auto c = certify<double>(law_by_name("linear"), 1.9999, 0.0, integrators_only());
  ASSERT_EQ(c.computations.size(), 4u);
  EXPECT_EQ(c.computations[2].outcome, impact_outcome::undecided);
  EXPECT_EQ(c.computations[3].source, certified_source::adaptive_reference);
  EXPECT_EQ(c.computations[3].outcome, impact_outcome::undecided);
  EXPECT_FALSE(c.outcome_certified);
  EXPECT_EQ(c.certified_digits, 0);
  EXPECT_EQ(c.certified_absolute_digits_e, 0);
  EXPECT_EQ(c.computations[2].certified_digits_contact_time, 0);
}

TEST(certification, an_adaptive_run_undecided_in_double_is_repeated_at_the_reference_precision) {
  // Kuwabara-Kono, gamma = 1e10, g = 0: e ~ 7e-51, below what the adaptive method
  // resolves in double (undecided: a creep into u = 0 or a rebound), not at the 20-digit
  // reference precision, where it is the independent check; certify certifies the
  // rebound, honestly (truth: the adaptive method at 40 digits,
  // tests/certification_test_utils.hpp; before this, uncertified).
  const test::sample_point p{law_by_name("kuwabara_kono"), "1e10", "0"};
  const auto c = check_honesty<double>(p);
  ASSERT_EQ(c.computations.size(), 4u);
  EXPECT_EQ(c.computations[2].outcome, impact_outcome::undecided);
  EXPECT_EQ(c.computations[3].source, certified_source::adaptive_reference);
  EXPECT_EQ(c.computations[3].precision_digits, c.computations[1].precision_digits);
  EXPECT_TRUE(c.outcome_certified);
  EXPECT_EQ(c.outcome, impact_outcome::rebound);
  EXPECT_GE(c.certified_digits, 10);
  // The repeated run is the independent check: perturbed, the digits drop with it.
  const auto wrong = detail::certify_perturbed<double>(p.law, 1e10, 0.0, {}, {certified_source::adaptive_reference, "1e-6"});
  EXPECT_LE(wrong.certified_digits, 7);
}

TEST(certification, the_linear_law_is_certified_by_its_closed_form_at_any_gamma_and_g) {
  // Over the overdamped grid, where the integrators face a stiff creep,
  // the closed form certifies every point, honestly (truth: the closed form at 40 digits).
  const contact_law linear = law_by_name("linear");
  for (const char* gamma : {"2", "10", "1e4", "1e10"})
    for (const char* g : {"-1e6", "-1", "-1e-3", "0", "1e-3", "1", "1e6", "1e12"}) {
      // NOTE: gamma = 1e10, g = -1e6 in double: u_max ~ 1e-10 is the difference of two
      // terms ~1e6 in the closed form, below their rounding: exact_linear finds no
      // bracket (it never could); left out, a known limit.
      if (std::string(gamma) == "1e10" && std::string(g) == "-1e6") continue;
      const auto c = certify<double>(linear, parse_real<double>(gamma, "gamma"), parse_real<double>(g, "g"));
      EXPECT_TRUE(c.outcome_certified) << "gamma = " << gamma << ", g = " << g;
      check_honesty<double>({linear, gamma, g});
    }
}

TEST(certification, a_perturbed_closed_form_makes_certification_drop) {
  const contact_law linear = law_by_name("linear");
  const auto clean = certify<double>(linear, 1e4, -1.0);
  for (auto which : {certified_source::closed_form, certified_source::closed_form_reference}) {
    const auto c = detail::certify_perturbed<double>(linear, 1e4, -1.0, {}, {which, "1e-8"});
    EXPECT_LE(c.certified_digits, 8) << to_string(which);
    EXPECT_LT(c.certified_digits, clean.certified_digits) << to_string(which);
  }
}

TEST(certification, sticking_outcome_is_certified_with_exact_e) {
  const auto c = certify<double>(law_by_name("kuwabara_kono"), 0.06, 4.0);  // report Fig. 4
  EXPECT_TRUE(c.outcome_certified);
  EXPECT_EQ(c.outcome, impact_outcome::stick);
  EXPECT_EQ(c.e, 0);
  EXPECT_EQ(c.one_minus_e, 1);
  EXPECT_GE(c.certified_digits, 10);  // the contact time (turning back) and u_max agree
}

#if VISCOR_HAS_MPFR
TEST(certification, schwager_poschel_coefficients_from_certified_e) {
  // Kuwabara-Kono, g = 0: e = 1 - C0 gamma - C2 gamma^2 + O(gamma^3) (report eq. (36)
  // with (39), (40)). f(gamma) = (1 - e)/gamma from certified 1 - e at gamma = i * 1e-8,
  // i = 1..5; the degree-4 interpolant gives C0 = f(0) and C2 = f'(0) (error ~ 1e-32).
  // Expected values: the closed forms after eq. (40), evaluated independently (the
  // report's printed c1 = -1.15448854 has two digits swapped, see docs/report-notes.md).
  using R = mpfr_50;
  const R C0("1.730173287142933198695851158"), C2("-1.796099762125789664063");
  const contact_law kk = law_by_name("kuwabara_kono");
  std::vector<R> x, f;
  for (int i = 1; i <= 5; ++i) {
    const R gamma = R(i) / R(100000000);
    const auto c = certify<R>(kk, gamma, R(0));
    ASSERT_TRUE(c.outcome_certified);
    ASSERT_GE(c.certified_digits_one_minus_e - c.safety_margin, 40);
    x.push_back(gamma);
    f.push_back(c.one_minus_e / gamma);
  }
  R value = 0, slope = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    R l = 1, sum = 0;
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (j == i) continue;
      l *= (0 - x[j]) / (x[i] - x[j]);
      sum += 1 / (0 - x[j]);
    }
    value += f[i] * l;
    slope += f[i] * l * sum;
  }
  EXPECT_PRED_FORMAT3(viscor::test::relative_close, value, C0, R(1e-25));
  EXPECT_PRED_FORMAT3(viscor::test::relative_close, slope, C2, R(1e-20));
}
#endif

TEST(certification, typed_errors) {
  const contact_law kk = law_by_name("kuwabara_kono");
  EXPECT_THROW(certify<double>(kk, -0.1, 0.0), invalid_parameter);
  certify_options options;
  options.reference_digits = 10;
  EXPECT_THROW(certify<double>(kk, 0.1, 0.0, options), invalid_parameter);
  options.reference_digits = 0;
  options.safety_margin = -1;
  EXPECT_THROW(certify<double>(kk, 0.1, 0.0, options), invalid_parameter);
}

#if VISCOR_HAS_MPFR
TEST(certification, run_time_precision_and_explicit_reference_precision) {
  scoped_precision precision(30);
  certify_options options;
  options.reference_digits = 70;  // 2 * 30 + 10, through mpfr_real
  const auto c = certify<mpfr_real>(law_by_name("hunt_crossley"), mpfr_real("1e-3"), mpfr_real(0), options);
  EXPECT_EQ(c.working_digits, 30);
  EXPECT_EQ(c.computations[1].precision_digits, 70);
  EXPECT_GE(c.certified_digits, 26);
  EXPECT_LE(c.certified_digits, 30);
  EXPECT_LE(c.e.precision(), 31u) << "results are rounded to the caller's precision";
}
#endif

}  // namespace

// The double-double scalar (include/viscor/core/double_double.hpp) against MPFR: its
// decimal input and output, the functions the solvers use, solve_impact for the five
// named laws against MPFR solves at 20 more digits (51), and its exponent limit
// (include/viscor/impact/double_double_impact.hpp); with_working_precision's choice of
// it for 19 to 31 digits, its escalation below that limit, and committed certified rows
// solved in it. Built only where QD is found.
#include <viscor/core/double_double.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/impact/double_double_impact.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <gtest/gtest.h>


#include <fstream>
#include <initializer_list>
#include <sstream>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace viscor;
using boost::multiprecision::mpfr_float_100;

// The exact value hi + lo (100 decimal digits, 336 bits, hold it for |x| >= 2^-969 away
// from the largest exponents used here).
mpfr_float_100 exact(const double_double& x) {
  mpfr_float_100 y(x.hi());
  y += x.lo();
  return y;
}

// |x - ref| / |ref| in double (an error size, not a value).
double relative_error(const double_double& x, const mpfr_float_100& ref) {
  return static_cast<double>(mpfr_float_100(abs(exact(x) - ref) / abs(ref)));
}

TEST(DoubleDouble, CarriesThirtyOneDigits) {
  EXPECT_EQ(std::numeric_limits<double_double>::digits, 104);
  EXPECT_EQ(binary_digits<double_double>(), 104);
  EXPECT_EQ(decimal_digits<double_double>(), 31);
  EXPECT_EQ(fixed_decimal_digits<double_double>(), 31);
  EXPECT_EQ(epsilon<double_double>(), double_double(std::ldexp(1.0, -103)));
  EXPECT_EQ(std::numeric_limits<double_double>::min(), double_double(std::ldexp(1.0, -969)));
  EXPECT_TRUE(has_fixed_precision<double_double>());
}

// log1p and expm1 keep their relative digits down to tiny arguments: QD's log near 1
// keeps only its absolute accuracy, so they are summed from series (16 digits were left
// at 1e-16 when they took the logarithm of 1 + x).
TEST(DoubleDouble, Log1pAndExpm1KeepTheirRelativeDigits) {
  const double eps = std::ldexp(1.0, -103);
  double worst_log1p = 0, worst_expm1 = 0;
  for (const char* text : {"1e-30", "-1e-30", "1e-16", "-1e-16", "3.7e-9", "-2.2e-5", "1e-3", "-0.01", "0.0625",
                           "0.07", "-0.3", "0.4999", "-0.5", "0.5001", "0.9", "1", "1.5", "-0.9", "-0.99999", "7",
                           "100", "-20"}) {
    const double_double x = parse_real<double_double>(text, "x");
    const mpfr_float_100 xr = exact(x);
    worst_log1p = std::max(worst_log1p, relative_error(log1p(x), log1p(xr)));
    worst_expm1 = std::max(worst_expm1, relative_error(expm1(x), expm1(xr)));
  }
  EXPECT_LE(worst_log1p, 2 * eps);
  EXPECT_LE(worst_expm1, 2 * eps);
  RecordProperty("worst_log1p_eps", std::to_string(worst_log1p / eps));
  RecordProperty("worst_expm1_eps", std::to_string(worst_expm1 / eps));
  EXPECT_EQ(log1p(double_double(0)), 0);
  EXPECT_EQ(expm1(double_double(0)), 0);
  // Tsuji's closed form at gamma = 1e-16 (through expm1 and log1p): 1 - e to 31 digits,
  // against the same closed form in MPFR at 51 digits.
  const contact_law law = law_by_name("tsuji");
  const auto dd = exact_cor(law, parse_real<double_double>("1e-16", "gamma"), double_double(0));
  scoped_precision digits(51);
  const auto ref = exact_cor(law, parse_real<mpfr_real>("1e-16", "gamma"), mpfr_real(0));
  ASSERT_TRUE(dd && ref);
  EXPECT_LE(relative_error(dd->one_minus_e, mpfr_float_100(ref->one_minus_e)), 1e-30);
}

TEST(DoubleDouble, IntegersConvertExactly) {
  for (const std::int64_t n : {std::int64_t{0}, std::int64_t{-7}, std::int64_t{1} << 53, (std::int64_t{1} << 53) + 1,
                               std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min() + 1}) {
    EXPECT_EQ(exact(double_double(n)), mpfr_float_100(n)) << n;
    EXPECT_EQ(static_cast<std::int64_t>(double_double(n)), n) << n;
  }
  const std::uint64_t u = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(exact(double_double(u)), mpfr_float_100(u));
  EXPECT_EQ(exact(double_double(3) * (std::int64_t{1} << 60)), mpfr_float_100(3) * mpfr_float_100(std::int64_t{1} << 60));
}

TEST(DoubleDouble, DecimalInputWithin2ToMinus105) {
  for (const char* text : {"0.1", "1e-3", "0.05", "3.14159265358979323846264338327950288419716939937510",
                           "-2.5e100", "1e-290", "6.02214076e23", "1.7976931348623157e308", "123456789.123456789"}) {
    const double_double x = parse_real<double_double>(text, "x");
    const mpfr_float_100 ref(text);
    EXPECT_LE(relative_error(x, ref), std::ldexp(1.0, -105)) << text;
    EXPECT_LE(std::fabs(x.lo()), std::ldexp(std::fabs(x.hi()), -53)) << text;  // normalised
  }
  EXPECT_EQ(parse_real<double_double>("0", "x"), 0);
  EXPECT_EQ(parse_real<double_double>("-0.000e5", "x"), 0);
  EXPECT_EQ(double_double("0.25"), 0.25);
  EXPECT_THROW(parse_real<double_double>("1e400", "gamma"), invalid_parameter);
  EXPECT_THROW(parse_real<double_double>("0.1x", "gamma"), invalid_parameter);
  try {
    parse_real<double_double>("1e-300", "gamma");  // above double's range, below double-double's full precision
    FAIL() << "1e-300 accepted";
  } catch (const invalid_parameter& error) {
    EXPECT_NE(std::string(error.what()).find("underflows the working precision"), std::string::npos) << error.what();
  }
}

TEST(DoubleDouble, PrintsAtMostTheDigitsItCarries) {
  const double_double third = double_double(1) / 3;
  const std::string s = to_decimal_string(third);
  EXPECT_EQ(s, "3.333333333333333333333333333333e-01");
  EXPECT_EQ(to_decimal_string(third, 40), s);                    // never more than 31
  EXPECT_EQ(to_decimal_string(third, roundtrip_digits<double_double>()), s);
  EXPECT_EQ(to_decimal_string(third, 5), "3.3333e-01");
  // The exact value hi + lo correctly rounded, as MPFR prints it.
  for (const char* text : {"0.1", "2.718281828459045235360287471352662497757", "-9.87654321e-200", "1e300"}) {
    const double_double x = parse_real<double_double>(text, "x");
    EXPECT_EQ(to_decimal_string(x), to_decimal_string(exact(x), 31)) << text;
  }
  // Below 2^-969 the lo part is subnormal: fewer digits printed.
  const double_double tiny = ldexp(third, -1000);
  const std::string t = to_decimal_string(tiny);
  const std::size_t mantissa_digits = t.find('e') - 1;  // "d." then the rest
  EXPECT_LT(mantissa_digits, 31u) << t;
  EXPECT_GE(mantissa_digits, 15u) << t;
  EXPECT_EQ(to_decimal_string(double_double(0)), "0.000000000000000000000000000000e+00");
  EXPECT_EQ(to_decimal_string(std::numeric_limits<double_double>::infinity()), "inf");
}

TEST(DoubleDouble, FunctionsAgainstMpfr) {
  using std::exp;
  using std::log;
  using std::pow;
  using std::sqrt;
  double worst_sqrt = 0, worst_exp = 0, worst_log = 0, worst_pow = 0;
  for (const char* text : {"0.1", "0.7", "1.3", "2.5", "17.25", "1e-5", "3e-20", "1e-250", "4.5e200"}) {
    const double_double x = parse_real<double_double>(text, "x");
    const mpfr_float_100 xr = exact(x);
    worst_sqrt = std::max(worst_sqrt, relative_error(sqrt(x), sqrt(xr)));
    worst_log = std::max(worst_log, relative_error(log(x), log(xr)));
    if (xr < 600) worst_exp = std::max(worst_exp, relative_error(exp(x), exp(xr)));
    // The solvers' rational exponents; far from 1 where exp(y ln x) would lose digits.
    for (const int q : {2, 3, 4, 5, 7}) {
      for (const int p : {1, 3, 5, 7}) {
        const double_double y = double_double(p) / q;
        for (const double_double& z : {y, -y}) {
          const mpfr_float_100 ref = pow(xr, exact(z));
          if (ref > 1e-280 && ref < 1e300)  // results in double-double's full range
            worst_pow = std::max(worst_pow, relative_error(pow(x, z), ref));
        }
      }
    }
  }
  const double eps = std::ldexp(1.0, -103);  // epsilon<double_double>()
  EXPECT_LE(worst_sqrt, 2 * eps);
  EXPECT_LE(worst_log, 4 * eps);
  EXPECT_LE(worst_exp, 4 * eps);
  EXPECT_LE(worst_pow, 8 * eps);
  RecordProperty("worst_sqrt_eps", std::to_string(worst_sqrt / eps));
  RecordProperty("worst_pow_eps", std::to_string(worst_pow / eps));
  // Integer exponents, frexp and the rounding functions.
  EXPECT_EQ(pow(double_double(3), 4), 81);
  EXPECT_EQ(pow(double_double(0), 0), 1);
  EXPECT_EQ(double_double(std::numeric_limits<long double>::infinity()), std::numeric_limits<double_double>::infinity());
  EXPECT_EQ(exact(double_double(0.1L)), mpfr_float_100(0.1L));  // an x87 long double, exactly
  EXPECT_EQ(pow(double_double(2), std::int64_t{-3}), 0.125);
  int e = 0;
  const double_double m = frexp(double_double(0.5) - ldexp(double_double(1), -80), &e);  // hi 0.5, lo < 0
  EXPECT_GE(abs(m), 0.5);
  EXPECT_LT(abs(m), 1);
  EXPECT_EQ(ldexp(m, e), double_double(0.5) - ldexp(double_double(1), -80));
  EXPECT_EQ(floor(double_double(2.5)), 2);
  EXPECT_EQ(ceil(double_double(-2.5)), -2);
  EXPECT_EQ(static_cast<int>(double_double(-2.75)), -2);
}

struct law_point {
  const char* law;
  const char* gamma;
  const char* g;
};

// The 45 points of the bench table of docs/performance.md (five named laws x gamma in
// {1e-3, 1e-2, 0.1} x g in {0, 0.05, 1}), and a few more of each law's range.
std::vector<law_point> law_points() {
  std::vector<law_point> points;
  for (const char* law : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"})
    for (const char* gamma : {"1e-3", "1e-2", "0.1"})
      for (const char* g : {"0", "0.05", "1"}) points.push_back({law, gamma, g});
  points.push_back({"linear", "2", "-3"});
  points.push_back({"tsuji", "0.5", "0"});
  points.push_back({"kuwabara_kono", "0.05", "1"});
  points.push_back({"hunt_crossley", "1e-6", "0"});
  return points;
}

class DoubleDoubleSolve : public ::testing::TestWithParam<law_point> {};

TEST_P(DoubleDoubleSolve, TaylorRightTo31DigitsAgainstMpfr51) {
  const law_point p = GetParam();
  const contact_law law = law_by_name(p.law);
  const impact_result<double_double> r =
      solve_impact<double_double>(law, parse_real<double_double>(p.gamma, "gamma"), parse_real<double_double>(p.g, "g"));
  scoped_precision digits(51);
  const impact_result<mpfr_real> ref =
      solve_impact<mpfr_real>(law, parse_real<mpfr_real>(p.gamma, "gamma"), parse_real<mpfr_real>(p.g, "g"));
  ASSERT_EQ(r.outcome, ref.outcome);
  const mpfr_float_100 e_ref(ref.e), one_minus_e_ref(ref.one_minus_e);
  const double e_error = static_cast<double>(mpfr_float_100(abs(exact(r.e) - e_ref)));
  EXPECT_LE(e_error, 1e-30) << "e = " << to_decimal_string(r.e) << ", MPFR " << to_decimal_string(ref.e, 40);
  EXPECT_LE(e_error, static_cast<double>(r.error_estimate) + 1e-33) << "beyond the solver's own error estimate";
  if (r.outcome == impact_outcome::rebound)
    EXPECT_LE(relative_error(r.one_minus_e, one_minus_e_ref), 1e-30) << to_decimal_string(r.one_minus_e);
  // Printed: never more than the 31 digits the type carries.
  const std::string printed = to_decimal_string(r.e, 40);
  EXPECT_LE(printed.find('e') - (printed.find('.') == std::string::npos ? 0 : 1), 31u) << printed;
  // The checked entry point gives the same result in this range.
  const impact_result<double_double> checked = solve_impact_double_double(
      law, parse_real<double_double>(p.gamma, "gamma"), parse_real<double_double>(p.g, "g"));
  EXPECT_EQ(checked.e, r.e);
}

TEST_P(DoubleDoubleSolve, AdaptiveRightTo31DigitsAgainstMpfr51) {
  const law_point p = GetParam();
  const contact_law law = law_by_name(p.law);
  solve_options<double_double> options;
  options.method = integration_method::adaptive;
  const impact_result<double_double> r = solve_impact<double_double>(
      law, parse_real<double_double>(p.gamma, "gamma"), parse_real<double_double>(p.g, "g"), options);
  scoped_precision digits(51);
  const impact_result<mpfr_real> ref =
      solve_impact<mpfr_real>(law, parse_real<mpfr_real>(p.gamma, "gamma"), parse_real<mpfr_real>(p.g, "g"));
  ASSERT_EQ(r.outcome, ref.outcome);
  // GBS integrates in MPFR at 57 digits (gbs_work<double_double>) and rounds back.
  const double e_error = static_cast<double>(mpfr_float_100(abs(exact(r.e) - mpfr_float_100(ref.e))));
  EXPECT_LE(e_error, 1e-30) << to_decimal_string(r.e);
  EXPECT_LE(e_error, static_cast<double>(r.error_estimate) + 1e-33) << "beyond the solver's own error estimate";
}

INSTANTIATE_TEST_SUITE_P(FiveLaws, DoubleDoubleSolve, ::testing::ValuesIn(law_points()));

TEST(DoubleDoubleRange, RefusesValuesBelowItsFullPrecision) {
  const contact_law law = law_by_name("kuwabara_kono");
  // gamma = 1e-300: a double, but below 2^-969 (so is 1 - e, about 1.7e-300); 1e-290 and
  // 1e-283: full double-double numbers, below the solve's bound 2^-939 = 2.2e-283.
  for (const double gamma : {1e-300, 1e-290, 1e-283}) {
    try {
      solve_impact_double_double(law, double_double(gamma), double_double(0));
      FAIL() << "gamma " << gamma << " accepted";
    } catch (const precision_unavailable& error) {
      EXPECT_NE(std::string(error.what()).find("gamma"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("MPFR"), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(solve_impact_double_double(law, double_double(1), double_double(-1e-300)), precision_unavailable);
  // solve_impact<double_double> itself refuses the result: 1 - e below the bound. The
  // Taylor method refuses it sooner: the dissipated energy's first coefficient (2 gamma
  // v^2, 2e-300) already lost its digits (taylor_integrator::require_precise_jet).
  for (const integration_method method : {integration_method::taylor, integration_method::adaptive}) {
    solve_options<double_double> options;
    options.method = method;
    try {
      const impact_result<double_double> r = solve_impact<double_double>(law, double_double(1e-300), 0, options);
      FAIL() << to_string(method) << ": 1 - e = " << to_decimal_string(r.one_minus_e) << " accepted";
    } catch (const precision_unavailable& error) {
      const std::string why = error.what();
      const bool sooner = method == integration_method::taylor &&
                          why.find("Taylor coefficient of order 1 of component 2 underflows") != std::string::npos;
      EXPECT_TRUE(sooner || why.find("1 - e") != std::string::npos) << why;
    }
  }
}

TEST(DoubleDoubleRange, SmallGammaAboveTheBoundKeepsItsDigits) {
  // 1 - e about 1.7 gamma, against MPFR at 51 digits: far inside the range and just above
  // the bound 2^-939 = 2.2e-283.
  const contact_law law = law_by_name("kuwabara_kono");
  for (const char* gamma : {"1e-250", "3e-283"}) {
    const impact_result<double_double> r =
        solve_impact_double_double(law, parse_real<double_double>(gamma, "gamma"), double_double(0));
    scoped_precision digits(51);
    const impact_result<mpfr_real> ref = solve_impact<mpfr_real>(law, parse_real<mpfr_real>(gamma, "gamma"), mpfr_real(0));
    EXPECT_LE(relative_error(r.one_minus_e, mpfr_float_100(ref.one_minus_e)), 1e-30)
        << gamma << ": " << to_decimal_string(r.one_minus_e) << " MPFR " << to_decimal_string(ref.one_minus_e, 40);
  }
}

// ---- with_working_precision: 19 to 31 digits run in double-double ----

// The scalar type with_working_precision(digits) runs a solve of law at gamma, g in, and
// the solve's 1 - e as a 100-digit MPFR number.
struct dispatched_solve {
  std::string type;
  impact_outcome outcome;
  mpfr_float_100 e, one_minus_e, error_estimate;
};
dispatched_solve solve_at_digits(int digits, const contact_law& law, const std::string& gamma, const std::string& g) {
  return with_working_precision(digits, [&]<class Real>() {
    const impact_result<Real> r = solve_impact<Real>(law, parse_real<Real>(gamma, "gamma"), parse_real<Real>(g, "g"));
    dispatched_solve out{to_string(scalar_kind_of<Real>()), r.outcome, 0, 0, 0};
    if constexpr (std::is_same_v<Real, double_double>) {
      out.e = exact(r.e), out.one_minus_e = exact(r.one_minus_e), out.error_estimate = exact(r.error_estimate);
    } else {
      out.e = mpfr_float_100(r.e), out.one_minus_e = mpfr_float_100(r.one_minus_e);
      out.error_estimate = mpfr_float_100(r.error_estimate);
    }
    return out;
  });
}

mpfr_float_100 mpfr51_one_minus_e(const contact_law& law, const std::string& gamma, const std::string& g) {
  scoped_precision digits(51);
  return mpfr_float_100(solve_impact<mpfr_real>(law, parse_real<mpfr_real>(gamma, "gamma"), parse_real<mpfr_real>(g, "g")).one_minus_e);
}

// The linear law's 1 - e at each gamma under g = 1e6, solved at `digits`, within
// `relative` of the closed form in MPFR at 51 digits.
void expect_linear_under_load_right(int digits, std::initializer_list<const char*> gammas, double relative) {
  const contact_law law = law_by_name("linear");
  for (const char* gamma : gammas) {
    const dispatched_solve r = solve_at_digits(digits, law, gamma, "1e6");
    scoped_precision precision(51);
    const auto exact_form = exact_cor(law, parse_real<mpfr_real>(gamma, "gamma"), parse_real<mpfr_real>("1e6", "g"));
    ASSERT_TRUE(exact_form) << gamma;
    const mpfr_float_100 truth(exact_form->one_minus_e);
    EXPECT_LE(static_cast<double>(mpfr_float_100(abs(r.one_minus_e - truth) / truth)), relative)
        << gamma << " (" << r.type << "): 1 - e " << r.one_minus_e.str(40) << ", closed form " << truth.str(40);
  }
}

#if VISCOR_HAS_FLOAT128
// Tiny damping under a large load: the dissipated energy's Taylor coefficients fall
// below double-double's range while the linear law's entire series allow long steps.
// Such a solve escalates to float128 and keeps 1 - e to 31 digits; the truth is the
// closed form in MPFR at 51 digits (before: 10 right digits at gamma = 1e-280).
TEST(DoubleDoubleWorkingPrecision, UnderflowingCoefficientsEscalateAndKeepTheDigits) {
  expect_linear_under_load_right(25, {"1e-280", "1e-250", "1e-200", "1e-100"}, 1e-30);
  const contact_law law = law_by_name("linear");
  EXPECT_EQ(solve_at_digits(25, law, "1e-280", "1e6").type, "float128");
  EXPECT_EQ(solve_at_digits(25, law, "0.05", "1e6").type, "double-double");  // an ordinary damping stays
}
#endif

// Double has double-double's exponent range and the same hazard: at gamma = 1e-305 under
// g = 1e6 its 1 - e had 5 right digits of 17 (10 at 1e-280). Such a solve escalates to
// long double.
TEST(DoubleWorkingPrecision, UnderflowingCoefficientsEscalateAndKeepTheDigits) {
  expect_linear_under_load_right(15, {"1e-305", "1e-280", "1e-200", "1e-100"}, 1e-14);
  const contact_law law = law_by_name("linear");
  EXPECT_EQ(solve_at_digits(15, law, "1e-305", "1e6").type, "long double");
  EXPECT_EQ(solve_at_digits(15, law, "0.05", "1e6").type, "double");  // an ordinary damping stays
}

TEST(DoubleDoubleWorkingPrecision, NineteenToThirtyOneDigitsRunInIt) {
  for (const int digits : {19, 25, 31})
    EXPECT_EQ(solve_at_digits(digits, law_by_name("tsuji"), "0.05", "1").type, "double-double") << digits;
#if VISCOR_HAS_FLOAT128
  EXPECT_EQ(solve_at_digits(32, law_by_name("tsuji"), "0.05", "1").type, "float128");
#endif
}

#if VISCOR_HAS_FLOAT128
TEST(DoubleDoubleWorkingPrecision, BelowItsExponentRangeEscalatesToFloat128) {
  const contact_law law = law_by_name("kuwabara_kono");
  // gamma 1e-300: an input below 2^-969; 1e-283: a full double-double input whose 1 - e
  // (about 1.7e-283) is below the solve's bound 2^-939; 1e-250: inside the range.
  for (const auto& [gamma, type] : std::vector<std::pair<std::string, std::string>>{
           {"1e-300", "float128"}, {"1e-283", "float128"}, {"1e-250", "double-double"}}) {
    const dispatched_solve r = solve_at_digits(25, law, gamma, "0");
    EXPECT_EQ(r.type, type) << gamma;
    const mpfr_float_100 ref = mpfr51_one_minus_e(law, gamma, "0");
    EXPECT_LE(static_cast<double>(mpfr_float_100(abs(r.one_minus_e - ref) / ref)), 1e-30)
        << gamma << ": 1 - e " << r.one_minus_e.str(40) << ", MPFR at 51 digits " << ref.str(40);
  }
}
#endif

// The extremes of the other precisions' tests (a bead creeping out of an overdamped
// contact under a pull, a creep up to the equilibrium, a tiny damping at zero load,
// vanishing damping under loads of 1e9 and 1e12, a huge damping) at 25 digits, for the
// named laws and two others (alpha 3 with beta 1, alpha 2 with beta 3): the same outcome
// as MPFR at 51 digits, and e within the solve's own error estimate. Under the large
// loads double-double's Taylor coefficients overflow double's exponent range near u = 0
// (order 37, terms like (|v|/u)^k), so those solves are run again in float128
// (exponent_range_exceeded); before, they ended in "no acceptable step". No point may fail.
TEST(DoubleDoubleWorkingPrecision, ExtremesWithinTheirErrorEstimateAgainstMpfr51) {
  std::vector<contact_law> laws;
  for (const char* name : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"})
    laws.push_back(law_by_name(name));
  laws.push_back(make_law(exponent::rational(3, 1), exponent::rational(1, 1)));
  laws.push_back(make_law(exponent::rational(2, 1), exponent::rational(3, 1)));
  for (const contact_law& law : laws)
    for (const auto& [gamma, g] : std::vector<std::pair<std::string, std::string>>{{"1e4", "-1"},
                                                                                 {"1e2", "1e3"},
                                                                                 {"1e-8", "0"},
                                                                                 {"1e-30", "1e9"},
                                                                                 {"1e-30", "1e12"},
                                                                                 {"0.05", "1e12"},
                                                                                 {"1e10", "1"}}) {
      const std::string where = law.describe() + " gamma " + gamma + " g " + g;
      dispatched_solve r;
      try {
        r = solve_at_digits(25, law, gamma, g);
      } catch (const error& e) {
        ADD_FAILURE() << where << ": " << e.what();
        continue;
      }
      scoped_precision digits(51);
      const impact_result<mpfr_real> ref =
          solve_impact<mpfr_real>(law, parse_real<mpfr_real>(gamma, "gamma"), parse_real<mpfr_real>(g, "g"));
      ASSERT_EQ(r.outcome, ref.outcome) << where;
      EXPECT_LE(abs(r.e - mpfr_float_100(ref.e)), r.error_estimate + mpfr_float_100("1e-31"))
          << where << ": e " << r.e.str(35) << ", MPFR " << ref.e.str(40);
    }
}

// Rows of a committed certified table (reference_data/cor_gamma_sweep.csv: five laws,
// gamma 1e-8..1, g in {0, 0.05, 1, 10}, certified to 38 digits by MPFR computations at 40
// digits, reference_data/README.md) solved at 31 digits, which run in double-double:
// every sixth row, 110 of them.
TEST(DoubleDoubleWorkingPrecision, CommittedCertifiedRowsRightTo30Digits) {
  std::ifstream in(std::string(VISCOR_SOURCE_DIR) + "/reference_data/cor_gamma_sweep.csv");
  ASSERT_TRUE(in) << "reference_data/cor_gamma_sweep.csv";
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line, "index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,contact_time,max_compression,digits,method");
  int rows = 0, rebounds = 0;
  for (int index = 0; std::getline(in, line); ++index) {
    if (index % 6 != 0) continue;
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 13u) << line;
    ASSERT_EQ(f[12], "certified") << line;
    ASSERT_GE(std::stoi(f[11]), 35) << line;
    const dispatched_solve r = solve_at_digits(31, law_by_name(f[1]), f[4], f[5]);
    ASSERT_EQ(r.type, "double-double");
    ASSERT_EQ(to_string(r.outcome), f[6]) << line;
    ++rows;
    if (r.outcome != impact_outcome::rebound) continue;
    const mpfr_float_100 e(f[7]), one_minus_e(f[8]);
    EXPECT_LE(static_cast<double>(mpfr_float_100(abs(r.e - e))), 1e-30) << line;
    EXPECT_LE(static_cast<double>(mpfr_float_100(abs(r.one_minus_e - one_minus_e) / one_minus_e)), 1e-29) << line;
    ++rebounds;
  }
  EXPECT_EQ(rows, 110);
  EXPECT_GE(rebounds, 90);  // 97: the others stick
}

}  // namespace

// The table machinery below the CLI: exact decimal grid values, grid expansion
// and shards, rows from closed forms, the CSV format and its validator, and
// sticking thresholds by bisection (checked on the linear law and on Tsuji at
// g = 0, where the thresholds follow from independently derived equations).
#include "test_utils.hpp"

#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/tables/reference_table.hpp>
#include <viscor/tables/sticking_threshold.hpp>
#include <viscor/tables/table_row.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace {

using viscor::detail::exact_decimal;

std::string canonical(const std::string& text) { return exact_decimal::parse(text, "x").to_string(); }

template <class F>
std::string error_message(F f) {
  try {
    f();
  } catch (const viscor::error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ExactDecimal, CanonicalText) {
  EXPECT_EQ(canonical("0.050"), "0.05");
  EXPECT_EQ(canonical("+5e-2"), "0.05");
  EXPECT_EQ(canonical("-0.0"), "0");
  EXPECT_EQ(canonical("1E6"), "1000000");
  EXPECT_EQ(canonical("1e-8"), "1e-08");
  EXPECT_EQ(canonical("0.0001"), "0.0001");
  EXPECT_EQ(canonical("0.00001"), "1e-05");
  EXPECT_EQ(canonical("12.5e-3"), "0.0125");
  EXPECT_EQ(canonical("1.58489e-08"), "1.58489e-08");
  EXPECT_EQ(canonical("1e16"), "1e+16");
  EXPECT_EQ(canonical("-2.50e20"), "-2.5e+20");
  EXPECT_EQ(canonical("123456789012345678901234567890e-20"), "1234567890.1234567890123456789");
  EXPECT_THROW(exact_decimal::parse("0.1x", "gamma"), viscor::invalid_parameter);
  EXPECT_THROW(exact_decimal::parse("nan", "gamma"), viscor::invalid_parameter);
  EXPECT_THROW(exact_decimal::parse("1e99999999", "gamma"), viscor::invalid_parameter);
}

TEST(ExactDecimal, ArithmeticIsExact) {
  const exact_decimal a = exact_decimal::parse("0.1", "a"), b = exact_decimal::parse("0.2", "b");
  EXPECT_EQ((a + b).to_string(), "0.3");  // not 0.30000000000000004
  EXPECT_EQ((b - a).to_string(), "0.1");
  EXPECT_EQ(a.times(7).to_string(), "0.7");
  EXPECT_EQ(a.divided_exactly(4)->to_string(), "0.025");
  EXPECT_EQ(exact_decimal::parse("1", "x").divided_exactly(1024)->to_string(), "0.0009765625");
  EXPECT_FALSE(exact_decimal::parse("1", "x").divided_exactly(3).has_value());
  EXPECT_FALSE(exact_decimal::parse("0.1", "x").divided_exactly(6).has_value());
  EXPECT_LT(exact_decimal::parse("-1e-300", "x"), exact_decimal::parse("0", "y"));
  EXPECT_EQ(exact_decimal::parse("2.50", "x"), exact_decimal::parse("25e-1", "y"));
}

viscor::axis_item range(std::string from, std::string to, std::int64_t count,
                        viscor::axis_item::kind k = viscor::axis_item::kind::linear) {
  viscor::axis_item it;
  it.type = k;
  it.from = std::move(from), it.to = std::move(to), it.count = count;
  it.where = "spec.json:3";
  return it;
}

viscor::axis_item value(std::string v) {
  viscor::axis_item it;
  it.from = std::move(v);
  it.where = "spec.json:4";
  return it;
}

TEST(GridSpec, LinearRangesAreExactDecimals) {
  viscor::grid_axis axis;
  axis.items = {range("0", "0.1", 5), value("0.5"), value("0.05")};
  EXPECT_EQ(viscor::expand_axis(axis, "gamma"),
            (std::vector<std::string>{"0", "0.025", "0.05", "0.075", "0.1", "0.5"}));  // sorted, duplicate 0.05 once

  viscor::axis_item stepped = range("0.001", "0.0105", 0);
  stepped.step = "0.0025";
  axis.items = {stepped};
  EXPECT_EQ(viscor::expand_axis(axis, "g"), (std::vector<std::string>{"0.001", "0.0035", "0.006", "0.0085"}));

  // 101 points from 0 to 0.1: every one an exact multiple of 0.001.
  axis.items = {range("0", "0.1", 101)};
  const auto v = viscor::expand_axis(axis, "gamma");
  ASSERT_EQ(v.size(), 101u);
  EXPECT_EQ(v[37], "0.037");
  EXPECT_EQ(v[100], "0.1");
}

TEST(GridSpec, LogRangesRoundToDigits) {
  viscor::grid_axis axis;
  axis.items = {range("1e-8", "1", 17, viscor::axis_item::kind::log)};
  const auto v = viscor::expand_axis(axis, "gamma");
  ASSERT_EQ(v.size(), 17u);
  EXPECT_EQ(v[0], "1e-08");
  EXPECT_EQ(v[2], "1e-07");       // 10^-7 exactly after rounding to 6 digits
  EXPECT_EQ(v[1], "3.16228e-08");  // 10^-7.5 = 3.16227766...e-8
  EXPECT_EQ(v[15], "0.316228");
  EXPECT_EQ(v[16], "1");
  axis.items[0].log_digits = 3;
  EXPECT_EQ(viscor::expand_axis(axis, "gamma")[1], "3.16e-08");
}

TEST(GridSpec, BadAxesNameFileLineAndField) {
  viscor::grid_axis axis;
  axis.items = {range("0", "0.1", 7)};  // step 1/60 does not terminate
  std::string m = error_message([&] { viscor::expand_axis(axis, "gamma"); });
  EXPECT_NE(m.find("spec.json:3: field gamma.count"), std::string::npos) << m;
  EXPECT_NE(m.find("not a terminating decimal"), std::string::npos) << m;

  axis.items = {value("0.1"), range("-0.1", "0.1", 3)};
  m = error_message([&] { viscor::expand_axis(axis, "gamma"); });
  EXPECT_NE(m.find("spec.json:3: field gamma[1].from: gamma must be >= 0, got -0.1"), std::string::npos) << m;

  axis.items = {value("0.1"), value("1.2.3")};
  m = error_message([&] { viscor::expand_axis(axis, "g"); });
  EXPECT_NE(m.find("spec.json:4: field g[1]"), std::string::npos) << m;
  EXPECT_THROW(viscor::expand_axis(axis, "g"), viscor::parse_error);

  axis.items = {range("0.1", "0.1", 3)};
  EXPECT_THROW(viscor::expand_axis(axis, "g"), viscor::parse_error);
  axis.items = {range("0", "1", 3, viscor::axis_item::kind::log)};  // log from 0
  EXPECT_THROW(viscor::expand_axis(axis, "g"), viscor::parse_error);
}

viscor::grid_spec small_spec() {
  viscor::grid_spec spec;
  spec.laws = {viscor::law_by_name("linear"), viscor::law_by_name("tsuji")};
  spec.gamma.items = {range("0", "0.3", 4)};
  spec.g.items = {value("0"), value("1")};
  spec.digits = 30;
  spec.method = viscor::row_method::exact;
  return spec;
}

TEST(GridSpec, PointsInFixedOrderAndShardsPartitionThem) {
  const viscor::grid_spec spec = small_spec();
  const viscor::expanded_axes axes = viscor::expand(spec);
  const auto all = viscor::grid_points(spec, axes);
  ASSERT_EQ(all.size(), 16u);
  EXPECT_EQ(viscor::grid_size(spec, axes), 16);
  // laws as given, then g, then gamma.
  EXPECT_EQ(all[0].law.name, "linear");
  EXPECT_EQ(all[0].g, "0");
  EXPECT_EQ(all[1].gamma, "0.1");
  EXPECT_EQ(all[4].g, "1");
  EXPECT_EQ(all[4].gamma, "0");
  EXPECT_EQ(all[8].law.name, "tsuji");
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i].index, static_cast<std::int64_t>(i));

  std::multiset<std::int64_t> seen;
  for (std::int64_t s = 0; s < 3; ++s)
    for (const auto& p : viscor::grid_points(spec, axes, viscor::shard{s, 3})) {
      EXPECT_EQ(p.index % 3, s);
      EXPECT_EQ(p.gamma, all[static_cast<std::size_t>(p.index)].gamma);
      seen.insert(p.index);
    }
  EXPECT_EQ(seen.size(), all.size());
  EXPECT_EQ(std::set<std::int64_t>(seen.begin(), seen.end()).size(), all.size());  // disjoint

  EXPECT_EQ(viscor::shard::parse("2/5").index, 2);
  EXPECT_THROW(viscor::shard::parse("5/5"), viscor::invalid_parameter);
  EXPECT_THROW(viscor::shard::parse("1/0"), viscor::invalid_parameter);
  EXPECT_THROW(viscor::shard::parse("-1/3"), viscor::invalid_parameter);
  EXPECT_THROW(viscor::shard::parse("1-3"), viscor::invalid_parameter);
}

TEST(TableRow, ClosedFormDispatchMatchesExactCor) {
  // closed_form_exists must say yes exactly where exact_cor has an answer.
  std::vector<viscor::contact_law> laws;
  for (const auto& n : viscor::named_laws) laws.push_back(viscor::law_by_name(n.name));
  laws.push_back(viscor::make_law(viscor::exponent::parse("2", "a"), viscor::exponent::parse("3", "b")));
  laws.push_back(viscor::make_law(viscor::exponent::parse("1.3", "a"), viscor::exponent::parse("1.7", "b")));
  for (const auto& law : laws)
    for (const char* gamma : {"0", "0.1"})
      for (const char* g : {"0", "0.5"}) {
        const bool exists = viscor::exact_cor(law, std::stod(gamma), std::stod(g)).has_value();
        EXPECT_EQ(viscor::closed_form_exists(law, std::string(gamma) == "0", std::string(g) == "0"), exists)
            << law.describe() << " gamma " << gamma << " g " << g;
      }
}

viscor::grid_point point(const std::string& law, const std::string& gamma, const std::string& g) {
  return {7, viscor::law_by_name(law), gamma, g};
}

#if VISCOR_HAS_MPFR
using viscor::mpfr_50;

// The decimal string of a row parsed at 50 digits.
mpfr_50 at50(const std::string& s) { return viscor::parse_real<mpfr_50>(s, "row value"); }

TEST(TableRow, LinearRowsFromTheClosedForm) {
  viscor::table_settings settings{30, viscor::row_method::exact, 0};
  // g = 0: e = exp(-xi pi / omega), xi = gamma/2, omega = sqrt(1 - xi^2); T_f = pi/omega (report App. D).
  const viscor::table_row r = viscor::compute_row(point("linear", "0.3", "0"), settings);
  EXPECT_EQ(r.index, 7);
  EXPECT_EQ(r.outcome, viscor::impact_outcome::rebound);
  EXPECT_EQ(r.source, viscor::row_source::exact);
  EXPECT_EQ(r.certified_digits, 28);
  EXPECT_EQ(r.alpha, "1");
  EXPECT_EQ(r.gamma, "0.3");
  const mpfr_50 xi = mpfr_50(3) / 20, omega = sqrt(1 - xi * xi), pi = boost::math::constants::pi<mpfr_50>();
  const mpfr_50 tol = mpfr_50("1e-27");
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(r.e), mpfr_50(exp(-xi * pi / omega)), tol);
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(r.one_minus_e), mpfr_50(-expm1(-xi * pi / omega)),
                      tol);
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(r.contact_time), mpfr_50(pi / omega), tol);
  // 28 significant digits: d.ddd...e-01 with 27 after the point.
  EXPECT_EQ(r.e.size(), std::string("x.").size() + 27 + std::string("e-01").size()) << r.e;
  // The line matches the header's columns.
  EXPECT_EQ(viscor::split_fields(viscor::csv_line(r)).size(),
            viscor::table_columns(viscor::table_kind::cor).size());
}

TEST(TableRow, ExactValuesAndSticking) {
  viscor::table_settings settings{30, viscor::row_method::exact, 0};
  // gamma = 0: e = 1 exactly for every law.
  const viscor::table_row elastic = viscor::compute_row(point("kuwabara_kono", "0", "1"), settings);
  EXPECT_EQ(elastic.e, "1");
  EXPECT_EQ(elastic.one_minus_e, "0");
  // Linear law, gamma = 0.5, g = 1: the overlap at the turning point t1 is
  // g - rho exp(-xi t1) = 1 - sqrt(1.5) exp(-xi t1) > 0, so the bead sticks.
  const viscor::table_row stuck = viscor::compute_row(point("linear", "0.5", "1"), settings);
  EXPECT_EQ(stuck.outcome, viscor::impact_outcome::stick);
  EXPECT_EQ(stuck.e, "0");
  EXPECT_EQ(stuck.one_minus_e, "1");
  // t1 = (atan2(omega, xi - g) + pi)/omega, the time u' vanishes again.
  const mpfr_50 xi = mpfr_50(1) / 4, omega = sqrt(1 - xi * xi), pi = boost::math::constants::pi<mpfr_50>();
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(stuck.contact_time),
                      mpfr_50((atan2(omega, xi - 1) + pi) / omega), mpfr_50("1e-27"));
  // Tsuji at g = 0 (Antypov-Elliott): e = exp(-xi pi/sqrt(1 - xi^2)), xi = sqrt(5) gamma/4.
  const viscor::table_row tsuji = viscor::compute_row(point("tsuji", "0.2", "0"), settings);
  const mpfr_50 xt = sqrt(mpfr_50(5)) / 20;
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(tsuji.e),
                      mpfr_50(exp(-xt * pi / sqrt(1 - xt * xt))), mpfr_50("1e-27"));
}

TEST(TableRow, NoRowWithoutACertificate) {
  viscor::table_settings exact{30, viscor::row_method::exact, 0};
  const std::string m = error_message([&] { viscor::compute_row(point("hertz_linear_damping", "0.1", "0.05"), exact); });
  EXPECT_NE(m.find("no closed form"), std::string::npos) << m;
  EXPECT_THROW(viscor::require_computable(viscor::law_by_name("tsuji"), false, false, viscor::row_method::exact, "p"),
               viscor::invalid_parameter);
  EXPECT_NO_THROW(viscor::require_computable(viscor::law_by_name("tsuji"), false, true, viscor::row_method::exact, "p"));
  // min_digits above what the closed form certifies (28 of 30) fails the row.
  viscor::table_settings strict{30, viscor::row_method::exact, 29};
  EXPECT_THROW(viscor::compute_row(point("linear", "0.1", "0"), strict), viscor::certification_error);
}

// Linear law, underdamped: with v = u - g, rho = sqrt(1 - 2 xi g + g^2) and
// t0 = atan2(omega, xi - g)/omega, the overlap when u' vanishes again is
// g - rho exp(-xi (t0 + pi/omega)); the bead sticks iff that is >= 0. Derived
// from v = e^{-xi t}(a cos + b sin) independently of exact_linear's code.
mpfr_50 linear_threshold(const mpfr_50& gamma) {
  const mpfr_50 xi = gamma / 2, omega = sqrt((1 - xi) * (1 + xi)), pi = boost::math::constants::pi<mpfr_50>();
  auto overlap = [&](const mpfr_50& g) {
    return mpfr_50(g - sqrt(1 - 2 * xi * g + g * g) * exp(-xi * (atan2(omega, xi - g) + pi) / omega));
  };
  boost::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(overlap, mpfr_50(0), mpfr_50(100),
                                                   boost::math::tools::eps_tolerance<mpfr_50>(), iterations);
  return (r.first + r.second) / 2;
}

TEST(StickingThreshold, LinearLawMatchesTheClosedFormCondition) {
  viscor::table_settings settings{40, viscor::row_method::exact, 0};
  for (const char* gamma : {"0.5", "1.2"}) {
    const viscor::threshold_point p{3, viscor::law_by_name("linear"), viscor::threshold_variable::g, gamma};
    const viscor::threshold_row row = viscor::compute_threshold_row(p, 25, settings);
    EXPECT_EQ(row.gamma, gamma);
    EXPECT_EQ(row.certified_digits, 25);
    const mpfr_50 expected = linear_threshold(at50(gamma));
    // Rounded to 25 digits: within 0.6 units of the 25th digit.
    EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(row.g), expected, mpfr_50("6e-25"))
        << "gamma = " << gamma;
    EXPECT_LT(at50(row.rebound_at), expected);
    EXPECT_GT(at50(row.stick_at), expected);
  }
}

TEST(StickingThreshold, TsujiCriticalDampingAtZeroLoad) {
  // Tsuji at g = 0 sticks iff xi = sqrt(5) gamma / 4 >= 1: gamma_c = 4/sqrt(5).
  viscor::table_settings settings{40, viscor::row_method::exact, 0};
  const viscor::threshold_point p{0, viscor::law_by_name("tsuji"), viscor::threshold_variable::gamma, "0"};
  const viscor::threshold_row row = viscor::compute_threshold_row(p, 30, settings);
  EXPECT_EQ(row.g, "0");
  EXPECT_EQ(row.certified_digits, 30);
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, at50(row.gamma), mpfr_50(4 / sqrt(mpfr_50(5))),
                      mpfr_50("6e-30"));
  EXPECT_THROW(viscor::compute_threshold_row(p, 36, settings), viscor::invalid_parameter);  // > digits - 5
}
#endif

// ---- CSV format ----

const std::string header = viscor::table_header(viscor::table_kind::cor);
const std::string good_row = "3,linear,1,1,0.1,0,rebound,9.5e-01,5e-02,3.1e+00,9.9e-01,2,exact";

std::string csv_error(const std::string& text) {
  return error_message([&] { viscor::parse_table(text, "t.csv"); });
}

TEST(ReferenceTable, ParsesAndValidates) {
  const viscor::csv_table t = viscor::parse_table(header + "\n" + good_row + "\n", "t.csv");
  EXPECT_EQ(t.kind, viscor::table_kind::cor);
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0].index, 3);
  EXPECT_EQ(t.rows[0].text, good_row);
  EXPECT_EQ(t.rows[0].line, 2u);
  EXPECT_EQ(viscor::field_value<double>(t, t.rows[0], "e"), 0.95);
  // A written row reads back to the same line.
  viscor::table_row r;
  r.index = 12, r.law = "tsuji", r.alpha = "3/2", r.beta = "5/4", r.gamma = "1e-08", r.g = "0";
  r.e = "9.99e-01", r.one_minus_e = "1e-08", r.certified_digits = 3;
  const std::string line = viscor::csv_line(r);
  EXPECT_EQ(viscor::parse_table(header + "\n" + line + "\n", "t.csv").rows.at(0).text, line);
}

TEST(ReferenceTable, ErrorsNameFileLineAndField) {
  EXPECT_NE(csv_error("index,law,alpha\n").find("t.csv:1: wrong columns"), std::string::npos);
  EXPECT_NE(csv_error("").find("t.csv:1: empty file"), std::string::npos);
  const std::string h = header + "\n" + good_row + "\n";
  std::string m = csv_error(h + "4,linear,1,1,0.1,0,rebound,9.5e-01\n");
  EXPECT_NE(m.find("t.csv:3: expected 13 fields"), std::string::npos) << m;
  EXPECT_NE(m.find("truncated"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,rebound,9.5e-01,5e-02,3.1e+00,9.9e-01,2,exact");  // no final newline
  EXPECT_NE(m.find("t.csv:3: truncated row"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,rebound,0.9x,5e-02,3.1e+00,9.9e-01,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field e: must be a decimal number, got '0.9x'"), std::string::npos) << m;
  m = csv_error(h + "4,linera,1,1,0.1,0,rebound,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field law: unknown contact law 'linera'"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,-0.1,0,rebound,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field gamma: must be in [0, inf]"), std::string::npos) << m;
  m = csv_error(h + "4,linear,3/2,1,0.1,0,rebound,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field law: the named law has alpha = 1"), std::string::npos) << m;
  m = csv_error(h + "4,,1/2,1,0.1,0,rebound,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field alpha"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,stick,0.1,1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field e: a sticking row has e = 0"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,rebound,1.5,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field e: must be in [0, 1]"), std::string::npos) << m;
  m = csv_error(h + "04,linear,1,1,0.1,0,rebound,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field index"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,rebound,0.9,0.1,,,2,guessed\n");
  EXPECT_NE(m.find("t.csv:3: field method: must be one of exact, certified"), std::string::npos) << m;
  m = csv_error(h + "4,linear,1,1,0.1,0,bounce,0.9,0.1,,,2,exact\n");
  EXPECT_NE(m.find("t.csv:3: field outcome"), std::string::npos) << m;
  EXPECT_THROW(viscor::parse_table(h + "4,linear,1,1,0.1,0,rebound,0.9,0.1,,,2,exact\r\n", "t.csv"),
               viscor::parse_error);
}

TEST(ReferenceTable, TruncatedTailOnlyWhenResuming) {
  const std::string text = header + "\n" + good_row + "\n" + "5,linear,1,1,0.1,0,rebou";
  EXPECT_THROW(viscor::parse_table(text, "p.csv"), viscor::parse_error);
  const viscor::csv_table t = viscor::parse_table(text, "p.csv", /*allow_truncated_tail=*/true);
  EXPECT_TRUE(t.truncated_tail);
  EXPECT_EQ(t.rows.size(), 1u);
}

TEST(ReferenceTable, CanonicalTextSortsAndRejectsDuplicates) {
  const std::string a = "1,linear,1,1,0.1,0,rebound,0.9,0.1,,,2,exact";
  const std::string b = "0,linear,1,1,0,0,rebound,1,0,,,2,exact";
  const viscor::csv_table t = viscor::parse_table(header + "\n" + a + "\n" + b + "\n", "t.csv");
  EXPECT_EQ(viscor::table_text(t.kind, t.rows, "t.csv"), header + "\n" + b + "\n" + a + "\n");
  const viscor::csv_table d = viscor::parse_table(header + "\n" + a + "\n" + a + "\n", "t.csv");
  EXPECT_THROW(viscor::table_text(d.kind, d.rows, "t.csv"), viscor::parse_error);
}

TEST(ReferenceTable, StickingRows) {
  const std::string h = viscor::table_header(viscor::table_kind::sticking);
  const std::string row = "0,linear,1,1,g,0.5,0.3,0.29,0.31,2,exact";
  const viscor::csv_table t = viscor::parse_table(h + "\n" + row + "\n", "s.csv");
  EXPECT_EQ(t.kind, viscor::table_kind::sticking);
  const std::string m = error_message([&] { viscor::parse_table(h + "\n0,linear,1,1,g,0.5,0.3,0.31,0.29,2,exact\n", "s.csv"); });
  EXPECT_NE(m.find("s.csv:2: field stick_at: the bracket needs rebound_at < stick_at"), std::string::npos) << m;
}

}  // namespace

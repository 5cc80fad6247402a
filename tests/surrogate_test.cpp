// The CoR surrogates (include/viscor/surrogate/):
//   - Chebyshev interpolation is exact on polynomials of degree < n (1-D and 2-D);
//   - a surrogate file reads back to identical evaluations;
//   - outside its domain a surrogate says so (and never returns a value);
//   - every committed surrogate meets its stated bound on a 2,000-point subsample
//     of its committed certified verification table (every 10th row); the slow
//     test (surrogate_slow_test.cpp) takes all rows;
//   - a perturbed surrogate fails the same check (the check can fail);
//   - the inverse gamma_for round-trips (e_s(gamma_for(e, g), g) = e) on 2,000
//     fixed-seed random (e, g), and is NaN where no gamma in the domain fits;
//   - the 2-D sum by columns (the evaluation's storage) equals the sum by rows to the
//     last bit, for every compiled order and the generic loop;
//   - the grid lookup finds the patch the tree walk finds, also on every split;
//   - a committed file written back from memory is the same file, byte for byte
//     (the coefficients are transposed on reading and on writing);
//   - the evaluation's FMA path (x86 with AVX2 + FMA) and its portable path give
//     bit-identical e, 1 - e, e^2, outcome and inverse;
//   - viscor::evaluate takes the surrogate where its bound meets the tolerance
//     (and its value is within that tolerance of an independent Taylor solve in long
//     double), and falls back outside the domain, near the threshold, or when the
//     tolerance is tighter than the bound.
#include "surrogate_test_utils.hpp"

#include <viscor/core/contact_law.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/surrogate/chebyshev.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_source.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <unistd.h>

namespace {

using namespace viscor::surrogate;

// ctest runs each case in its own process, two at a time: a file name shared by the
// cases of one parametrized test must carry the process (they raced on one file).
std::string temp_path_of_this_process(const std::string& name) {
  return ::testing::TempDir() + "viscor_surrogate_" + std::to_string(::getpid()) + "_" + name;
}

TEST(Chebyshev, InterpolationIsExactOnPolynomials1D) {
  const int n = 12;
  const auto x = chebyshev_points(n);
  auto p = [](long double t) { return 3 - 2 * t + 5 * t * t * t - 0.25L * std::pow(t, 11); };
  std::vector<long double> f;
  for (auto t : x) f.push_back(p(t));
  const auto c = chebyshev_coefficients_1d(f);
  for (double t : {-1.0, -0.73, 0.0, 0.31, 0.999, 1.0})
    EXPECT_NEAR(clenshaw(c.data(), n, t), static_cast<double>(p(t)), 1e-14) << t;
}

TEST(Chebyshev, InterpolationIsExactOnPolynomials2D) {
  for (int n : {8, 12, 16}) {
    const auto x = chebyshev_points(n);
    auto p = [n](long double s, long double t) {
      return 1 + s * t - 3 * s * s + std::pow(t, n - 1) * (s - 0.5L) + std::pow(s, n - 1) * std::pow(t, n - 1);
    };
    std::vector<long double> f;
    for (auto s : x)
      for (auto t : x) f.push_back(p(s, t));
    const auto c = chebyshev_coefficients_2d(f, n);
    for (double s : {-1.0, -0.4, 0.2, 1.0})
      for (double t : {-0.9, 0.0, 0.77, 1.0})
        EXPECT_NEAR(clenshaw_2d(c.data(), n, s, t), static_cast<double>(p(s, t)), 1e-13) << n << " " << s << " " << t;
  }
}

TEST(Chebyshev, SumByColumnsEqualsSumByRowsToTheLastBit) {
  std::mt19937_64 rng(3);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-52 - 1; };
  for (int n : {6, 8, 10, 12, 14, 16}) {
    std::vector<double> rows(static_cast<std::size_t>(n * n)), columns(rows.size());
    for (auto& c : rows) c = u() * std::pow(10.0, -8 * (u() + 1));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) columns[static_cast<std::size_t>(j * n + i)] = rows[static_cast<std::size_t>(i * n + j)];
    for (int k = 0; k < 200; ++k) {
      const double x = u(), y = u();
      EXPECT_EQ(clenshaw_2d_by_columns(columns.data(), n, x, y), clenshaw_2d(rows.data(), n, x, y)) << n << " " << x << " " << y;
    }
  }
}

class CommittedSurrogate : public ::testing::TestWithParam<const char*> {};

TEST_P(CommittedSurrogate, GridLookupFindsThePatchOfTheTreeWalk) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  std::mt19937_64 rng(17);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (const patch_tree* t : {&s->low_load, &s->high_load}) {
    ASSERT_FALSE(t->index.cells.empty());
    std::vector<std::pair<double, double>> points;
    for (int k = 0; k < 20000; ++k) points.push_back({t->x0 + (t->x1 - t->x0) * u(), t->y0 + (t->y1 - t->y0) * u()});
    for (double x : {t->x0, t->x1})
      for (double y : {t->y0, t->y1}) points.push_back({x, y});
    for (const auto& n : t->nodes) {  // on every split, and a rounding either side of it
      if (n.dim == 2) continue;
      for (double v : {n.split, std::nextafter(n.split, -HUGE_VAL), std::nextafter(n.split, HUGE_VAL)}) {
        const double other = n.dim == 0 ? t->y0 + (t->y1 - t->y0) * u() : t->x0 + (t->x1 - t->x0) * u();
        points.push_back(n.dim == 0 ? std::pair{v, other} : std::pair{other, v});
      }
    }
    for (const auto& [x, y] : points) ASSERT_EQ(t->locate(x, y), t->walk(x, y)) << x << " " << y;
  }
}

TEST_P(CommittedSurrogate, WritesTheCommittedFileBackByteForByte) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  std::ifstream in(viscor::test::surrogate_path(GetParam()));
  std::stringstream committed, written;
  committed << in.rdbuf();
  write_cor_surrogate(written, *s);
  EXPECT_TRUE(written.str() == committed.str());
}

TEST_P(CommittedSurrogate, FmaPathIsBitIdenticalToThePortablePath) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  if (!cpu_has_fma()) GTEST_SKIP() << "one path only here (no AVX2 + FMA, or the build targets FMA)";
  std::mt19937_64 rng(23);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int k = 0; k < 20000; ++k) {
    const double gamma = s->gamma_max * u();
    const double g = k % 2 ? s->g_min + (10 - s->g_min) * u() : std::exp(std::log(1e-3) + (std::log(s->g_max) - std::log(1e-3)) * u());
    const auto a = (*s)(gamma, g), b = s->evaluate_portable(gamma, g);
    ASSERT_TRUE(same(a.e, b.e) && same(a.one_minus_e, b.one_minus_e) && same(a.e_squared, b.e_squared) && a.outcome == b.outcome)
        << "gamma = " << gamma << ", g = " << g;
    if (k % 10 == 0) {
      const double e = 0.01 + 0.98999 * u();
      ASSERT_TRUE(same(s->gamma_for(e, g), s->gamma_for_portable(e, g))) << "e = " << e << ", g = " << g;
    }
  }
}

TEST_P(CommittedSurrogate, FileReadsBackIdentically) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  std::stringstream text;
  write_cor_surrogate(text, *s);
  const std::string path = temp_path_of_this_process(std::string(GetParam()) + ".roundtrip.surrogate");
  {
    std::ofstream out(path);
    out << text.str();
  }
  const cor_surrogate t = read_cor_surrogate(path);
  std::remove(path.c_str());
  for (double gamma : {0.0, 1e-9, 0.01, 0.3, 1.0})
    for (double g : {-0.5, -0.1, 0.0, 0.02, 1.0, 57.0, 1e4}) {
      const auto a = (*s)(gamma, g), b = t(gamma, g);
      EXPECT_EQ(a.e, b.e) << gamma << " " << g;
      EXPECT_EQ(a.one_minus_e, b.one_minus_e);
      EXPECT_EQ(a.outcome, b.outcome);
    }
}

TEST_P(CommittedSurrogate, ThresholdPowerIsAppliedAndReadBack) {
  // The threshold line holds h = ln gamma_c + p ln g (cor_surrogate::threshold_power).
  // Adding p x to the line exactly (p mid to T_0, p half-width to T_1 of each interval)
  // and setting threshold_power = p must leave gamma_c unchanged, also after a write
  // and read (file version 2 when p != 0).
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  cor_surrogate t = *s;
  const double p = t.threshold_power + 0.75;
  auto& line = t.log_gamma_c;
  for (std::size_t k = 0; k + 1 < line.breaks.size(); ++k) {
    const double a = line.breaks[k], b = line.breaks[k + 1];
    line.coefficients[k * static_cast<std::size_t>(line.order)] += 0.75 * (a + b) / 2;
    line.coefficients[k * static_cast<std::size_t>(line.order) + 1] += 0.75 * (b - a) / 2;
  }
  t.threshold_power = p;
  std::stringstream text;
  write_cor_surrogate(text, t);
  EXPECT_EQ(text.str().rfind("viscor-cor-surrogate 2\n", 0), 0u);
  const std::string path = temp_path_of_this_process(std::string(GetParam()) + ".power.surrogate");
  {
    std::ofstream out(path);
    out << text.str();
  }
  const cor_surrogate u = read_cor_surrogate(path);
  std::remove(path.c_str());
  EXPECT_EQ(u.threshold_power, p);
  for (double g : {s->g_split * 1.5, 0.3, 1.0, 57.0, 2000.0, 1e4}) {
    if (!(g > s->g_split)) continue;
    EXPECT_NEAR(u.critical_gamma(g) / s->critical_gamma(g), 1.0, 1e-13) << g;
    EXPECT_EQ(u.critical_gamma(g), t.critical_gamma(g)) << g;
  }
}

TEST_P(CommittedSurrogate, OutsideTheDomainNothingIsReturned) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  for (auto [gamma, g] : std::vector<std::pair<double, double>>{{-1e-3, 1}, {1.0001, 1}, {0.1, -0.51}, {0.1, 1.1e4},
                                                               {NAN, 1}, {0.1, NAN}, {INFINITY, 0}})
    EXPECT_FALSE((*s)(gamma, g).in_domain) << gamma << " " << g;
  EXPECT_TRUE((*s)(0.0, 0.0).in_domain);
  EXPECT_EQ((*s)(0.0, 0.0).e, 1.0);  // gamma = 0: no dissipation
  EXPECT_EQ((*s)(0.0, 0.0).one_minus_e, 0.0);
}

TEST_P(CommittedSurrogate, MeetsItsBoundOnASubsampleOfItsVerificationTable) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  ASSERT_TRUE(s->bound.verified());
  const auto refs = viscor::test::load_verification_table(GetParam(), /*every=*/10);
  ASSERT_GE(refs.size(), 2000u);
  const auto failures = viscor::test::bound_violations(*s, refs);
  EXPECT_TRUE(failures.empty()) << failures.size() << " violations; first: " << failures.front();
}

TEST_P(CommittedSurrogate, APerturbedSurrogateFailsTheCheck) {
  auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  // 1e-11 added to the constant term of every low-load patch: a change of 1e-11 gamma in e^2.
  for (std::size_t p = 0; p < s->low_load.patches.size(); ++p)
    s->low_load.coefficients[p * static_cast<std::size_t>(s->low_load.order * s->low_load.order)] += 1e-11;
  const auto refs = viscor::test::load_verification_table(GetParam(), 10);
  EXPECT_FALSE(viscor::test::bound_violations(*s, refs).empty());
}

TEST_P(CommittedSurrogate, InverseRoundTrips) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  std::mt19937_64 rng(41);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  int solved = 0;
  for (int i = 0; i < 2000; ++i) {
    const double e = 0.01 + 0.98999 * u();
    const double g = i % 2 ? s->g_min * u() : std::exp(std::log(1e-3) + (std::log(s->g_max) - std::log(1e-3)) * u());
    const double gamma = s->gamma_for(e, g);
    if (std::isnan(gamma)) {
      // Unreachable in the domain: even gamma_max leaves e above the target.
      EXPECT_GT((*s)(s->gamma_max, g).e, e) << "e = " << e << ", g = " << g;
      continue;
    }
    ++solved;
    ASSERT_TRUE(gamma >= 0 && gamma <= s->gamma_max) << gamma;
    const auto v = (*s)(gamma, g);
    EXPECT_NEAR(v.e, e, 1e-13) << "e = " << e << ", g = " << g << ", gamma = " << gamma;
  }
  EXPECT_GT(solved, 1000);
  EXPECT_TRUE(std::isnan(s->gamma_for(0.005, 1.0)));
  EXPECT_TRUE(std::isnan(s->gamma_for(1.0, 1.0)));
  EXPECT_TRUE(std::isnan(s->gamma_for(0.5, s->g_max * 2)));
}

TEST_P(CommittedSurrogate, EvaluateUsesItWhereItsBoundMeetsTheTolerance) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  const viscor::contact_law law = viscor::law_by_name(GetParam());
  const surrogate_source source(*s);
  viscor::evaluate_options options;
  options.surrogate = &source;
  const viscor::evaluator<double> ev(law, options);
  for (auto [gamma, g] : std::vector<std::pair<double, double>>{{0.05, 1.0}, {0.3, -0.2}, {0.5 * s->critical_gamma(500.0), 500.0}, {0.9, 0.0}}) {
    const auto r = ev(gamma, g, 1e-10);
    EXPECT_EQ(r.method, viscor::evaluation_method::surrogate) << gamma << " " << g;
    EXPECT_LE(r.bound, 1e-10);
    const auto truth = viscor::solve_impact<long double>(law, gamma, g);
    EXPECT_NEAR(r.e, static_cast<double>(truth.e), 1e-10) << gamma << " " << g;
    // Relative on 1 - e as well.
    viscor::evaluate_options relative = options;
    relative.relative = true;
    EXPECT_EQ(viscor::evaluator<double>(law, relative)(gamma, g, 1e-8).method, viscor::evaluation_method::surrogate);
  }
  // A stick well past the threshold: e = 0 exactly (a rebound would break the |de^2|
  // bound), so any tolerance is met. Truth: the Taylor solve in long double.
  {
    const double g_stick = 500, gamma_stick = std::min(s->gamma_max, 2 * s->critical_gamma(g_stick));
    const auto r = ev(gamma_stick, g_stick, 1e-14);
    EXPECT_EQ(r.method, viscor::evaluation_method::surrogate) << gamma_stick;
    EXPECT_EQ(r.outcome, viscor::impact_outcome::stick);
    EXPECT_EQ(r.bound, 0.0);
    EXPECT_EQ(viscor::solve_impact<long double>(law, gamma_stick, g_stick).outcome, viscor::impact_outcome::stick);
  }
  // Falls back: outside the domain, tighter than the bound, at a hair from the threshold.
  EXPECT_NE(ev(1.5, 1.0, 1e-10).method, viscor::evaluation_method::surrogate);
  // (A rebound: a stick's bound is 0, so it meets any tolerance.)
  const double gamma_rebound = std::min(0.05, 0.5 * s->critical_gamma(1.0));
  if (s->bound.abs_e / 2 >= 1e-14)
    EXPECT_NE(ev(gamma_rebound, 1.0, s->bound.abs_e / 2).method, viscor::evaluation_method::surrogate);
  const double g = 50, gamma = s->critical_gamma(g) * (1 - 1e-12);
  EXPECT_NE(ev(gamma, g, 1e-4).method, viscor::evaluation_method::surrogate);
  // A surrogate of another law is refused.
  const viscor::contact_law other = viscor::law_by_name(std::string(GetParam()) == "linear" ? "tsuji" : "linear");
  EXPECT_THROW(viscor::evaluator<double>(other, options), viscor::invalid_parameter);
}

// The same surrogate without a verification (safety factor 0: no bound is claimed) is
// never used, even where the verified one is; a damaged (truncated) file is not read.
TEST_P(CommittedSurrogate, UnverifiedOrDamagedIsRefused) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  const viscor::contact_law law = viscor::law_by_name(GetParam());
  cor_surrogate unverified = *s;
  unverified.bound.safety_factor = 0;
  ASSERT_FALSE(unverified.bound.verified());
  const surrogate_source verified_source(*s), unverified_source(unverified);
  viscor::evaluate_options verified_options, unverified_options;
  verified_options.surrogate = &verified_source;
  unverified_options.surrogate = &unverified_source;
  const viscor::evaluator<double> verified(law, verified_options), refused(law, unverified_options);
  for (auto [gamma, g] : std::vector<std::pair<double, double>>{{0.05, 1.0}, {0.3, -0.2}, {0.9, 0.0}}) {
    ASSERT_EQ(verified(gamma, g, 1e-10).method, viscor::evaluation_method::surrogate) << gamma << " " << g;
    const auto r = refused(gamma, g, 1e-10);
    EXPECT_NE(r.method, viscor::evaluation_method::surrogate) << gamma << " " << g;
    EXPECT_LE(r.bound, 1e-10);
  }
  std::stringstream written;
  write_cor_surrogate(written, *s);
  const std::string text = written.str();
  const std::string damaged = ::testing::TempDir() + "damaged_" + GetParam() + ".surrogate";
  std::ofstream(damaged) << text.substr(0, text.size() / 2);
  EXPECT_THROW(read_cor_surrogate(damaged), viscor::parse_error);
  std::remove(damaged.c_str());
}

INSTANTIATE_TEST_SUITE_P(Laws, CommittedSurrogate,
                         ::testing::Values("linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"));

}  // namespace

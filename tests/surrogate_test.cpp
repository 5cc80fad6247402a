// The CoR surrogates (include/viscor/surrogate/):
//   - Chebyshev interpolation is exact on polynomials of degree < n (1-D and 2-D);
//   - a surrogate file reads back to identical evaluations;
//   - outside its domain a surrogate says so (and never returns a value);
//   - every committed surrogate meets its stated bound on a 2,000-point subsample
//     of its committed certified verification table (every 10th row); the slow
//     test (surrogate_slow_test.cpp) takes all rows;
//   - a perturbed surrogate fails the same check (the check can fail).
#include "surrogate_test_utils.hpp"

#include <viscor/surrogate/chebyshev.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

using namespace viscor::surrogate;

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

class CommittedSurrogate : public ::testing::TestWithParam<const char*> {};

TEST_P(CommittedSurrogate, FileReadsBackIdentically) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) GTEST_SKIP() << "no committed surrogate for " << GetParam();
  std::stringstream text;
  write_cor_surrogate(text, *s);
  const std::string path = ::testing::TempDir() + "/roundtrip.surrogate";
  {
    std::ofstream out(path);
    out << text.str();
  }
  const cor_surrogate t = read_cor_surrogate(path);
  for (double gamma : {0.0, 1e-9, 0.01, 0.3, 1.0})
    for (double g : {-0.5, -0.1, 0.0, 0.02, 1.0, 57.0, 1e4}) {
      const auto a = (*s)(gamma, g), b = t(gamma, g);
      EXPECT_EQ(a.e, b.e) << gamma << " " << g;
      EXPECT_EQ(a.one_minus_e, b.one_minus_e);
      EXPECT_EQ(a.outcome, b.outcome);
    }
}

TEST_P(CommittedSurrogate, OutsideTheDomainNothingIsReturned) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) GTEST_SKIP() << "no committed surrogate for " << GetParam();
  for (auto [gamma, g] : std::vector<std::pair<double, double>>{{-1e-3, 1}, {1.0001, 1}, {0.1, -0.51}, {0.1, 1.1e4},
                                                               {NAN, 1}, {0.1, NAN}, {INFINITY, 0}})
    EXPECT_FALSE((*s)(gamma, g).in_domain) << gamma << " " << g;
  EXPECT_TRUE((*s)(0.0, 0.0).in_domain);
  EXPECT_EQ((*s)(0.0, 0.0).e, 1.0);  // gamma = 0: no dissipation
  EXPECT_EQ((*s)(0.0, 0.0).one_minus_e, 0.0);
}

TEST_P(CommittedSurrogate, MeetsItsBoundOnASubsampleOfItsVerificationTable) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) GTEST_SKIP() << "no committed surrogate for " << GetParam();
  ASSERT_TRUE(s->bound.verified());
  const auto refs = viscor::test::load_verification_table(GetParam(), /*every=*/10);
  ASSERT_GE(refs.size(), 2000u);
  const auto failures = viscor::test::bound_violations(*s, refs);
  EXPECT_TRUE(failures.empty()) << failures.size() << " violations; first: " << failures.front();
}

TEST_P(CommittedSurrogate, APerturbedSurrogateFailsTheCheck) {
  auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) GTEST_SKIP() << "no committed surrogate for " << GetParam();
  // 1e-11 added to the constant term of every low-load patch: a change of 1e-11 gamma in e^2.
  for (std::size_t p = 0; p < s->low_load.patches.size(); ++p)
    s->low_load.coefficients[p * static_cast<std::size_t>(s->low_load.order * s->low_load.order)] += 1e-11;
  const auto refs = viscor::test::load_verification_table(GetParam(), 10);
  EXPECT_FALSE(viscor::test::bound_violations(*s, refs).empty());
}

INSTANTIATE_TEST_SUITE_P(Laws, CommittedSurrogate,
                         ::testing::Values("linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"));

}  // namespace

// Bad input: a typed exception naming the parameter and its value through the
// API; through the CLI a non-zero exit, the message, and no output file.
#include "test_utils.hpp"

#include <viscor/viscor.hpp>

#include <filesystem>
#include <functional>

namespace viscor::test {
namespace {

// Runs f, expects an exception of type E whose message contains every fragment.
template <class E>
void expect_error(const std::function<void()>& f, std::initializer_list<const char*> fragments) {
  try {
    f();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    const std::string what = e.what();
    for (const char* fragment : fragments) EXPECT_NE(what.find(fragment), std::string::npos) << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

TEST(Validation, ContactLawExponents) {
  expect_error<invalid_parameter>([] { make_law(exponent::parse("0.5", "alpha"), exponent::rational(1, 1)); },
                                  {"alpha", "1/2"});
  expect_error<invalid_parameter>([] { make_law(exponent::rational(3, 2), exponent::parse("9/10", "beta")); },
                                  {"beta", "9/10"});
  expect_error<invalid_parameter>([] { exponent::parse("3/0", "alpha"); }, {"alpha", "3/0"});
  expect_error<invalid_parameter>([] { exponent::parse("1.5x", "beta"); }, {"beta", "1.5x"});
  expect_error<invalid_parameter>([] { exponent::parse("nan", "alpha"); }, {"alpha", "nan"});
  expect_error<invalid_parameter>([] { law_by_name("hooke"); }, {"hooke", "kuwabara_kono"});
}

TEST(Validation, ExponentsKeepExactRationals) {
  EXPECT_EQ(exponent::parse("3/2", "a"), exponent::rational(3, 2));
  EXPECT_EQ(exponent::parse("1.5", "a"), exponent::rational(3, 2));
  EXPECT_EQ(exponent::parse("1.25e0", "a"), exponent::rational(5, 4));
  EXPECT_EQ(exponent::parse("6/4", "a").to_string(), "3/2");
  EXPECT_TRUE(exponent::parse("1.3", "a").is_rational());
  EXPECT_EQ(exponent::parse("1.3", "a").denominator(), 10);
  const exponent irrational = exponent::parse("1.41421356237309504880168872420969807856967187537694", "a");
  EXPECT_FALSE(irrational.is_rational());
  // the long decimal is kept exactly: read at 50 digits it carries 50 digits
  EXPECT_GE(agreeing_digits(irrational.value<mpfr_50>(), mpfr_50(sqrt(mpfr_50(2)))), 49);
}

TEST(Validation, ImpactParameters) {
  const contact_law kk = law_by_name("kuwabara_kono");
  expect_error<invalid_parameter>([&] { exact_cor(kk, -0.5, 0.0); }, {"gamma", "-5"});
  expect_error<invalid_parameter>([&] { exact_cor(kk, std::nan(""), 0.0); }, {"gamma", "nan"});
  expect_error<invalid_parameter>([&] { exact_cor(kk, 0.1, HUGE_VAL); }, {"g", "inf"});
  expect_error<invalid_parameter>([&] { exact_cor(kk, mpfr_50(-1), mpfr_50(0)); }, {"gamma", "-1"});
  expect_error<invalid_parameter>([] { parse_real<double>("1e999", "g"); }, {"g", "1e999"});
  expect_error<invalid_parameter>([] { parse_real<mpfr_50>("0x1p3", "gamma"); }, {"gamma", "0x1p3"});
}

TEST(Validation, PhysicalParameters) {
  const contact_law kk = law_by_name("kuwabara_kono");
  physical_parameters<double> good;
  good.m = 1, good.k = 1e9, good.v0 = 1, good.gamma0 = 0, good.gravity = 9.8;
  for (auto [field, name] : {std::pair{&physical_parameters<double>::m, "m"}, std::pair{&physical_parameters<double>::k, "k"},
                             std::pair{&physical_parameters<double>::v0, "v0"}}) {
    auto p = good;
    p.*field = 0;
    expect_error<invalid_parameter>([&] { to_scaled(kk, p); }, {name, "> 0"});
    p.*field = -2;
    expect_error<invalid_parameter>([&] { to_scaled(kk, p); }, {name, "-2"});
  }
  auto p = good;
  p.gamma0 = -1;
  expect_error<invalid_parameter>([&] { to_scaled(kk, p); }, {"gamma0", "-1"});
  expect_error<invalid_parameter>([&] { to_physical(kk, 0.1, 0.0, -1.0, 1e9, 1.0, 9.8); }, {"m", "-1"});
}

TEST(Validation, PrecisionRequests) {
  expect_error<precision_unavailable>([] { scalar_for_digits(0); }, {"digits", "0"});
  expect_error<precision_unavailable>([] { scalar_for_digits(-3); }, {"digits", "-3"});
  expect_error<precision_unavailable>([] { scalar_for_digits(max_working_digits + 1); }, {"digits", "100001"});
  EXPECT_EQ(scalar_for_digits(15), scalar_kind::double_);
  EXPECT_EQ(scalar_for_digits(30), VISCOR_HAS_QD ? scalar_kind::double_double : scalar_kind::quad);
  EXPECT_EQ(scalar_for_digits(40), scalar_kind::mpfr);
  // a 300-digit request really computes with 300 digits
  const int digits = with_working_precision(300, []<class Real>() { return decimal_digits<Real>(); });
  EXPECT_GE(digits, 300);
}

// ---- the same through the CLI ----
struct cli_case {
  const char* args;
  const char* message;
};

TEST(Validation, CliRejectsBadInputAndWritesNothing) {
  const cli_case cases[] = {
      {"exact --alpha 0.5 --beta 1 --gamma 0.1", "alpha = 1/2"},
      {"exact --alpha 3/2 --beta 0 --gamma 0.1", "beta = 0"},
      {"exact --model linear --gamma -0.1", "gamma must be >= 0"},
      {"exact --model linear --gamma nan", "gamma"},
      {"exact --model linear --gamma 0.1 --g inf", "parameter g"},
      {"exact --model linear --gamma 0.1 --digits 0", "digits = 0"},
      {"exact --model linear --gamma 0.1 --digits 1000000", "digits = 1000000"},
      {"exact --model newton --gamma 0.1", "unknown contact law 'newton'"},
      {"scale --model kuwabara_kono --m -1 --k 1e9 --v0 1 --gamma0 0 --gravity 9.8", "parameter m"},
      {"scale --model kuwabara_kono --m 1 --k 0 --v0 1 --gamma0 0 --gravity 9.8", "parameter k"},
      {"scale --model kuwabara_kono --m 1 --k 1e9 --v0 -3 --gamma0 0 --gravity 9.8", "parameter v0"},
  };
  const std::string path = ::testing::TempDir() + "viscor_validation_output.json";
  for (const auto& c : cases) {
    std::filesystem::remove(path);
    const cli_run r = run_cli(std::string(c.args) + " --json -o " + path);
    EXPECT_NE(r.status, 0) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\nstderr: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(path)) << c.args;
  }
  // and a good run does write the file
  const cli_run ok = run_cli("exact --model linear --gamma 0.1 --g 1 --json -o " + path);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace viscor::test

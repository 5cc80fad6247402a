// viscor::enclose (include/viscor/enclose/enclose.hpp): the
// public entry point's decimal bounds of e, 1 - e, T_f and u_max contain the closed
// forms (include/viscor/exact/, evaluated in MPFR at 2D + 20 digits: formulas, not
// this integrator) at 30 and 50 digits, its proven digits are correctly rounded
// digits of the exact value, and u_max is tight (interval Newton at the turning
// point). Both provers are covered: the linear law through enclose()
// (proven_linear.hpp) and through prove_impact (the general prover).
#include <viscor/enclose/enclose.hpp>
#include <viscor/exact/exact_hunt_crossley.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace viscor;
using namespace viscor::proofs;

/// Whether lower <= x <= upper, the bounds read exactly (decimal strings at a precision far above x's).
bool within(const proven_bounds& b, const mpfr_real& x) {
  const mpfr_real lower(b.lower), upper(b.upper);
  return lower <= x && x <= upper;
}

/// x rounded to nearest at d significant digits, as MPFR prints it (digits, exponent).
std::string rounded(const mpfr_real& x, int d) {
  mpfr_exp_t exponent = 0;
  char* s = mpfr_get_str(nullptr, &exponent, 10, static_cast<std::size_t>(d), x.backend().data(), MPFR_RNDN);
  std::string out = std::string(s) + "e" + std::to_string(exponent);
  mpfr_free_str(s);
  return out;
}

/// The checks of one quantity against its exact value: inside, its proven digits
/// are the exact value's correctly rounded digits, and at least `least` of them.
void expect_proven(const proven_bounds& b, const mpfr_real& exact, int least, const std::string& what) {
  EXPECT_TRUE(within(b, exact)) << what << ": exact " << to_decimal_string(exact, 60) << " outside [" << b.lower
                                << ", " << b.upper << "]";
  EXPECT_GE(b.proven_digits, least) << what;
  if (b.proven_digits > 0)
    EXPECT_EQ(rounded(exact, b.proven_digits), rounded(mpfr_real(b.lower), b.proven_digits))
        << what << ": " << b.proven_digits << " digits are not the correctly rounded ones";
}

struct closed_case {
  std::string law, gamma, g;
};

const std::vector<closed_case> cases{{"linear", "0.3", "0.2"},  {"linear", "0.1", "-0.5"},
                                     {"linear", "0.05", "1"},  {"linear", "0", "1"},
                                     {"linear", "1.5", "0"},  {"hunt_crossley", "0.001", "0"},
                                     {"hunt_crossley", "0.2", "0"}, {"hunt_crossley", "0.6", "0"}};

TEST(EncloseApi, BoundsContainTheClosedFormsIncludingMaxCompression) {
  for (const int digits : {30, 50}) {
    for (const auto& c : cases) {
      const std::string at = c.law + " gamma " + c.gamma + " g " + c.g + " at " + std::to_string(digits) + ": ";
      const cor_enclosure proof = enclose(law_by_name(c.law), c.gamma, c.g, digits);
      scoped_precision precision(2 * digits + 20);
      const auto exact = c.law == "linear" ? exact_linear(mpfr_real(c.gamma), mpfr_real(c.g))
                                           : exact_hunt_crossley(mpfr_real(3) / 2, mpfr_real(c.gamma));
      ASSERT_EQ(proof.outcome, proven_outcome::rebound) << at << proof.how;
      ASSERT_EQ(exact.outcome, impact_outcome::rebound) << at;
      expect_proven(proof.e, exact.e, digits - 3, at + "e");
      expect_proven(proof.one_minus_e, exact.one_minus_e, c.gamma == "0" ? 0 : digits - 3, at + "1 - e");
      ASSERT_TRUE(proof.contact_time.has_value()) << at;
      if (exact.contact_time) expect_proven(*proof.contact_time, *exact.contact_time, digits - 3, at + "T_f");
      ASSERT_TRUE(proof.max_compression.has_value()) << at << "no u_max";
      ASSERT_TRUE(exact.max_compression.has_value()) << at;
      expect_proven(*proof.max_compression, *exact.max_compression, digits - 3, at + "u_max");
    }
  }
}

TEST(EncloseApi, GeneralProverEnclosesTheLinearMaxCompression) {
  // The linear law through prove_impact (Q = 1), not proven_linear.hpp.
  for (const auto& [gamma, g] : std::vector<std::pair<std::string, std::string>>{{"0.3", "0.2"}, {"0.2", "0.5"}}) {
    const proven_impact proof = prove_impact(law_by_name("linear"), gamma, g, 30);
    ASSERT_EQ(proof.outcome, proven_outcome::rebound) << proof.how;
    ASSERT_TRUE(proof.max_compression.has_value());
    scoped_precision precision(80);
    const auto exact = exact_linear(mpfr_real(gamma), mpfr_real(g));
    scoped_ball_bits bits(working_bits(80));
    const ball truth = ball::from_decimal(to_decimal_string(*exact.max_compression, 80))
                           .widened(ball::from_decimal("1e-70"));
    EXPECT_TRUE(proof.max_compression->contains(truth)) << gamma << " " << g << ": " << proof.max_compression->str(40);
    EXPECT_GE(proven_impact::relative_digits(*proof.max_compression), 27) << proof.max_compression->str(40);
  }
}

TEST(EncloseApi, StickIsExactAndNonRationalIsNotProvable) {
  const cor_enclosure stick = enclose(law_by_name("kuwabara_kono"), "0.5", "3", 20);
  ASSERT_EQ(stick.outcome, proven_outcome::stick) << stick.how;
  EXPECT_EQ(stick.e.lower, "0");
  EXPECT_EQ(stick.e.upper, "0");
  EXPECT_EQ(stick.one_minus_e.lower, "1");
  EXPECT_EQ(stick.e.proven_digits, 20);
  const contact_law irrational{exponent::parse("1.4142135623730950488016887242097", "alpha"), exponent::parse("1", "beta")};
  try {
    (void)enclose(irrational, "0.1", "0", 30);
    FAIL() << "a non-rational exponent was enclosed";
  } catch (const invalid_parameter& e) {
    EXPECT_NE(std::string(e.what()).find("not provable"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1.41421356"), std::string::npos) << e.what();
  }
}

}  // namespace

// The big certification sweeps (label "slow"): honesty over every exact
// case at 50 digits and over >= 200 random points (fixed seed), and the 45-digit
// floor at 50 digits over the whole grid of named laws.
#include "certification_test_utils.hpp"

#include <gtest/gtest.h>

namespace {

using namespace viscor;
using viscor::test::check_honesty;

TEST(certification_slow, honest_on_a_random_sample_of_240_points_in_double) {
  int informative = 0, total = 0;
  for (const auto& p : test::random_sample_points(240, 4242u)) {
    informative += check_honesty<double>(p).certified_digits >= 10;
    ++total;
  }
  // Honesty must not come from certifying nothing: most points carry >= 10 digits.
  EXPECT_GE(informative, total * 9 / 10);
}

#if VISCOR_HAS_MPFR
TEST(certification_slow, honest_on_every_exact_case_at_50_digits) {
  for (const auto& p : test::exact_sample_points()) check_honesty<mpfr_50>(p);
}

TEST(certification_slow, honest_on_a_random_sample_at_50_digits) {
  for (const auto& p : test::random_sample_points(60, 777u)) check_honesty<mpfr_50>(p);
}

TEST(certification_slow, at_least_45_digits_at_50_for_named_laws_everywhere) {
  // g in {0, 0.05, 1, 10}, gamma in {1e-4, 1e-3, 1e-2, 0.05, 0.1}; a point within
  // 1e-6 (relative in g) of the sticking threshold is exempt: there the outcome
  // flips and absolute digits are what is reported.
  for (const auto& n : named_laws) {
    const contact_law law = law_by_name(n.name);
    for (const char* g : {"0", "0.05", "1", "10"}) {
      for (const char* gamma : {"1e-4", "1e-3", "1e-2", "0.05", "0.1"}) {
        SCOPED_TRACE(std::string(n.name) + " gamma = " + gamma + " g = " + g);
        const mpfr_50 gm(gamma), gg(g);
        const auto c = certify<mpfr_50>(law, gm, gg);
        if (c.certified_digits >= 45) continue;
        bool near_threshold = false;
        if (gg != 0) {
          const auto below = certify<mpfr_50>(law, gm, mpfr_50(gg * (1 - mpfr_50(1e-6))));
          const auto above = certify<mpfr_50>(law, gm, mpfr_50(gg * (1 + mpfr_50(1e-6))));
          near_threshold = below.outcome != above.outcome;
        }
        EXPECT_TRUE(near_threshold) << "certified only " << c.certified_digits << " digits (e " << c.certified_digits_e << ", 1-e "
                                    << c.certified_digits_one_minus_e << ", T " << c.certified_digits_contact_time << ", u_max "
                                    << c.certified_digits_max_compression << ")";
        if (near_threshold) EXPECT_TRUE(c.near_sticking || c.certified_absolute_digits_e >= 45);
      }
    }
  }
}
#endif

}  // namespace

// The double tail of float128 jets (detail/taylor_tail.hpp), time and endpoint systems: the
// orders computed in double must change the step polynomial by less than a quarter
// of the tolerance at the step the integrator takes. Reference: the same jet
// computed entirely at 50 digits (mpfr_50 has no tail), from the same state.
#include <viscor/core/contact_law.hpp>
#include <viscor/impact/detail/impact_systems.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <gtest/gtest.h>

#include "test_utils.hpp"

#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace viscor {
namespace {

#if VISCOR_HAS_FLOAT128 && VISCOR_HAS_MPFR
// The solver's constants (one place: detail::make_impact_constants).
template <class Real>
detail::impact_constants<Real> constants(const contact_law& law, const char* gamma, const char* g) {
  return detail::make_impact_constants(law, parse_real<Real>(gamma, "gamma"), parse_real<Real>(g, "g"));
}

// What the orders from tail_start on change in the step polynomial at h: the
// difference of the two jets there, summed over those orders.
template <class Integrator>
mpfr_50 tail_difference(const taylor_jet<quad>& jq, const Integrator& im, std::size_t i, std::size_t start,
                        const quad& h) {
  mpfr_50 difference = 0;
  for (std::size_t k = start; k <= jq.order(); ++k)
    difference += abs(mpfr_50(jq[i][k]) - im.jet()[i][k]) * pow(mpfr_50(h), static_cast<long>(k));
  return difference;
}

TEST(TaylorTail, TimeJetWithinTheToleranceOfTheFullPrecisionJetAtTheStepTaken) {
  using ts_quad = detail::time_system<quad>;
  using ts_mpfr = detail::time_system<mpfr_50>;
  const quad tol = epsilon<quad>();
  const mpfr_50 tol_m = mpfr_50(tol);
  int tails = 0;
  for (const char* name : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"}) {
    const contact_law law = law_by_name(name);
    for (auto [gamma, g] : {std::pair{"0.05", "1"}, {"1e-3", "0.05"}, {"0.5", "0"}, {"1e-4", "10"}}) {
      const auto cq = constants<quad>(law, gamma, g);
      const auto cm = constants<mpfr_50>(law, gamma, g);
      // states along a compression and a restitution: (u, v, D)
      for (auto [u, v] : {std::pair{"0.3", "0.9"}, {"1.1", "0.2"}, {"0.02", "-0.7"}, {"1e-6", "0.999"}}) {
        ts_quad sq(cq, taylor_order(tol), tol);
        ts_mpfr sm(cm, taylor_order(tol_m), tol_m);
        taylor_integrator<quad, ts_quad> iq(sq, tol);
        taylor_integrator<mpfr_50, ts_mpfr> im(sm, tol_m);
        ASSERT_EQ(iq.order(), im.order());
        const std::vector<quad> x{parse_real<quad>(u, "u"), parse_real<quad>(v, "v"), quad("1e-3")};
        const std::vector<mpfr_50> xm{mpfr_50(x[0]), mpfr_50(x[1]), mpfr_50(x[2])};
        const quad h = iq.expand(quad(0), x, quad(1e30));
        im.expand(mpfr_50(0), xm, mpfr_50(1e30));
        if (sq.tail_start() <= iq.order()) ++tails;
        for (std::size_t i = 0; i < 3; ++i) {
          // Against the design budget of a quarter of the tolerance on component i.
          // (Below tail_start both jets differ by float128's own rounding only.)
          const mpfr_50 difference = tail_difference(iq.jet(), im, i, sq.tail_start(), h);
          const mpfr_50 allowed = tol_m * mpfr_50(sq.step_scale(i, x[i])) / 4;
          EXPECT_LE(difference, allowed) << name << " gamma = " << gamma << " g = " << g << " u = " << u
                                         << " v = " << v << " component " << i << " h = " << h;
        }
      }
    }
  }
  // The tail must actually have been used (else this test checks nothing new).
  EXPECT_GT(tails, 60);
}

TEST(TaylorTail, EndpointJetWithinTheToleranceOfTheFullPrecisionJetAtTheStepTaken) {
  using es_quad = detail::endpoint_system<quad>;
  using es_mpfr = detail::endpoint_system<mpfr_50>;
  const quad tol = epsilon<quad>();
  const mpfr_50 tol_m = mpfr_50(tol);
  int tails = 0;
  std::vector<contact_law> laws;
  for (const char* name : {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"})
    laws.push_back(law_by_name(name));
  // real exponents (denominators beyond exponent::max_denominator): u = exp(sigma)
  laws.push_back(make_law(exponent::parse("1.3000000000000000000001", "alpha"),
                          exponent::parse("1.7000000000000000000001", "beta")));
  for (const contact_law& law : laws) {
    for (auto [gamma, g] : {std::pair{"0.05", "1"}, {"1e-3", "0.05"}, {"0.5", "0"}, {"1e-4", "10"}}) {
      const auto cq = constants<quad>(law, gamma, g);
      const auto cm = constants<mpfr_50>(law, gamma, g);
      // (sigma, v): the start of contact, on the way in, on the way out
      const bool root = cq.use_root_variable;
      for (auto [sigma, v] : {std::pair{root ? "0" : "-20", "1"}, {root ? "0.3" : "-2", "0.8"},
                              {root ? "0.5" : "-1", "-0.6"}}) {
        es_quad sq(cq, taylor_order(tol), tol);
        es_mpfr sm(cm, taylor_order(tol_m), tol_m);
        taylor_integrator<quad, es_quad> iq(sq, tol);
        taylor_integrator<mpfr_50, es_mpfr> im(sm, tol_m);
        const quad s0 = parse_real<quad>(sigma, "sigma");
        const std::vector<quad> x{parse_real<quad>(v, "v"), quad("0.1"), quad("1e-3")};
        const std::vector<mpfr_50> xm{mpfr_50(x[0]), mpfr_50(x[1]), mpfr_50(x[2])};
        const quad h = iq.expand(s0, x, quad(1e30));
        im.expand(mpfr_50(s0), xm, mpfr_50(1e30));
        if (sq.tail_start() <= iq.order()) ++tails;
        for (std::size_t i = 0; i < 3; ++i) {
          const mpfr_50 difference = tail_difference(iq.jet(), im, i, sq.tail_start(), h);
          const mpfr_50 allowed = tol_m * mpfr_50(sq.step_scale(i, x[i])) / 4;
          EXPECT_LE(difference, allowed) << law.describe() << " gamma = " << gamma << " g = " << g
                                         << " sigma = " << sigma << " v = " << v << " component " << i
                                         << " h = " << h;
        }
      }
    }
  }
  EXPECT_GT(tails, 50);
}

// Constants outside double's normal range (gamma = 1e-320 is subnormal in
// double, 1e-400 is 0 there; g likewise) must switch the tail off, since D's orders
// are proportional to gamma and are wanted relative to D itself.
TEST(TaylorTail, ConstantsOutsideDoublesNormalRangeSwitchTheTailOff) {
  const quad tol = epsilon<quad>();
  const mpfr_50 tol_m = mpfr_50(tol);
  const contact_law law = law_by_name("kuwabara_kono");
  for (auto [gamma, g, D] : {std::tuple{"1e-320", "1", "1e-321"}, {"1e-400", "1", "1e-401"},
                             {"1e-310", "0.5", "1e-311"}, {"0.05", "1e-320", "1e-3"}}) {
    SCOPED_TRACE(std::string("gamma = ") + gamma + ", g = " + g);
    const auto cq = constants<quad>(law, gamma, g);
    const auto cm = constants<mpfr_50>(law, gamma, g);
    {
      detail::time_system<quad> sq(cq, taylor_order(tol), tol);
      detail::time_system<mpfr_50> sm(cm, taylor_order(tol_m), tol_m);
      taylor_integrator<quad, detail::time_system<quad>> iq(sq, tol);
      taylor_integrator<mpfr_50, detail::time_system<mpfr_50>> im(sm, tol_m);
      const std::vector<quad> x{quad("0.3"), quad("0.9"), parse_real<quad>(D, "D")};
      const quad h = iq.expand(quad(0), x, quad(1e30));
      im.expand(mpfr_50(0), {mpfr_50(x[0]), mpfr_50(x[1]), mpfr_50(x[2])}, mpfr_50(1e30));
      EXPECT_GT(sq.tail_start(), iq.order()) << "time jet: the tail ran";
      for (std::size_t i = 0; i < 3; ++i)
        EXPECT_LE(tail_difference(iq.jet(), im, i, sq.tail_start(), h),
                  tol_m * mpfr_50(sq.step_scale(i, x[i])) / 4)
            << "time jet, component " << i;
    }
    {
      detail::endpoint_system<quad> sq(cq, taylor_order(tol), tol);
      detail::endpoint_system<mpfr_50> sm(cm, taylor_order(tol_m), tol_m);
      taylor_integrator<quad, detail::endpoint_system<quad>> iq(sq, tol);
      taylor_integrator<mpfr_50, detail::endpoint_system<mpfr_50>> im(sm, tol_m);
      const std::vector<quad> x{quad("0.8"), quad("0.1"), parse_real<quad>(D, "D")};
      const quad h = iq.expand(quad("0.3"), x, quad(1e30));
      im.expand(mpfr_50("0.3"), {mpfr_50(x[0]), mpfr_50(x[1]), mpfr_50(x[2])}, mpfr_50(1e30));
      if (std::string(g) != "1e-320") EXPECT_GT(sq.tail_start(), iq.order()) << "endpoint jet: the tail ran";
      for (std::size_t i = 0; i < 3; ++i)
        EXPECT_LE(tail_difference(iq.jet(), im, i, sq.tail_start(), h),
                  tol_m * mpfr_50(sq.step_scale(i, x[i])) / 4)
            << "endpoint jet, component " << i;
    }
  }
}

// At the start of contact tau = D = 0, so the step cap, which measures a
// state relative to its value, cannot see what the tail does to them: the orders
// computed in double must then change tau(h) and D(h) by less than a quarter of the
// tolerance relative to those values (or the tail must be off).
TEST(TaylorTail, StatesThatAreZeroAtTheExpansionPointKeepTheirDigits) {
  const quad tol = epsilon<quad>();
  const mpfr_50 tol_m = mpfr_50(tol);
  for (const char* name : {"hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"}) {
    const contact_law law = law_by_name(name);
    for (auto [gamma, g] : {std::pair{"0.05", "1"}, {"1e-3", "0.05"}, {"0.5", "0"}, {"1e-4", "10"}}) {
      SCOPED_TRACE(std::string(name) + " gamma = " + gamma + " g = " + g);
      const auto cq = constants<quad>(law, gamma, g);
      const auto cm = constants<mpfr_50>(law, gamma, g);
      detail::endpoint_system<quad> sq(cq, taylor_order(tol), tol);
      detail::endpoint_system<mpfr_50> sm(cm, taylor_order(tol_m), tol_m);
      taylor_integrator<quad, detail::endpoint_system<quad>> iq(sq, tol);
      taylor_integrator<mpfr_50, detail::endpoint_system<mpfr_50>> im(sm, tol_m);
      const std::vector<quad> x{quad(1), quad(0), quad(0)};  // v = 1, tau = 0, D = 0 at s = 0
      const quad h = iq.expand(quad(0), x, quad(1e30));
      im.expand(mpfr_50(0), {mpfr_50(1), mpfr_50(0), mpfr_50(0)}, mpfr_50(1e30));
      for (std::size_t i : {std::size_t(1), std::size_t(2)}) {
        const mpfr_50 value = abs(im.value(i, mpfr_50(h)));
        EXPECT_LE(tail_difference(iq.jet(), im, i, std::min(sq.tail_start(), iq.order() + 1), h), tol_m * value / 4)
            << "component " << i << ", tail from order " << sq.tail_start() << " of " << iq.order();
      }
    }
  }
}
#endif

}  // namespace
}  // namespace viscor

// The proof's building blocks against closed forms written here, and mutation tests
// that show the checks have teeth at the default tolerance.
//
// This program is compiled with VISCOR_PROOF_MUTATIONS (tests/CMakeLists.txt), which
// opens the test seam of include/viscor/enclose/mutation_seam.hpp; no other build has it.
//
// The truth: the oscillator u'' + gamma u' + u = 0, u(0) = 0, u'(0) = 1 (the linear
// law at g = 0), with w = sqrt(1 - gamma^2 / 4),
//     u(t) = exp(-gamma t / 2) sin(w t) / w,
//     v(t) = u'(t) = exp(-gamma t / 2) (cos(w t) - gamma / (2 w) sin(w t)),
// u falls through 0 at t = pi / w (rises at 2 pi / w), and v falls through 0 at
// t_m = atan(2 w / gamma) / w (pi / 2 at gamma = 0), where sin(w t_m) = w, so that
// u_max = exp(-gamma t_m / 2). Evaluated with Arb's elementary functions (not with
// viscor's integrator) at 64 bits more than the balls under test.
//
// - validated_step (validated_taylor.hpp): at orders 1 to 40 and steps 1/4 to 2,
//   from the exact start and from a ball state, the step's polynomial with its
//   remainder and its range hold u and v at points of the step (and, with the
//   linear prover's own system, w = 1 - u^2 - v^2, the energy identity at g = 0);
// - the crossing search (crossing.hpp): a falling and a rising crossing are enclosed
//   to within 2^-(bits - 16), an interval without a crossing or with two gives none;
// - first_maximum: interval Newton encloses u_max tightly; the fallback (v' not
//   proven of one sign) still holds it, in a hull of pieces.
//
// The mutations, each switched on alone, each caught by a default-suite test at the
// default working precision (that of a 30-digit proof, 128 bits):
// (1) the remainder scaled down 1e-3 and 1e-6, (2) the remainder taken from the
// initial state's jet instead of the a priori box, (3) the box's inclusion test
// skipped: validated steps at low order and long steps, where the truncation error
// is far above the rounding (at order 4 and h = 1 it is about 1e-2 against 2^-128),
// so an enclosure that drops even a part of it misses sin(h). (The whole provers at
// their default tolerance stay right under these mutations, measured: their box
// remainder over-estimates the truncation error by about 2^20; docs/proofs.md,
// "Mutation tests".) The "remainder under-estimated in coarse steps" checks of the
// whole provers (steps aimed at 40 bits) are here too, as they use the same seam.
// (4) a crossing accepted without its sign proofs: in a step where u falls through 0
// and rises again, the search then returns the second zero as the crossing.
#include <viscor/enclose/crossing.hpp>
#include <viscor/enclose/proven_impact.hpp>
#include <viscor/enclose/proven_linear.hpp>
#include <viscor/enclose/validated_taylor.hpp>
#include <viscor/exact/exact_hunt_crossley.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_tsuji.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "enclose_test_points.hpp"

#ifndef VISCOR_PROOF_MUTATIONS
#error "enclose_proof_mutation_test needs VISCOR_PROOF_MUTATIONS (tests/CMakeLists.txt)"
#endif

namespace {

using namespace viscor;
using namespace viscor::proofs;

/// Switches one mutation on for its lifetime.
class mutation {
 public:
  explicit mutation(proof_mutation m, double factor = 1) { proof_mutation_seam = {m, factor}; }
  ~mutation() { proof_mutation_seam = {}; }
  mutation(const mutation&) = delete;
  mutation& operator=(const mutation&) = delete;
};

/// u' = v, v' = -gamma v - u (the system under test, written here).
struct oscillator {
  ball gamma;
  std::size_t size() const { return 2; }
  ball_jet jet(const std::vector<ball>& x, std::size_t order) const {
    ball_jet c(2, std::vector<ball>(order + 1));
    c[0][0] = x[0], c[1][0] = x[1];
    for (std::size_t k = 0; k < order; ++k) {
      const ball next(static_cast<long>(k + 1));
      c[0][k + 1] = c[1][k] / next;
      c[1][k + 1] = (-(gamma * c[1][k]) - c[0][k]) / next;
    }
    return c;
  }
};

// ---- the closed forms, in Arb at ball_bits() + 64 ----

slong truth_bits() { return ball_bits() + 64; }

ball w_of(const ball& gamma) {
  ball w = 1 - gamma * gamma / 4;
  arb_sqrt(w.get(), w.get(), truth_bits());
  return w;
}

/// (u(t), v(t)) of the closed form.
std::vector<ball> exact_state(const ball& gamma, const ball& t) {
  const slong bits = truth_bits();
  scoped_ball_bits precision(bits);
  const ball w = w_of(gamma);
  ball s, c, decay, wt = w * t, arg = -(gamma * t) / 2;
  arb_sin_cos(s.get(), c.get(), wt.get(), bits);
  arb_exp(decay.get(), arg.get(), bits);
  return {decay * s / w, decay * (c - gamma / (2 * w) * s)};
}

ball pi() {
  ball p;
  arb_const_pi(p.get(), truth_bits());
  return p;
}

/// The time where u falls through 0: pi / w.
ball exact_fall(const ball& gamma) {
  scoped_ball_bits precision(truth_bits());
  return pi() / w_of(gamma);
}

/// u_max = exp(-gamma t_m / 2), t_m = atan(2 w / gamma) / w (pi / 2 at gamma = 0).
ball exact_u_max(const ball& gamma) {
  if (gamma.nonpositive()) return ball(1);
  scoped_ball_bits precision(truth_bits());
  const ball w = w_of(gamma);
  ball tm = 2 * w / gamma, e;
  arb_atan(tm.get(), tm.get(), truth_bits());
  const ball arg = -(gamma * (tm / w)) / 2;
  arb_exp(e.get(), arg.get(), truth_bits());
  return e;
}

ball exact(const std::string& decimal) { return ball::from_decimal(decimal); }

/// The ball a state of the closed form at time t0, widened by 2^-(bits - 8): the
/// initial ball of a later step (the true state lies inside).
std::vector<ball> ball_state_at(const ball& gamma, const ball& t0) {
  std::vector<ball> x = exact_state(gamma, t0);
  for (auto& xi : x) xi = xi.widened(ball_2exp(-(ball_bits() - 8)));
  return x;
}

/// Counts the checks at t = 0, h/3, h/2, h where the step misses the closed form
/// through x0 = state at t0 (its polynomial with remainder, and its range).
int misses(const oscillator& system, const step_enclosure& step, const ball& t0) {
  int missed = 0;
  for (const ball& t : {ball(0), step.h / 3, step.h / 2, step.h}) {
    const std::vector<ball> truth = exact_state(system.gamma, t0 + t);
    for (std::size_t i = 0; i < 2; ++i) {
      if (!step.at(i, t).contains(truth[i])) ++missed;
      if (!step.range[i].contains(truth[i])) ++missed;
    }
  }
  return missed;
}

const std::vector<std::string> gammas{"0", "0.3"};

// The working precision of a 30-digit proof (128 bits).
constexpr int digits = 30;

// ---- validated_step ----

TEST(ValidatedStep, HoldsTheOscillatorAtLowAndHighOrders) {
  scoped_ball_bits bits(working_bits(digits));
  int validated = 0;
  for (const auto& gamma : gammas) {
    const oscillator system{exact(gamma)};
    for (std::size_t order : {1, 2, 4, 8, 20}) {
      for (const char* h : {"0.25", "1", "2"}) {
        for (const char* t0 : {"0", "1"}) {
          const std::vector<ball> x0 =
              std::string(t0) == "0" ? std::vector<ball>{ball(0), ball(1)} : ball_state_at(system.gamma, exact(t0));
          const step_enclosure step = validated_step(system, system.jet(x0, order), exact(h), order);
          const std::string at = "gamma " + gamma + " order " + std::to_string(order) + " h " + h + " t0 " + t0;
          if (std::string(h) != "2") EXPECT_TRUE(step.validated) << at;  // h = 2 at low order may need a shorter step
          if (!step.validated) continue;
          ++validated;
          EXPECT_EQ(misses(system, step, exact(t0)), 0) << at;
          // Not vacuous: u(h) to within 1 where order >= 2 and h <= 1 (|u| < 1).
          if (order >= 2 && std::string(h) != "2") EXPECT_LT(step.at(0, step.h).rad_double(), 1) << at;
        }
      }
    }
  }
  EXPECT_GE(validated, 40);
}

TEST(ValidatedStep, TightAtHighOrder) {
  // Order 40, h = 1/2: the truncation error is below 2^-200, so the enclosure of
  // u(h) is as narrow as the working precision.
  scoped_ball_bits bits(working_bits(digits));
  const oscillator system{exact("0.3")};
  const step_enclosure step = validated_step(system, system.jet({ball(0), ball(1)}, 40), exact("0.5"), 40);
  ASSERT_TRUE(step.validated);
  EXPECT_EQ(misses(system, step, ball(0)), 0);
  EXPECT_LT(step.at(0, step.h).rad_double(), std::ldexp(1.0, -static_cast<int>(ball_bits()) + 16));
}

// ---- the crossing search ----

/// The one step from t0 (the closed form's state there, as a ball) of size h at `order`.
step_enclosure step_from(const oscillator& system, const std::string& t0, const std::string& h, std::size_t order) {
  return validated_step(system, system.jet(ball_state_at(system.gamma, exact(t0)), order), exact(h), order);
}

const auto velocity = [](const std::vector<ball>& x) { return x[1]; };

TEST(Crossing, EnclosesTheFallAndTheRise) {
  scoped_ball_bits bits(working_bits(digits));
  for (const auto& gamma : gammas) {
    const oscillator system{exact(gamma)};
    // u falls through 0 at pi / w (3.14 and 3.18): inside the step from 3 of size 1/2
    // (order 40: the truncation error, below 2^-200, does not widen the crossing).
    const step_enclosure fall = step_from(system, "3", "0.5", 40);
    ASSERT_TRUE(fall.validated) << gamma;
    const auto t = enclose_crossing(fall, 0, 1);
    ASSERT_TRUE(t.has_value()) << gamma;
    EXPECT_TRUE(t->contains(exact_fall(system.gamma) - 3)) << gamma << ": " << t->str(40);
    EXPECT_LT(t->rad_double(), std::ldexp(1.0, -static_cast<int>(ball_bits()) + 16)) << gamma;
    // The state there holds the closed form's exit velocity -exp(-gamma pi / (2 w)).
    EXPECT_TRUE(fall.at(1, *t).contains(exact_state(system.gamma, exact_fall(system.gamma))[1])) << gamma;
    // No crossing in [0, 1/16] (u > 0 there): none claimed.
    EXPECT_FALSE(enclose_crossing_in(fall, 0, velocity, ball(0), exact("0.0625")).has_value()) << gamma;
  }
  // u rises through 0 at 2 pi (gamma = 0): inside the step from 6 of size 1/2.
  const oscillator system{ball(0)};
  const step_enclosure rise = step_from(system, "6", "0.5", 40);
  ASSERT_TRUE(rise.validated);
  const auto t = enclose_crossing(rise, 0, 1);
  ASSERT_TRUE(t.has_value());
  EXPECT_TRUE(t->contains(2 * pi() - 6)) << t->str(40);
  EXPECT_LT(t->rad_double(), std::ldexp(1.0, -static_cast<int>(ball_bits()) + 16));
}

/// In one step from 3 of size 7/2 (t in [3, 6.5]), u falls through 0 at pi and rises
/// through 0 at 2 pi. The search over the whole step either gives none (the slope is
/// not of one sign) or must hold the fall at pi: 0 when it does, 1 when it does not,
/// -1 if the step is not validated (the check then proves nothing).
int crossing_misses() {
  const oscillator system{ball(0)};
  const step_enclosure step = step_from(system, "3", "3.5", 40);
  if (!step.validated) return -1;
  const auto t = enclose_crossing_in(step, 0, velocity, ball(0), step.h);
  return t && !t->contains(pi() - 3) ? 1 : 0;
}

TEST(Crossing, NoneClaimedOverTwoZeros) {
  scoped_ball_bits bits(working_bits(digits));
  EXPECT_EQ(crossing_misses(), 0);
}

// ---- first_maximum ----

/// Feeds first_maximum the steps of size 1/2 at order 40 (truncation error below
/// 2^-200 per step) from (0, 1) until it has a
/// value (at most 8 steps); dv is v' over a ball of states.
template <class Derivative>
first_maximum turning_point(const oscillator& system, Derivative dv) {
  first_maximum turning;
  std::vector<ball> x{ball(0), ball(1)};
  for (int n = 0; n < 8 && !turning.value(); ++n) {
    const step_enclosure step = validated_step(system, system.jet(x, 40), exact("0.5"), 40);
    if (!step.validated) break;
    turning.add(step, 0, 1, dv);
    if (n == 0) EXPECT_FALSE(turning.value().has_value()) << "a maximum before the turn (t_m > 1/2)";
    x = step.state_at(step.h);
  }
  return turning;
}

TEST(FirstMaximum, NewtonEnclosesTheTurn) {
  scoped_ball_bits bits(working_bits(digits));
  for (const auto& gamma : gammas) {
    const oscillator system{exact(gamma)};
    const first_maximum turning =
        turning_point(system, [&](const std::vector<ball>& x) { return -(system.gamma * x[1]) - x[0]; });
    ASSERT_TRUE(turning.value().has_value()) << gamma;
    EXPECT_TRUE(turning.tight()) << gamma;
    EXPECT_TRUE(turning.value()->contains(exact_u_max(system.gamma))) << gamma << ": " << turning.value()->str(40);
    EXPECT_LT(turning.value()->rad_double(), std::ldexp(1.0, -static_cast<int>(ball_bits()) + 16)) << gamma;
  }
}

TEST(FirstMaximum, FallbackHullHoldsTheTurn) {
  // v' widened to hold 0: Newton cannot prove the zero of v unique, so the value is
  // the hull of u over the pieces from the first where v may vanish to the first
  // that ends with v < 0. It holds u_max, and is narrow: each piece's Horner
  // enclosure is about its width (h / 64 = 1/128) times a majorant of |u'| wide
  // (measured radius: 1.4e-3 at gamma = 0.3).
  scoped_ball_bits bits(working_bits(digits));
  for (const auto& gamma : gammas) {
    const oscillator system{exact(gamma)};
    const first_maximum turning = turning_point(
        system, [&](const std::vector<ball>& x) { return (-(system.gamma * x[1]) - x[0]).widened(ball(2)); });
    ASSERT_TRUE(turning.value().has_value()) << gamma;
    EXPECT_FALSE(turning.tight()) << gamma;
    EXPECT_TRUE(turning.value()->contains(exact_u_max(system.gamma))) << gamma << ": " << turning.value()->str(40);
    EXPECT_LT(turning.value()->rad_double(), 1e-2) << gamma;
  }
}

// ---- the mutations ----

/// Misses of the closed form over the low-order, long steps where the truncation
/// error (about h^(p+1) / (p+1)!, 1e-2 at order 4 and h = 1) is far above the
/// rounding (2^-128).
int low_order_misses() {
  int missed = 0;
  for (const auto& gamma : gammas) {
    const oscillator system{exact(gamma)};
    for (std::size_t order : {1, 2, 4, 8}) {
      for (const char* h : {"0.25", "1"}) {
        for (const char* t0 : {"0", "1"}) {
          const std::vector<ball> x0 =
              std::string(t0) == "0" ? std::vector<ball>{ball(0), ball(1)} : ball_state_at(system.gamma, exact(t0));
          const step_enclosure step = validated_step(system, system.jet(x0, order), exact(h), order);
          missed += step.validated ? misses(system, step, exact(t0)) : 0;
        }
      }
    }
  }
  return missed;
}

/// The same low-order, long steps with the linear prover's own system
/// (proven_linear.hpp: u, v and w' = 2 gamma v^2) at g = 0, where the energy identity
/// gives w = 1 - u^2 - v^2: misses of u, v, w in the polynomial and in the range.
int linear_law_misses() {
  int missed = 0;
  for (const auto& gamma : gammas) {
    const linear_contact_system system{exact(gamma), ball(0)};
    for (std::size_t order : {1, 2, 4, 8}) {
      for (const char* h : {"0.25", "1"}) {
        for (const char* t0 : {"0", "1"}) {
          std::vector<ball> x0{ball(0), ball(1), ball(0)};
          if (std::string(t0) != "0") {
            x0 = ball_state_at(system.gamma, exact(t0));
            x0.push_back(1 - x0[0] * x0[0] - x0[1] * x0[1]);
          }
          const step_enclosure step = validated_step(system, system.jet(x0, order), exact(h), order);
          if (!step.validated) continue;
          for (const ball& t : {ball(0), step.h / 3, step.h / 2, step.h}) {
            std::vector<ball> truth = exact_state(system.gamma, exact(t0) + t);
            if (system.gamma.nonpositive()) {
              truth.push_back(ball(0));  // no dissipation: w = 0 exactly
            } else {
              scoped_ball_bits precision(truth_bits());
              truth.push_back(1 - truth[0] * truth[0] - truth[1] * truth[1]);
            }
            for (std::size_t i = 0; i < 3; ++i) {
              if (!step.at(i, t).contains(truth[i])) ++missed;
              if (!step.range[i].contains(truth[i])) ++missed;
            }
          }
        }
      }
    }
  }
  return missed;
}

TEST(ProofMutation, UnmutatedStepsHoldTheClosedForms) {
  scoped_ball_bits bits(working_bits(digits));
  EXPECT_EQ(low_order_misses(), 0);
  EXPECT_EQ(linear_law_misses(), 0);
  EXPECT_EQ(crossing_misses(), 0);
}

// The low-order steps make 512 checks (2 gammas, orders 1, 2, 4, 8, steps 1/4 and 1,
// two starts, four times, u and v in the polynomial and in the range). Measured
// misses: none unmutated; 204 with the remainder scaled by 1e-3 or 1e-6; 192 with
// the remainder from the point; 6 with the box test skipped (at order 1, where the
// first box is too narrow: v's polynomial 1 is widened by its zero last term only,
// the box's remainder -1/2 is accepted and v(h) is enclosed as 1 - h^2/2 without
// the h^4/24 of cos h). With the linear prover's system (768 checks): 213 and 214,
// 204 and 6 (measured). Under the crossing mutation the search over the step with
// two zeros returns 2 pi - 3 = 3.2832 (the rise) as the fall.
TEST(ProofMutation, ScaledRemainderIsCaught) {
  scoped_ball_bits bits(working_bits(digits));
  for (double factor : {1e-3, 1e-6}) {
    mutation scaled(proof_mutation::remainder_scaled, factor);
    EXPECT_GE(low_order_misses(), 10) << "a remainder scaled by " << factor << " went unnoticed";
    EXPECT_GE(linear_law_misses(), 10) << "a remainder scaled by " << factor << " went unnoticed (linear law)";
  }
}

TEST(ProofMutation, RemainderFromThePointIsCaught) {
  scoped_ball_bits bits(working_bits(digits));
  mutation point(proof_mutation::remainder_from_point);
  EXPECT_GE(low_order_misses(), 10) << "a remainder from the initial state's jet went unnoticed";
  EXPECT_GE(linear_law_misses(), 10) << "a remainder from the initial state's jet went unnoticed (linear law)";
}

TEST(ProofMutation, SkippedBoxTestIsCaught) {
  scoped_ball_bits bits(working_bits(digits));
  mutation skipped(proof_mutation::box_test_skipped);
  EXPECT_GE(low_order_misses(), 4) << "an a priori box accepted without its inclusion test went unnoticed";
  EXPECT_GE(linear_law_misses(), 4) << "an a priori box accepted without its inclusion test went unnoticed (linear law)";
}

TEST(ProofMutation, CrossingWithoutSignProofIsCaught) {
  scoped_ball_bits bits(working_bits(digits));
  mutation unproven(proof_mutation::crossing_unproven);
  EXPECT_EQ(crossing_misses(), 1) << "a crossing accepted without its sign proofs went unnoticed";
}

// ---- the whole provers ----

TEST(ProofMutation, LinearProverWithCoarseStepsCatchesAThousandfoldRemainder) {
  // Steps aimed at 40 bits make the remainder, not the rounding, set the width of
  // each step. With the true remainder the enclosures are wide but hold; with the
  // remainder under-estimated 1000-fold the containment check sees exact values
  // outside (measured: 101 of the 103 rebounds).
  proof_options coarse;
  coarse.step_tolerance_bits = 40;
  const auto points = sample_points(200, 17);
  const auto honest = check_against_closed_form(points, 30, coarse);
  EXPECT_EQ(honest.outside, 0) << honest.first_problem;
  EXPECT_EQ(honest.outcome_mismatch, 0) << honest.first_problem;
  mutation scaled(proof_mutation::remainder_scaled, 1e-3);
  const auto cheated = check_against_closed_form(points, 30, coarse);
  EXPECT_GE(cheated.outside, 50) << "an under-estimated remainder went unnoticed";
}

/// The closed-form value as a ball that also holds 10^-(2 digits + 10) for its own rounding.
ball truth(const mpfr_real& x, int d) {
  return ball::from_decimal(to_decimal_string(x, 2 * d + 20)).widened(ball::from_decimal("1e-" + std::to_string(2 * d + 10)));
}

struct closed_case {
  std::string law, gamma, g;
};

/// Counts the cases whose exact e, 1 - e or T_f (where the closed form gives it)
/// lies outside the general prover's enclosure, or whose outcome differs.
int outside_count(const std::vector<closed_case>& cases, int d, const proof_options& options) {
  int outside = 0;
  for (const auto& c : cases) {
    const proven_impact proof = prove_impact(law_by_name(c.law), c.gamma, c.g, d, options);
    scoped_precision precision(2 * d + 20);
    const mpfr_real gamma(c.gamma), g(c.g);
    const auto exact = c.law == "linear" ? exact_linear(gamma, g)
                       : c.law == "tsuji" ? exact_tsuji(gamma)
                                          : exact_hunt_crossley(mpfr_real(3) / 2, gamma);
    scoped_ball_bits bits(working_bits(2 * d + 20));
    if ((proof.outcome == proven_outcome::rebound) != (exact.outcome == impact_outcome::rebound) ||
        proof.outcome == proven_outcome::undecided) {
      ++outside;
      continue;
    }
    if (proof.outcome == proven_outcome::stick) continue;
    const bool inside = proof.e.contains(truth(exact.e, d)) && proof.one_minus_e.contains(truth(exact.one_minus_e, d)) &&
                        (!exact.contact_time || proof.contact_time.contains(truth(*exact.contact_time, d)));
    if (!inside) ++outside;
  }
  return outside;
}

const std::vector<closed_case> closed_cases{
    {"tsuji", "0.01", "0"},        {"tsuji", "0.3", "0"},         {"tsuji", "1.7", "0"},
    {"hunt_crossley", "0.001", "0"}, {"hunt_crossley", "0.2", "0"}, {"hunt_crossley", "0.6", "0"},
    {"linear", "0.3", "0.2"},      {"linear", "0.1", "-0.5"},     {"linear", "0.05", "10"}};

TEST(ProofMutation, GeneralProverWithCoarseStepsCatchesAMillionfoldRemainder) {
  // As above, for the general prover: its box-based remainder is pessimistic (a
  // thousand-fold under-estimate still leaves valid enclosures here, measured); a
  // billion-fold one must be caught, and a million-fold one too (measured: 7 and 5
  // of the 9 cases).
  proof_options coarse;
  coarse.step_tolerance_bits = 40;
  EXPECT_EQ(outside_count(closed_cases, 30, coarse), 0);
  int caught = 0, caught_million = 0;
  {
    mutation scaled(proof_mutation::remainder_scaled, 1e-9);
    caught = outside_count(closed_cases, 30, coarse);
  }
  {
    mutation scaled(proof_mutation::remainder_scaled, 1e-6);
    caught_million = outside_count(closed_cases, 30, coarse);
  }
  EXPECT_GE(caught, 4) << "an under-estimated remainder went unnoticed";
  EXPECT_GE(caught_million, 3) << "a million-fold under-estimated remainder went unnoticed";
}

TEST(ProofMutation, CoarseProversCatchARemainderFromThePoint) {
  // The remainder from the initial state's jet (the next Taylor term only) in 40-bit
  // steps: measured 34 of 60 linear-law points and 8 of the 9 closed forms outside.
  proof_options coarse;
  coarse.step_tolerance_bits = 40;
  mutation point(proof_mutation::remainder_from_point);
  EXPECT_GE(check_against_closed_form(sample_points(60, 17), 30, coarse).outside, 15);
  EXPECT_GE(outside_count(closed_cases, 30, coarse), 4);
}

}  // namespace

// A proven impact for the linear law (alpha = beta = 1):
//     u'' + gamma u' + u = g,  u(0) = 0, u'(0) = 1,
// whose right-hand side is analytic, so the whole impact is one validated Taylor
// integration (the Hertz-type laws need s = u^(1/Q) at both ends; they come next).
// State (u, v = u', w): w' = 2 gamma v^2 accumulates the dissipated energy, so that
// 1 - e^2 = w(T_f) (energy identity: E = v^2/2 + u^2/2 - g u has E' = -gamma v^2,
// E(0) = 1/2 and E(T_f) = e^2/2) and 1 - e = w / (1 + e) keeps its relative width
// as gamma -> 0.
//
// How the outcome is proven:
// - rebound: a step whose u falls from a proven positive to a proven negative value
//   with v proven negative over the whole step; the crossing time is enclosed by
//   interval Newton (crossing.hpp) and e = -v(T_f).
// - stick, g > 0: E proven negative at some time. E never increases and E >= 0 at
//   u = 0, so the bead never reaches u = 0 again (E(0) = 1/2: checked after every step).
// - stick, g = 0 and gamma >= 2: u > 0 and v >= c u proven with c = -gamma/2. On the
//   line v = c u, d/dt (v - c u) = -u (c^2 + gamma c + 1) = -u (1 - gamma^2/4) >= 0,
//   so the sector {u > 0, v >= c u} is never left, and there u' >= c u keeps
//   u(t) >= u(t0) exp(c (t - t0)) > 0. (The sector holds from the first step on, as
//   v > 0 >= c u there: at g = 0 every gamma >= 2 sticks, as the closed form says.)
// - g < 0, or g = 0 with gamma < 2: the bead always comes back; only rebound can
//   be proven.
// u_max: the first zero of v, enclosed by interval Newton on its step (crossing.hpp).
// Anything else within the step budget, or a step that cannot be validated down to
// a tiny size (the bead grazing u = 0 at the sticking threshold), is undecided.
#pragma once

#include <viscor/enclose/crossing.hpp>
#include <viscor/enclose/proven_result.hpp>
#include <viscor/enclose/validated_taylor.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace viscor::proofs {

/// u' = v, v' = g - gamma v - u, w' = 2 gamma v^2, in balls.
struct linear_contact_system {
  ball gamma, g;

  /// Three components: u, v, w.
  std::size_t size() const { return 3; }

  /// The Taylor coefficients 0..order of (u, v, w) through the ball state x.
  ball_jet jet(const std::vector<ball>& x, std::size_t order) const {
    ball_jet c(3, std::vector<ball>(order + 1));
    for (std::size_t i = 0; i < 3; ++i) c[i][0] = x[i];
    const ball two_gamma = 2 * gamma;
    for (std::size_t k = 0; k < order; ++k) {
      const ball next = ball(static_cast<long>(k + 1));
      c[0][k + 1] = c[1][k] / next;
      ball force = -(gamma * c[1][k]) - c[0][k];
      if (k == 0) force += g;
      c[1][k + 1] = force / next;
      ball square;  // (v^2)_k = sum_j v_j v_{k-j}
      for (std::size_t j = 0; j <= k; ++j) square += c[1][j] * c[1][k - j];
      c[2][k + 1] = two_gamma * square / next;
    }
    return c;
  }
};

/// Proves the impact of the linear law at (gamma, g), given as exact decimals, with
/// balls of working_bits(digits) bits. Throws invalid_parameter for a gamma < 0 or a
/// text that is not a finite decimal.
inline proven_impact prove_linear_impact(std::string_view gamma_text, std::string_view g_text, int digits,
                                         const proof_options& options = {}) {
  if (digits < 5 || digits > 100000) throw invalid_parameter("digits must be in [5, 100000], got " + std::to_string(digits));
  scoped_ball_bits bits(working_bits(digits));
  linear_contact_system system{ball::from_decimal(gamma_text, "gamma"), ball::from_decimal(g_text, "g")};
  if (system.gamma.negative() || !system.gamma.nonnegative())
    throw invalid_parameter("gamma must be >= 0, got " + std::string(gamma_text));
  const ball& gamma = system.gamma;
  const ball& g = system.g;
  const bool g_is_zero = g.nonnegative() && g.nonpositive();
  const ball sector_slope = -(gamma / 2);  // c of the g = 0 trapping sector
  const bool sector_exists = g_is_zero && (1 - gamma * gamma / 4).nonpositive();

  const double log2_tolerance =
      -static_cast<double>(options.step_tolerance_bits > 0 ? options.step_tolerance_bits : ball_bits());
  const auto order = static_cast<std::size_t>(std::ceil(-log2_tolerance * std::log(2.0) / 2 + 1));  // Jorba-Zou

  proven_impact result;
  std::vector<ball> x{ball(0), ball(1), ball(0)};
  ball t(0);
  first_maximum turning;  // u_max at the first zero of v (crossing.hpp)
  const auto acceleration = [&](const std::vector<ball>& state) { return g - gamma * state[1] - state[0]; };
  for (std::size_t n = 0; n < options.max_steps; ++n) {
    result.steps = n + 1;
    const ball_jet jet = system.jet(x, order);
    double h_try = proposed_step(jet, order, log2_tolerance);
    step_enclosure step;
    int halvings = 0;
    for (;; ++halvings) {
      if (halvings > options.max_halvings) {
        result.how = "no validated step at t = " + t.mid_str(10) + " (the bead grazes u = 0?)";
        return result;
      }
      ball h;
      arb_set_d(h.get(), h_try);  // exact: a double is a dyadic number
      step = validated_step(system, jet, h, order);
      h_try /= 2;
      if (!step.validated || !step.tight(log2_tolerance)) continue;
      const ball& u_range = step.range[0];
      const ball& v_range = step.range[1];
      if (u_range.positive() || (n == 0 && v_range.positive())) break;  // still in contact over the whole step
      if (!v_range.negative()) continue;  // u may touch 0 while turning: shorten the step
      const ball u_end = step.at(0, step.h);
      if (u_end.positive()) break;  // falling but still positive at the end: in contact throughout
      if (!u_end.negative()) continue;
      const auto crossing = enclose_crossing(step, 0, 1);
      if (!crossing) continue;
      const std::vector<ball> at_exit = step.state_at(*crossing);
      result.outcome = impact_outcome::rebound;
      result.e = -at_exit[1];
      result.one_minus_e = at_exit[2] / (1 + result.e);
      result.contact_time = t + *crossing;
      turning.add(step, 0, 1, acceleration);  // v's last zero may be on this step's start
      result.max_compression = turning.value();
      result.how = "u crosses 0 with v < 0 (interval Newton on the validated step)";
      if (!result.e.positive()) result.outcome = impact_outcome::undecided, result.how = "e not proven > 0";
      return result;
    }
    turning.add(step, 0, 1, acceleration);
    result.max_compression = turning.value();
    x = step.state_at(step.h);
    t = t + step.h;
    const ball energy = x[1] * x[1] / 2 + x[0] * x[0] / 2 - g * x[0];
    if (energy.negative()) {
      result.outcome = impact_outcome::stick;
      result.e = ball(0), result.one_minus_e = ball(1);
      result.how = "energy v^2/2 + u^2/2 - g u proven negative at t = " + t.mid_str(10);
      return result;
    }
    if (sector_exists && x[0].positive() && (x[1] - sector_slope * x[0]).nonnegative()) {
      result.outcome = impact_outcome::stick;
      result.e = ball(0), result.one_minus_e = ball(1);
      result.how = "trapped in the sector v >= -(gamma/2) u, u > 0 at t = " + t.mid_str(10);
      return result;
    }
  }
  result.how = "step budget exhausted";
  return result;
}

}  // namespace viscor::proofs

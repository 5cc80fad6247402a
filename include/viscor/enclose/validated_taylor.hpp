// One validated Taylor step in ball arithmetic: the Taylor coefficients of the
// solution through a ball of initial states, an a priori enclosure of the solution
// over the whole step, and a rigorous remainder, so that x(t) is enclosed for every
// t in [0, h] and every initial state in the ball.
//
// The a priori enclosure is the high-order enclosure (HOE) test of Nedialkov,
// Jackson and Pryce (Reliable Computing 7, 2001): with x_0..x_p the coefficients
// from the initial ball X0 and x_{p+1}(B) the order-(p+1) coefficient computed from
// a candidate box B,
//     X0 + sum_{k=1..p} x_k [0,h]^k + x_{p+1}(B) [0,h]^(p+1)  contained in int(B)
// proves that the solution exists on [0, h] and stays in B. Then for t in [0, h]
// the Lagrange form x(t) = sum_{k<=p} x_k t^k + x_{p+1}(x(xi)) t^(p+1), xi in
// [0, t], holds component by component, and x_{p+1}(x(xi)) lies in x_{p+1}(B):
// the remainder ball R = x_{p+1}(B) is valid at every t of the step.
//
// The wrapping effect: the coefficients are computed from the ball X0 as a whole,
// so the enclosure widens by about the norm of the flow's Jacobian per step (the
// impact is short: a few units of scaled time); working_bits() adds guard bits
// that absorb it (measured in docs/proofs.md).
#pragma once

#include <viscor/enclose/ball.hpp>
#include <viscor/enclose/mutation_seam.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <optional>
#include <vector>

namespace viscor::proofs {

/// Taylor coefficients [component][order] in balls.
using ball_jet = std::vector<std::vector<ball>>;

/// A system of autonomous ODEs whose Taylor coefficients can be computed in
/// balls: jet(x, order) returns the coefficients 0..order of every component
/// of the solution through the (ball) state x.
template <class S>
concept ball_system = requires(const S& s, const std::vector<ball>& x, std::size_t order) {
  { s.size() } -> std::convertible_to<std::size_t>;
  { s.jet(x, order) } -> std::same_as<ball_jet>;
};

/// x(t) of one component, sum_{k<=p} c_k t^k + R t^(p+1), for t a ball inside [0, h].
inline ball evaluate_with_remainder(const std::vector<ball>& c, const ball& remainder, const ball& t) {
  ball s = remainder;  // Horner with the remainder as the leading coefficient
  for (std::size_t k = c.size(); k-- > 0;) s = s * t + c[k];
  return s;
}

/// A validated step: everything needed to evaluate the solution anywhere in [0, h].
struct step_enclosure {
  bool validated = false;        ///< false: the enclosure test failed for this h (take a smaller one)
  ball h;                        ///< the step (an exact number)
  ball_jet coefficients;         ///< orders 0..p at the step's start, from the initial ball
  std::vector<ball> remainder;   ///< order p+1 over the step's enclosure, per component
  std::vector<ball> range;       ///< encloses x(t) for all t in [0, h]

  /// How far (in bits) the remainder's contribution R h^(p+1) exceeds
  /// 2^log2_tolerance (1 + |x_i|) in the worst component; <= 0: the step is tight,
  /// i.e. it keeps the enclosure as narrow as the working precision (a validated
  /// step can be valid and still far too wide).
  double excess_bits(double log2_tolerance) const {
    double worst = -1e300;
    for (std::size_t i = 0; i < remainder.size(); ++i) {
      const double added = static_cast<double>(remainder[i].abs_upper().log2_bound()) +
                           static_cast<double>(coefficients[i].size()) * std::log2(h.mid_double());
      const double scale = std::max(0.0, static_cast<double>(coefficients[i][0].log2_bound()));
      worst = std::max(worst, added - (log2_tolerance + scale));
    }
    return worst;
  }
  /// Whether excess_bits(log2_tolerance) <= 0.
  bool tight(double log2_tolerance) const { return excess_bits(log2_tolerance) <= 0; }
  /// Encloses component i at time t (a ball inside [0, h]).
  ball at(std::size_t i, const ball& t) const { return evaluate_with_remainder(coefficients[i], remainder[i], t); }
  /// Encloses the state at time t (a ball inside [0, h]).
  std::vector<ball> state_at(const ball& t) const {
    std::vector<ball> x;
    for (std::size_t i = 0; i < coefficients.size(); ++i) x.push_back(at(i, t));
    return x;
  }
};

/// Bits of the balls in which the a priori enclosure's jet is computed. The box
/// holds the whole path over the step (its relative width is at least 2^-(bits/2),
/// usually 0.01-1), so its order-(p+1) coefficient is a wide ball, and rounding to
/// 64-bit midpoints (2^-64 relative) is far below that width: the working precision
/// buys nothing there but costs (Arb's products grow with the limbs, and a ball of
/// more than two limbs allocates; one limb is the fastest case). Rigorous at any
/// precision, as every ball operation is.
inline constexpr slong box_jet_bits = 64;

/// system.jet(box, order) in balls of box_jet_bits: the box rounded (outwards) to
/// that precision, and every operation of the jet at it.
template <ball_system S>
ball_jet jet_on_box(const S& system, const std::vector<ball>& box, std::size_t order) {
  const slong bits = std::min(box_jet_bits, ball_bits());
  scoped_ball_bits low(bits);
  std::vector<ball> rounded(box.size());
  for (std::size_t i = 0; i < box.size(); ++i) arb_set_round(rounded[i].get(), box[i].get(), bits);
  return system.jet(rounded, order);
}

/// The exact ball 2^e.
inline ball ball_2exp(long e) {
  ball b(1);
  arb_mul_2exp_si(b.get(), b.get(), e);
  return b;
}

/// The interval [0, h] as a ball.
inline ball zero_to(const ball& h) { return ball::hull(ball(0), h); }

/// Tries one validated step of size h (exact) from the ball x0 at Taylor order p,
/// given the coefficients of the solution through x0 (system.jet(x0, order)).
template <ball_system S>
step_enclosure validated_step(const S& system, const ball_jet& coefficients, const ball& h, std::size_t order) {
  step_enclosure step;
  step.h = h;
  step.coefficients = coefficients;
  const std::size_t n = system.size();
  const ball interval = zero_to(h);
  const ball half_precision = ball_2exp(-ball_bits() / 2);
  // The polynomial part over [0, h] and a first candidate box around it.
  std::vector<ball> polynomial(n), box(n);
  for (std::size_t i = 0; i < n; ++i) {
    polynomial[i] = evaluate_with_remainder(step.coefficients[i], ball(0), interval);
    const ball last = step.coefficients[i][order] * pow(h, order);
    // The box's width feeds the remainder's width (times about (|J| h)^(p+1) / (p+1)!),
    // so it starts tight: the last term's size, half the working digits relative, an
    // absolute 2^-64 that keeps it open around exact components (a point has no
    // interior), and 2^-20 of the polynomial's own radius. NOTE: without that last
    // part the first box never passed: Arb's radius has 30 bits, so a widening below
    // 2^-30 of it is lost to the same upward rounding the candidate's radius gets, the
    // candidate is not in the box's interior, and the retry doubled the box (a twice
    // wider box, a larger remainder, shorter steps, and a second jet on the box).
    box[i] = polynomial[i].widened(4 * last.abs_upper() + polynomial[i].abs_upper() * half_precision +
                                   polynomial[i].rad() * ball_2exp(-20) + ball_2exp(-64));
  }
  const ball tail_power = pow(interval, order + 1);
  for (int attempt = 0; attempt < 8; ++attempt) {
    const ball_jet on_box = jet_on_box(system, box, order + 1);
    std::vector<ball> candidate(n), remainder(n);
    bool inside = true;
    for (std::size_t i = 0; i < n; ++i) {
      remainder[i] = on_box[i][order + 1];
      candidate[i] = polynomial[i] + remainder[i] * tail_power;
      inside = inside && (proof_mutated(proof_mutation::box_test_skipped) || box[i].contains_interior(candidate[i]));
    }
    if (inside) {
      // Test seam (mutation_seam.hpp): dead code unless VISCOR_PROOF_MUTATIONS.
      if (proof_mutated(proof_mutation::remainder_scaled)) {
        ball factor;
        arb_set_d(factor.get(), proof_mutation_factor());
        for (std::size_t i = 0; i < n; ++i) {
          remainder[i] = remainder[i] * factor;
          candidate[i] = polynomial[i] + remainder[i] * tail_power;
        }
      }
      if (proof_mutated(proof_mutation::remainder_from_point)) {
        std::vector<ball> start(n);
        for (std::size_t i = 0; i < n; ++i) start[i] = step.coefficients[i][0];
        const ball_jet on_start = system.jet(start, order + 1);
        for (std::size_t i = 0; i < n; ++i) {
          remainder[i] = on_start[i][order + 1];
          candidate[i] = polynomial[i] + remainder[i] * tail_power;
        }
      }
      step.remainder = std::move(remainder);
      step.range = std::move(candidate);
      step.validated = true;
      return step;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const ball merged = ball::hull(box[i], candidate[i]);
      box[i] = merged.widened(merged.rad() + merged.abs_upper() * ball::from_decimal("1e-10"));
    }
  }
  return step;  // not validated
}

/// The next size to try after `step` failed: from the remainder's excess when it
/// was validated (the contribution scales as h^(p+1)), else half.
inline double retry_size(const step_enclosure& step, double log2_tolerance, std::size_t order) {
  const double h = step.h.mid_double();
  if (!step.validated) return h / 2;
  const double excess = step.excess_bits(log2_tolerance);
  return h * std::clamp(std::exp2(-(excess + 1) / static_cast<double>(order + 1)), 0.1, 0.97);
}

/// A step size for which the last retained coefficients are below 2^log2_tolerance
/// relative to the state (Jorba-Zou): min_i over k = p-1, p of
/// (2^log2_tolerance (1 + |x_i|) / |c_{i,k}|)^(1/k), computed from binary exponents.
/// A heuristic only: the validated step decides.
inline double proposed_step(const ball_jet& c, std::size_t order, double log2_tolerance, double largest = 4) {
  double log2_h = std::log2(largest);
  for (const auto& ci : c) {
    const double log2_scale = std::max(0.0, static_cast<double>(ci[0].log2_bound()));
    for (std::size_t k : {order - 1, order}) {
      const long log2_c = ci[k].log2_bound();
      if (log2_c < -900000) continue;  // zero coefficient: no limit
      log2_h = std::min(log2_h, (log2_tolerance + log2_scale - static_cast<double>(log2_c)) / static_cast<double>(k));
    }
  }
  return std::exp2(log2_h);
}

/// What find_step carries from one step to the next of an integration.
struct step_memory {
  double last_size = 0;  ///< the last accepted size (0: none yet)
  /// By how many bits the remainder at the Jorba-Zou proposal exceeded the tolerance
  /// at the last validated try (extrapolated from the size tried: the contribution
  /// scales as h^(p+1)). The box-based remainder over-estimates the truncation error
  /// by about 20 bits, so the proposal alone failed the tightness test at almost
  /// every step (a wasted jet on the box per step); the next proposal is shortened by
  /// this much plus 4 bits (measured: with 2 the enclosures came out slightly wider
  /// than the retries' steps gave; with 4 slightly tighter, and 3/4 of the steps pass
  /// at their first try).
  double overshoot_bits = 0;
};

/// A step from the state whose coefficients are `jet`: the first of the sizes
/// tried (the proposal shortened by memory.overshoot_bits and at most 1.25 x the last
/// accepted size, then retry_size) that is validated, tight and accepted by
/// `accept(step)`; nullopt after `attempts` tries. `memory` is updated.
template <ball_system S, class Accept>
std::optional<step_enclosure> find_step(const S& system, const ball_jet& jet, std::size_t order,
                                        double log2_tolerance, step_memory& memory, int attempts, Accept accept) {
  const double p1 = static_cast<double>(order + 1);
  const double proposal = proposed_step(jet, order, log2_tolerance);
  double h = proposal * std::exp2(-(memory.overshoot_bits + 4) / p1);
  if (memory.last_size > 0) h = std::min(h, 1.25 * memory.last_size);
  for (int attempt = 0; attempt < attempts; ++attempt) {
    ball size;
    arb_set_d(size.get(), h);  // exact: a double is a dyadic number
    step_enclosure step = validated_step(system, jet, size, order);
    if (step.validated)
      memory.overshoot_bits = std::max(0.0, step.excess_bits(log2_tolerance) + p1 * std::log2(proposal / h));
    if (step.validated && step.tight(log2_tolerance) && accept(step)) {
      memory.last_size = h;
      return step;
    }
    h = step.validated && !step.tight(log2_tolerance) ? retry_size(step, log2_tolerance, order) : h / 2;
  }
  return std::nullopt;
}

}  // namespace viscor::proofs

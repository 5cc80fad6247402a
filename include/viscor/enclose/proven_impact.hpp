// A proven impact for any law with rational exponents alpha = a/q_a, beta = b/q_b
// (docs/proofs.md). With Q = lcm(q_a, q_b) and u = s^Q both ends of the contact,
// u = 0, are regular points of the equations written in s, so the proof has three
// phases (core/impact_phase.hpp; no creep phase), each a validated Taylor integration
// (validated_taylor.hpp), in detail::impact_proof:
//
//   compress  s from 0 (exactly) while v stays >= 1/4:      states (s, v, tau, D)
//   turn      tau through the maximal compression:           states (u, v, D)
//   exit      s down to 0 (exactly) once one s-step reaches:  states (s, v, tau, D)
//             (back to the turn if the s-steps crawl: a turn back at small u > 0)
//
// In s (J = du/ds = Q s^(Q-1); every power of s below is a polynomial):
//   dv/ds   = (g J - Q s^(Q(alpha+1)-1)) / v - gamma beta Q s^(Q beta-1),
//   dtau/ds = J / v,   dD/ds = 2 gamma beta Q s^(Q beta-1) v;
// in tau: u' = v, v' = g - u^alpha - gamma beta u^(beta-1) v,
//   D' = 2 gamma beta u^(beta-1) v^2.
// D is the dissipated energy (core/contact_state.hpp): E = v^2/2 + u^(alpha+1)/(alpha+1) - g u has
// E' = -gamma beta u^(beta-1) v^2, E(0) = 1/2, E(T_f) = e^2/2, so 1 - e^2 = D(T_f)
// and 1 - e = D / (1 + e) keeps its relative width as gamma -> 0.
//
// The switch points are exact where the proof needs it: the first switch is at the
// end of an s-step (an exact s); the second needs no exact point, as s = u^(1/Q) is
// carried as a ball; the end of contact is s = 0 exactly, reached at sigma = s0 of
// the last step, since s is linear in the step variable sigma: no root finding.
//
// Switch points (measured on Kuwabara-Kono, gamma = 0.05, g = 1): compress in s while
// v >= 3/4, turn in tau until an s-step reaches a tenth of the way to s = 0; near
// either singular point the series of the other variable converge slowly.
//
// u_max: v falls through 0 in the turn phase; the first step in which it may
// vanish encloses the turning point by interval Newton (crossing.hpp,
// first_maximum), and u_max = u there.
//
// Outcomes (core/outcome.hpp): rebound (v proven negative over every step of the exit, so the
// first return to u = 0 is the end of the last step); stick when E is proven
// negative after a step in tau or in s (E never increases and E >= 0 at u = 0, so
// the bead never gets back), or at g = 0 when the state enters a trap that keeps
// u > 0 for ever (detail::creeps_to_origin: laws with alpha + 1 >= 2 beta);
// undecided otherwise (a step that cannot be validated, the bead grazing u = 0, a
// creep at g = 0 that no argument here traps, or the step budget spent).
// proven_linear.hpp proves the linear law by a separate, simpler integration in
// tau alone; the tests compare both with the closed form.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/contact_state.hpp>
#include <viscor/core/impact_phase.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/enclose/ball_series.hpp>
#include <viscor/enclose/crossing.hpp>
#include <viscor/enclose/proven_result.hpp>
#include <viscor/enclose/validated_taylor.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

namespace viscor::proofs {

/// The constants of one proof, as balls (exact where the inputs are dyadic).
struct impact_ball_constants {
  ball alpha, beta, gamma, g, gamma_beta;
  long Q = 1, Q_alpha = 1, Q_beta = 1;  ///< u = s^Q; Q alpha, Q beta integers
  bool beta_is_one = false;
  /// m when alpha = m + (beta - 1) with m = 0 or 1 (Hunt-Crossley: 0, Kuwabara-Kono: 1):
  /// u^alpha = u^m u^(beta - 1) exactly, one power series where there were two; -1 otherwise.
  long spring_shift = -1;
};

/// The equations in s, stepping in sigma with s = s0 + direction sigma.
/// States: (s, v, tau, D), D the dissipated energy of core/contact_state.hpp.
struct s_system {
  enum : std::size_t { s = 0, v = 1, tau = 2, D = 3 };  ///< the components of a state
  const impact_ball_constants* k;
  int direction = 1;  ///< +1: s grows (the compress phase); -1: s falls (the exit)

  /// Four components: s, v, tau, D.
  std::size_t size() const { return 4; }

  /// Taylor coefficients 0..order in sigma through the ball state x.
  ///
  /// g J - (spring), J and the damping term are polynomials in sigma (of degree
  /// Q(alpha + 1) - 1, Q - 1 and Q beta - 1), so the only full-length convolution per
  /// order is the series of 1/v; (g J - spring)/v, J/v and damping v are short
  /// products of a polynomial with a series (series::polynomial_product). NOTE: the
  /// numerator g J - spring is formed before it meets 1/v: g J and the spring nearly
  /// cancel near the switch to tau, and (g J) (1/v) - (spring) (1/v) would carry the
  /// radius of 1/v twice (measured: 5x wider enclosures of e, and more steps).
  ball_jet jet(const std::vector<ball>& x, std::size_t order) const {
    // Exponents of s: u^alpha J = Q s^(Q alpha + Q - 1), u^(beta-1) J = Q s^(Q beta - 1), J = Q s^(Q-1).
    const long Q = k->Q, m_spring = k->Q_alpha + Q - 1, m_damping = k->Q_beta - 1, m_jacobian = Q - 1;
    std::vector<ball> powers(static_cast<std::size_t>(std::max({m_spring, m_damping, m_jacobian})) + 1);
    powers[0] = ball(1);
    for (std::size_t j = 1; j < powers.size(); ++j) powers[j] = powers[j - 1] * x[0];
    const ball q(Q);
    // factor (s0 + direction sigma)^m, coefficients 0..m.
    auto polynomial = [&](long m, const ball& factor) {
      std::vector<ball> p(static_cast<std::size_t>(m) + 1);
      for (std::size_t j = 0; j < p.size(); ++j) p[j] = factor * series::monomial(powers, m, direction, j);
      return p;
    };
    const std::vector<ball> jacobian = polynomial(m_jacobian, q), damping = polynomial(m_damping, k->gamma_beta * q);
    std::vector<ball> force = polynomial(m_spring, -q);  // g J - Q s^(Q alpha + Q - 1)
    if (force.size() < jacobian.size()) force.resize(jacobian.size());
    for (std::size_t j = 0; j < jacobian.size(); ++j) force[j] += k->g * jacobian[j];
    ball_jet c(4, std::vector<ball>(order + 1));
    for (std::size_t i = 0; i < 4; ++i) c[i][0] = x[i];
    std::vector<ball> reciprocal(order);  // 1/v
    const ball sign(static_cast<long>(direction));
    const slong prec = ball_bits();
    for (std::size_t n = 0; n < order; ++n) {
      reciprocal[n] = series::quotient(ball(n == 0 ? 1 : 0), reciprocal, c[1], n);
      ball dv = series::polynomial_product(force, reciprocal, n);
      if (n < damping.size()) dv -= damping[n];
      const ball dtau = series::polynomial_product(jacobian, reciprocal, n);
      const ball dD = 2 * series::polynomial_product(damping, c[1], n);
      const slong next = static_cast<slong>(direction) * static_cast<slong>(n + 1);  // d/dsigma = direction d/ds
      c[0][n + 1] = n == 0 ? sign : ball(0);
      arb_div_si(c[1][n + 1].get(), dv.get(), next, prec);
      arb_div_si(c[2][n + 1].get(), dtau.get(), next, prec);
      arb_div_si(c[3][n + 1].get(), dD.get(), next, prec);
    }
    return c;
  }
};

/// The equations in tau. States: (u, v, D); needs u > 0.
struct tau_system {
  enum : std::size_t { u = 0, v = 1, D = 2 };  ///< the components of a state
  const impact_ball_constants* k;

  /// Three components: u, v, D.
  std::size_t size() const { return 3; }

  /// Taylor coefficients 0..order in tau through the ball state x.
  ball_jet jet(const std::vector<ball>& x, std::size_t order) const {
    ball_jet c(3, std::vector<ball>(order + 1));
    for (std::size_t i = 0; i < 3; ++i) c[i][0] = x[i];
    std::vector<ball> spring(order), damping_power(order), damped_v(order), scratch;
    const ball two_gamma_beta = 2 * k->gamma_beta;
    const slong prec = ball_bits();
    for (std::size_t n = 0; n < order; ++n) {
      // u^(beta-1) and u^alpha with the exponents (Q beta - Q)/Q and Q alpha/Q.
      damping_power[n] =
          k->beta_is_one ? ball(n == 0 ? 1 : 0) : series::power(c[0], damping_power, k->Q_beta - k->Q, k->Q, n, scratch);
      if (k->spring_shift == 0)
        spring[n] = damping_power[n];
      else if (k->spring_shift == 1)
        spring[n] = series::product(damping_power, c[0], n);  // u^alpha = u u^(beta - 1)
      else
        spring[n] = series::power(c[0], spring, k->Q_alpha, k->Q, n, scratch);
      damped_v[n] = series::product(damping_power, c[1], n);  // u^(beta-1) v
      ball dv = -spring[n] - k->gamma_beta * damped_v[n];
      if (n == 0) dv += k->g;
      const slong next = static_cast<slong>(n + 1);
      arb_div_si(c[0][n + 1].get(), c[1][n].get(), next, prec);
      arb_div_si(c[1][n + 1].get(), dv.get(), next, prec);
      const ball dD = two_gamma_beta * series::product(damped_v, c[1], n);
      arb_div_si(c[2][n + 1].get(), dD.get(), next, prec);
    }
    return c;
  }
};

namespace detail {

/// Energy E = v^2/2 + u^(alpha+1)/(alpha+1) - g u.
inline ball energy(const impact_ball_constants& k, const ball& u, const ball& v) {
  ball spring;
  const ball a1 = k.alpha + 1;
  arb_pow(spring.get(), u.get(), a1.get(), proofs::ball_bits());
  return v * v / 2 + spring / a1 - k.g * u;
}

/// Whether E is proven negative at (u, v): E never increases and E >= 0 at u = 0, so
/// the bead never gets back (the solvers' energy_proven_negative, written apart).
inline bool energy_proven_negative(const impact_ball_constants& k, const ball& u, const ball& v) {
  return energy(k, u, v).negative();
}

/// v' = g - u^alpha - gamma beta u^(beta-1) v over a ball state (u, v, ...), u > 0.
inline ball acceleration(const impact_ball_constants& k, const std::vector<ball>& x) {
  ball spring, damping(1);
  arb_pow(spring.get(), x[0].get(), k.alpha.get(), proofs::ball_bits());
  if (!k.beta_is_one) {
    const ball beta_minus_one = k.beta - 1;
    arb_pow(damping.get(), x[0].get(), beta_minus_one.get(), proofs::ball_bits());
  }
  return k.g - spring - k.gamma_beta * damping * x[1];
}

/// At g = 0 with kappa = alpha + 1 - 2 beta >= 0 (the linear law, Hertz with linear
/// damping, Tsuji), whether the state (u, v) lies in the trap
///   T = { u > 0, -c u^beta < v < 0, beta gamma^2 / 4 > u^kappa },  c = gamma / 2,
/// which the bead never leaves and in which it never reaches u = 0: a stick. Why: on
/// the face v = -c u^beta, d/dtau (v + c u^beta) = u^(2 beta - 1) (beta gamma^2/4 -
/// u^kappa) > 0, so the flow enters T there; on v = 0, v' = -u^alpha < 0; u falls
/// (v < 0), so the last condition is kept; and u' = v > -c u^beta keeps u > 0 for
/// ever (u >= u0 exp(-c tau) for beta = 1, algebraic decay for beta > 1). At kappa = 0
/// the last condition is gamma > 2/sqrt(beta), the critical damping of the linear
/// law and of Tsuji's exact solution at g = 0. `trap_applies` is false otherwise.
/// Deliberately the same barrier argument as the solvers' creeps_to_origin, written apart.
inline bool creeps_to_origin(const impact_ball_constants& k, bool trap_applies, const ball& u, const ball& v) {
  if (!trap_applies || !u.positive() || !v.negative()) return false;
  const ball kappa = k.alpha + 1 - 2 * k.beta;
  ball u_beta, u_kappa;
  arb_pow(u_beta.get(), u.get(), k.beta.get(), proofs::ball_bits());
  arb_pow(u_kappa.get(), u.get(), kappa.get(), proofs::ball_bits());
  return (v + k.gamma / 2 * u_beta).positive() && (k.beta * k.gamma * k.gamma / 4 - u_kappa).positive();
}

inline ball root(const ball& u, long Q) {
  ball s;
  arb_root_ui(s.get(), u.get(), static_cast<ulong>(Q), proofs::ball_bits());
  return s;
}

inline ball upper_bound(const ball& x) {
  arf_t u;
  arf_init(u);
  arb_get_ubound_arf(u, x.get(), proofs::ball_bits());
  ball b;
  arb_set_arf(b.get(), u);
  arf_clear(u);
  return b;
}

/// Jorba-Zou order for the working bits.
inline std::size_t proof_order(double log2_tolerance) {
  return static_cast<std::size_t>(std::ceil(-log2_tolerance * std::log(2.0) / 2 + 1));
}

/// The constants of a proof of (law, gamma, g), gamma and g exact decimals; throws
/// invalid_parameter as prove_impact documents.
inline impact_ball_constants make_ball_constants(const contact_law& law, std::string_view gamma_text,
                                                 std::string_view g_text) {
  impact_ball_constants k;
  k.alpha = ball(static_cast<long>(law.alpha.numerator())) / ball(static_cast<long>(law.alpha.denominator()));
  k.beta = ball(static_cast<long>(law.beta.numerator())) / ball(static_cast<long>(law.beta.denominator()));
  k.gamma = ball::from_decimal(gamma_text, "gamma");
  k.g = ball::from_decimal(g_text, "g");
  if (!k.gamma.nonnegative()) throw invalid_parameter("gamma must be >= 0, got " + std::string(gamma_text));
  k.gamma_beta = k.gamma * k.beta;
  const exponent_multiples multiples = law.multiples();  // checked: validate() refused any overflow
  k.Q = multiples.Q, k.Q_alpha = multiples.Q_alpha, k.Q_beta = multiples.Q_beta;
  k.beta_is_one = law.beta.numerator() == law.beta.denominator();
  // alpha - (beta - 1) = (Q alpha - Q beta + Q) / Q.
  if (const long shift = k.Q_alpha - k.Q_beta + k.Q; !k.beta_is_one && (shift == 0 || shift == k.Q))
    k.spring_shift = shift / k.Q;
  return k;
}

/// One proof, phase by phase (core/impact_phase.hpp: compress, turn, exit; no creep
/// phase). Each phase takes the state it starts at and returns how it ended: on to
/// the next phase (the state updated in place), back to the turn from the exit, or
/// decided (the proof's result holds rebound, stick or undecided).
class impact_proof {
 public:
  enum class phase_end { next, back_to_turn, decided };

  impact_proof(const impact_ball_constants& k, const proof_options& options)
      : m_k(k),
        m_options(options),
        m_log2_tolerance(
            -static_cast<double>(options.step_tolerance_bits > 0 ? options.step_tolerance_bits : proofs::ball_bits())),
        m_order(proof_order(m_log2_tolerance)),
        // g = 0 exactly and alpha + 1 >= 2 beta: the trap of creeps_to_origin exists.
        m_trap_applies(arb_is_zero(k.g.get()) && k.Q_alpha + k.Q >= 2 * k.Q_beta && k.gamma.positive()) {}

  proven_impact run() {
    std::vector<ball> x{ball(0), ball(1), ball(0), ball(0)};  // s_system: s, v, tau, D
    if (compress_phase(x) == phase_end::decided) return m_result;
    m_tau = x[s_system::tau];
    for (;;) {
      if (turn_phase(x) == phase_end::decided) return m_result;
      if (exit_phase(x) == phase_end::decided) return m_result;
    }
  }

 private:
  phase_end undecided(std::string why) {
    m_result.outcome = impact_outcome::undecided;
    m_result.how = std::move(why);
    return phase_end::decided;
  }
  phase_end stick(std::string why) {
    m_result.outcome = impact_outcome::stick;
    m_result.e = ball(0), m_result.one_minus_e = ball(1);
    m_result.how = std::move(why);
    return phase_end::decided;
  }
  // Whether the step budget is spent (counting this step).
  bool budget_spent() { return ++m_result.steps > m_options.max_steps; }

  // ---- compress: s from 0 while v >= 1/4 over the whole step; on to the turn once
  // v < 3/4 (near the maximal compression, where v -> 0, the s-series converge slowly).
  // x: the s_system state (s, v, tau, D), from first contact to where the turn starts.
  phase_end compress_phase(std::vector<ball>& x) {
    const ball quarter = ball(1) / ball(4), three_quarters = ball(3) / ball(4);
    const s_system in{&m_k, +1};
    step_memory memory;
    for (;;) {
      if (budget_spent()) return undecided("step budget exhausted on the way in");
      const auto step = find_step(in, in.jet(x, m_order), m_order, m_log2_tolerance, memory, m_options.max_halvings,
                                  [&](const step_enclosure& st) { return (st.range[s_system::v] - quarter).positive(); });
      if (!step) {
        if (x[s_system::s].positive()) return phase_end::next;  // v is near 1/4: continue in tau
        return undecided("no validated first step in s");
      }
      x = step->state_at(step->h);
      if (!(x[s_system::v] - three_quarters).positive()) return phase_end::next;
    }
  }

  // ---- turn: in tau through the maximal compression, until one s-step of the exit
  // reaches a tenth of the way to s = 0 (near u = 0 the tau-series converge slowly).
  // x: the s_system state where the turn starts, on return where the exit starts (its
  // first jet in m_exit_jet).
  phase_end turn_phase(std::vector<ball>& x) {
    const tau_system mid{&m_k};
    const s_system out{&m_k, -1};
    std::vector<ball> y{pow(x[s_system::s], static_cast<unsigned long>(m_k.Q)), x[s_system::v],
                        x[s_system::D]};  // tau_system: u, v, D
    step_memory memory;
    for (;;) {
      if (budget_spent()) return undecided("step budget exhausted in tau");
      const auto step = find_step(mid, mid.jet(y, m_order), m_order, m_log2_tolerance, memory, m_options.max_halvings,
                                  [](const step_enclosure& st) { return st.range[tau_system::u].positive(); });
      if (!step) return undecided("no validated step in tau at tau = " + m_tau.mid_str(10));
      const impact_ball_constants& k = m_k;
      m_turning.add(*step, tau_system::u, tau_system::v,
                    [&k](const std::vector<ball>& state) { return acceleration(k, state); });
      m_result.max_compression = m_turning.value();
      y = step->state_at(step->h);
      m_tau = m_tau + step->h;
      if (energy_proven_negative(m_k, y[tau_system::u], y[tau_system::v]))
        return stick("energy proven negative at tau = " + m_tau.mid_str(10));
      if (creeps_to_origin(m_k, m_trap_applies, y[tau_system::u], y[tau_system::v]))
        return stick("trapped at g = 0 (-gamma u^beta / 2 < v < 0) at tau = " + m_tau.mid_str(10));
      if (!y[tau_system::v].negative()) continue;
      x = {root(y[tau_system::u], m_k.Q), y[tau_system::v], m_tau, y[tau_system::D]};
      m_exit_jet = out.jet(x, m_order);  // the exit's first jet, if the switch is made
      if (proposed_step(m_exit_jet, m_order, m_log2_tolerance) >= x[s_system::s].mid_double() / 10)
        return phase_end::next;
    }
  }

  // ---- exit: s down to 0, with v < 0 over every step. The last step is as long as
  // the upper bound of s, and ends where sigma = s0: s = 0 exactly. Next to the
  // sticking threshold the bead turns back at a small u > 0: v -> 0 there, dv/ds grows
  // like 1/v and the s-steps shrink towards that point without reaching it (it took
  // 10,000 steps). So when a step covers less than 1/64 of s, the proof goes back to
  // the turn, where v = 0 is a regular point and the energy soon proves the stick (or,
  // if v stays negative, the s-steps lengthen again).
  phase_end exit_phase(std::vector<ball>& x) {
    const s_system out{&m_k, -1};
    step_memory memory;
    for (bool first_step = true;; first_step = false) {
      if (budget_spent()) return undecided("step budget exhausted on the way out");
      const ball_jet jet = first_step ? std::move(m_exit_jet) : out.jet(x, m_order);
      if (last_step_reaches_zero(out, jet, x)) {
        if (!m_result.e.positive()) return undecided("e not proven > 0");
        return phase_end::decided;
      }
      const auto step = find_step(out, jet, m_order, m_log2_tolerance, memory, m_options.max_halvings,
                                  [](const step_enclosure& st) {
                                    return st.range[s_system::v].negative() && st.range[s_system::s].positive();
                                  });
      if (!step) return undecided("no validated step on the way out (v near 0?)");
      x = step->state_at(step->h);
      m_tau = x[s_system::tau];
      const ball u = pow(x[s_system::s], static_cast<unsigned long>(m_k.Q));
      if (energy_proven_negative(m_k, u, x[s_system::v]))
        return stick("energy proven negative on the way out at tau = " + m_tau.mid_str(10));
      if (creeps_to_origin(m_k, m_trap_applies, u, x[s_system::v]))
        return stick("trapped at g = 0 (-gamma u^beta / 2 < v < 0) on the way out at tau = " + m_tau.mid_str(10));
      if (step->h.mid_double() < x[s_system::s].mid_double() / 64) return phase_end::back_to_turn;  // crawling
    }
  }

  // Whether one validated step from x reaches s = 0 with v < 0 throughout: then the
  // rebound is proven and m_result holds it (its e may still not be proven > 0).
  bool last_step_reaches_zero(const s_system& out, const ball_jet& jet, const std::vector<ball>& x) {
    const ball s_upper = upper_bound(x[s_system::s]);
    if (!(proposed_step(jet, m_order, m_log2_tolerance) >= s_upper.mid_double())) return false;
    const step_enclosure last = validated_step(out, jet, s_upper, m_order);
    if (!(last.validated && last.tight(m_log2_tolerance) && last.range[s_system::v].negative())) return false;
    const std::vector<ball> end = last.state_at(x[s_system::s]);
    m_result.outcome = impact_outcome::rebound;
    m_result.e = -end[s_system::v];
    m_result.contact_time = end[s_system::tau];
    m_result.one_minus_e = end[s_system::D] / (1 + m_result.e);
    m_result.how = "s reaches 0 with v < 0 over the last step";
    return true;
  }

  const impact_ball_constants m_k;
  const proof_options m_options;
  const double m_log2_tolerance;
  const std::size_t m_order;
  const bool m_trap_applies;
  proven_impact m_result;
  first_maximum m_turning;  // u_max: v falls through 0 in tau (v >= 1/4 before, v < 0 after)
  ball m_tau;               // tau at the current state
  ball_jet m_exit_jet;      // the exit's first jet, computed where the turn decides to leave
};

}  // namespace detail

/// Proves the impact of `law` (rational exponents) at (gamma, g), given as exact
/// decimals, with balls of working_bits(digits) bits. Throws invalid_parameter for a
/// law the proof cannot take ("not provable": contact_law::why_not_provable), gamma < 0,
/// or an input that is not a finite decimal.
inline proven_impact prove_impact(const contact_law& law, std::string_view gamma_text, std::string_view g_text,
                                  int digits, const proof_options& options = {}) {
  law.validate();
  if (const std::string why = law.why_not_provable(); !why.empty()) throw invalid_parameter(why + "; use certify for this law");
  if (digits < 5 || digits > 100000) throw invalid_parameter("digits must be in [5, 100000], got " + std::to_string(digits));
  scoped_ball_bits bits(working_bits(digits));
  return detail::impact_proof(detail::make_ball_constants(law, gamma_text, g_text), options).run();
}

}  // namespace viscor::proofs

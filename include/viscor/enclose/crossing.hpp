// Where a component of a validated step crosses zero: an enclosure of the crossing
// time by the interval Newton operator (and bisection while Newton does not contract), for a component x_i whose
// derivative is proven of one sign over the step (so the crossing is unique). The
// derivative is either another component (x_i' = x_j, as u' = v) or a function of
// the state (v' = f(u, v), for the turning point u' = 0 where u is maximal).
#pragma once

#include <viscor/enclose/validated_taylor.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace viscor::proofs {

/// The lower end of t as an exact ball.
inline ball lower_end(const ball& t) {
  ball b;
  arb_get_lbound_arf(arb_midref(b.get()), t.get(), ball_bits());
  return b;
}

/// The upper end of t as an exact ball.
inline ball upper_end(const ball& t) {
  ball b;
  arb_get_ubound_arf(arb_midref(b.get()), t.get(), ball_bits());
  return b;
}

/// The state over the times T (inside [0, h]): the step's polynomial over T,
/// intersected with the step's range (both enclose it). nullopt if they are
/// disjoint (impossible for a valid step).
inline std::optional<std::vector<ball>> state_over(const step_enclosure& step, const ball& T) {
  std::vector<ball> state = step.state_at(T);
  for (std::size_t k = 0; k < state.size(); ++k)
    if (arb_intersection(state[k].get(), state[k].get(), step.range[k].get(), ball_bits()) == 0) return std::nullopt;
  return state;
}

/// The crossing time t* in [from, to] (inside [0, h]) of component i, whose
/// derivative over a ball of states is `derivative(state)`. Requires: x_i(from)
/// and x_i(to) proven of opposite signs and the derivative proven non-zero over
/// [from, to] (so the crossing is unique there). nullopt when a requirement cannot
/// be proven.
template <class Derivative>
std::optional<ball> enclose_crossing_in(const step_enclosure& step, std::size_t i, Derivative derivative,
                                        const ball& from, const ball& to) {
  ball t = ball::hull(from, to);
  const auto over = state_over(step, t);
  if (!over) return std::nullopt;
  const ball slope_range = derivative(*over);
  // Test seam (mutation_seam.hpp): crossing_unproven skips both sign proofs.
  const bool unproven = proof_mutated(proof_mutation::crossing_unproven);
  if (!unproven && !(slope_range.positive() || slope_range.negative())) return std::nullopt;
  const ball start = step.at(i, from), end = step.at(i, to);
  const bool falls = start.positive() && end.negative(), rises = start.negative() && end.positive();
  if (!unproven && (!(falls || rises) || (falls && !slope_range.negative()) || (rises && !slope_range.positive())))
    return std::nullopt;
  // Interval Newton: N(T) = m - x_i(m) / x_i'(T) contains the (unique) root in T;
  // where it does not shrink T by a quarter (a wide T: the Horner enclosure over a
  // long step is loose) bisect instead, on the proven sign of x_i(m).
  for (int iteration = 0; iteration < 400; ++iteration) {
    const double width = t.rad_double();
    const ball m = t.mid();
    const ball value = step.at(i, m);
    const auto state = state_over(step, t);
    if (!state) return std::nullopt;
    const ball slope = derivative(*state);
    ball next = t;
    if (slope.positive() || slope.negative()) {
      const ball newton = m - value / slope;
      if (arb_intersection(next.get(), t.get(), newton.get(), ball_bits()) == 0) return std::nullopt;  // cannot happen
      if (next.rad_double() < 0.75 * width) {
        t = next;
        continue;
      }
    }
    const bool before = falls ? value.positive() : value.negative();  // x_i(m) still on the start's side
    const bool after = falls ? value.negative() : value.positive();
    if (!(before || after)) {
      t = next;  // x_i(m) of no proven sign: T is as narrow as the precision allows
      break;
    }
    t = before ? ball::hull(m, upper_end(t)) : ball::hull(lower_end(t), m);
  }
  return t;
}

/// The crossing time t* in [0, h] of component i (enclose_crossing_in over the
/// whole step).
template <class Derivative>
std::optional<ball> enclose_crossing_by(const step_enclosure& step, std::size_t i, Derivative derivative) {
  return enclose_crossing_in(step, i, derivative, ball(0), step.h);
}

/// The crossing time t* in [0, h] of component i, whose derivative is component
/// `derivative` (x_i' = x_derivative). Requires: x_i(0) and x_i(h) proven of
/// opposite signs and the derivative proven non-zero over the step's range.
/// nullopt when a requirement cannot be proven.
inline std::optional<ball> enclose_crossing(const step_enclosure& step, std::size_t i, std::size_t derivative) {
  return enclose_crossing_by(step, i, [derivative](const std::vector<ball>& x) { return x[derivative]; });
}

/// u(t*) at the unique t* in [from, to] where u' = v falls through 0, with
/// v' = dv(state) proven negative there. Evaluated as u(m) + v(T) [-r, r] for the
/// enclosure T = m +/- r of t* (mean value theorem; v is tiny on T, so the
/// enclosure is as tight as the state's). nullopt when the crossing cannot be proven.
template <class Derivative>
std::optional<ball> enclose_maximum(const step_enclosure& step, std::size_t u, std::size_t v, Derivative dv,
                                    const ball& from, const ball& to) {
  const auto t = enclose_crossing_in(step, v, dv, from, to);
  if (!t) return std::nullopt;
  const ball spread = ball::hull(-t->rad(), t->rad());
  return step.at(u, t->mid()) + step.at(v, *t) * spread;
}

/// The first maximum of a component u whose derivative is component v (u_max at
/// the first zero of v), from the validated steps of an integration in time, fed in
/// order. Each step is cut into 64 pieces (the Horner enclosure over a piece is
/// much tighter than over the step): pieces with v proven positive are passed
/// over (v > 0 over the piece, or at its end with v' < 0 over it); in the first piece where v may vanish, interval Newton encloses u at the
/// unique zero (enclose_maximum). When it cannot (v' not proven negative, or the
/// zero on a piece's boundary), the enclosure is the hull of u over that piece and
/// the next ones, until v is proven negative at a piece's end: the first zero lies
/// in one of them. Rigorous either way, tight only with Newton.
class first_maximum {
 public:
  /// Feeds the next step; dv(state) encloses v' over a ball of states.
  template <class Derivative>
  void add(const step_enclosure& step, std::size_t u, std::size_t v, Derivative dv) {
    // v proven positive over the whole step: every piece below would be passed over
    // (each piece's state lies in the step's range), so skip the 64 evaluations
    // (they were a tenth of a proof's time).
    if (!m_started && step.range[v].positive()) return;
    constexpr long pieces = 64;  // a power of two: the piece ends k h / 64 are exact
    for (long k = 0; k < pieces && !m_done; ++k) {
      const ball from = step.h * ball(k) / ball(pieces), to = step.h * ball(k + 1) / ball(pieces);
      const auto state = state_over(step, ball::hull(from, to));
      if (!state) return;  // impossible for a valid step; nothing is claimed
      // Passed over: v > 0 on the piece, or v > 0 at its end while falling throughout.
      if (!m_started && ((*state)[v].positive() || (step.at(v, to).positive() && dv(*state).negative()))) continue;
      if (!m_started) {
        m_started = true;
        if (const auto newton = enclose_maximum(step, u, v, dv, from, to)) {
          m_value = *newton, m_done = true, m_tight = true;
          return;
        }
        m_value = (*state)[u];
      } else {
        m_value = ball::hull(m_value, (*state)[u]);
      }
      if (step.at(v, to).negative()) m_done = true;
    }
  }
  /// The enclosure of u_max once the first zero of v is behind; nullopt before.
  std::optional<ball> value() const { return m_done ? std::optional<ball>(m_value) : std::nullopt; }
  /// Whether the enclosure came from interval Newton (else a hull of piece ranges).
  bool tight() const { return m_tight; }

 private:
  bool m_started = false, m_done = false, m_tight = false;
  ball m_value;
};

}  // namespace viscor::proofs

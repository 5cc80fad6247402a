// Where a component of a validated step crosses zero: an enclosure of the crossing
// time by bisection and the interval Newton operator, for a component x_i whose
// derivative x_i' = x_j(t) is proven of one sign over the step (so the crossing is
// unique).
#pragma once

#include <viscor/enclose/validated_taylor.hpp>

#include <cstddef>
#include <optional>

namespace viscor::enclose {

/// The crossing time t* in [0, h] of component i, whose derivative is component
/// `derivative` (x_i' = x_derivative). Requires: x_i(0) and x_i(h) proven of
/// opposite signs and the derivative proven non-zero over the step's range.
/// nullopt when a requirement cannot be proven.
inline std::optional<ball> enclose_crossing(const step_enclosure& step, std::size_t i, std::size_t derivative) {
  const ball& slope_range = step.range[derivative];
  if (!(slope_range.positive() || slope_range.negative())) return std::nullopt;
  const ball start = step.at(i, ball(0)), end = step.at(i, step.h);
  const bool falls = start.positive() && end.negative(), rises = start.negative() && end.positive();
  if (!(falls || rises) || (falls && !slope_range.negative()) || (rises && !slope_range.positive()))
    return std::nullopt;
  // Interval Newton: N(T) = m - x_i(m) / x_i'(T) contains the (unique) root of T;
  // intersect and repeat until the width stops shrinking.
  ball t = zero_to(step.h);
  double width = t.rad_double();
  for (int iteration = 0; iteration < 200; ++iteration) {
    const ball m = t.mid();
    const ball newton = m - step.at(i, m) / step.at(derivative, t);
    ball next;
    if (arb_intersection(next.get(), t.get(), newton.get(), ball_bits()) == 0) return std::nullopt;  // cannot happen
    t = next;
    const double w = t.rad_double();
    if (!(w < 0.75 * width)) break;
    width = w;
  }
  return t;
}

}  // namespace viscor::enclose

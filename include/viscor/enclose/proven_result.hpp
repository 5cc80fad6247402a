// What a proof of an impact established.
#pragma once

#include <viscor/core/outcome.hpp>
#include <viscor/enclose/ball.hpp>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace viscor::proofs {

/// The outcome of a proof: the solvers' impact_outcome (core/outcome.hpp). rebound:
/// the bead provably leaves the wall, e > 0 enclosed. stick: it provably never reaches
/// u = 0 again (e = 0). undecided: the working precision (or the step budget) could
/// not separate the two; nothing is claimed.
using proven_outcome = impact_outcome;
using viscor::to_string;  // the outcome's name as in JSON, also as proofs::to_string

/// A proven impact: every ball contains the exact value.
struct proven_impact {
  impact_outcome outcome = impact_outcome::undecided;
  ball e;             ///< rebound: encloses e; stick: exactly 0
  ball one_minus_e;   ///< from the dissipated energy, so its relative width survives gamma -> 0
  ball contact_time;  ///< rebound: encloses T_f (scaled time)
  /// Encloses u_max, the compression where u' first vanishes, once the integration
  /// has passed it (every rebound; a stick only if proven after the turning point).
  std::optional<ball> max_compression;
  std::string how;    ///< the argument that decided the outcome (or why it is undecided)
  std::size_t steps = 0;

  /// Decimal digits d with rad(x) <= 10^-d |x| for every point x of the ball
  /// (0 when the ball contains 0 or is not finite).
  static int relative_digits(const ball& x) {
    if (!x.finite() || !(x.positive() || x.negative())) return 0;
    if (x.rad_double() == 0) return 1000;
    // NOTE: the doubles are rounded; the factors 1 -/+ 1e-9 keep the count on the safe side.
    const double lower = (std::abs(x.mid_double()) - x.rad_double()) * (1 - 1e-9);
    const double rad = x.rad_double() * (1 + 1e-9);
    if (!(lower > 0) || !(rad > 0) || !std::isfinite(lower / rad)) return 0;
    return static_cast<int>(std::floor(std::log10(lower / rad)));
  }
};

/// Limits of a proof.
struct proof_options {
  std::size_t max_steps = 10000;
  int max_halvings = 60;  ///< a step halved this often without validating: undecided
  /// Bits of accuracy per step that order and step size aim at; 0: all working
  /// bits. Fewer give longer steps and wider, still valid, enclosures (the tests use
  /// it to make the remainder dominate the width).
  int step_tolerance_bits = 0;
};

}  // namespace viscor::proofs

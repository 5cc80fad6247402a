// What a proof of one impact established, as exact decimals: no Arb type, so a
// job's result can carry it in builds without the proofs.
#pragma once

#include <viscor/core/outcome.hpp>

#include <optional>
#include <string>

namespace viscor::proofs {

/// A proven quantity: lower <= exact <= upper (exact decimals) and its proven
/// correctly rounded significant digits.
struct proven_bounds {
  std::string lower;  ///< a decimal <= the exact value
  std::string upper;  ///< a decimal >= the exact value
  int proven_digits = 0;  ///< d: both bounds round (to nearest) to the same d-digit decimal; 0 if none
  std::string rounded;  ///< that decimal: the exact value correctly rounded to `proven_digits` digits (empty if none)
};

/// The proven bounds of one impact (viscor::enclose, enclose.hpp).
struct proven_decimals {
  impact_outcome outcome = impact_outcome::undecided;  ///< rebound, stick or undecided (nothing claimed)
  std::string how;                 ///< the argument that decided the outcome, or why it is undecided
  proven_bounds e;                 ///< rebound: encloses e; stick: exactly 0
  proven_bounds one_minus_e;       ///< 1 - e from the dissipated energy (relative width survives gamma -> 0)
  std::optional<proven_bounds> contact_time;     ///< rebound: T_f (scaled)
  std::optional<proven_bounds> max_compression;  ///< u_max, once the proof passed the turning point
};

}  // namespace viscor::proofs

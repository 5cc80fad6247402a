// What an exact (closed-form) solution reports.
#pragma once

#include <viscor/core/outcome.hpp>

#include <optional>
#include <string>

namespace viscor {

/// A closed-form impact: e, 1 - e, the contact time and the maximal compression.
template <class Real>
struct exact_result {
  Real e = 0;            ///< coefficient of restitution
  Real one_minus_e = 1;  ///< 1 - e, at full relative precision (no cancellation)
  impact_outcome outcome = impact_outcome::rebound;
  /// Scaled contact duration T_f (rebound), or for sticking the time u' vanishes
  /// again with u > 0; +infinity when the bead creeps to rest without turning back.
  std::optional<Real> contact_time;
  std::optional<Real> max_compression;           ///< u_max
  std::optional<Real> time_of_max_compression;   ///< tau at u_max
  std::string formula;                           ///< which exact solution was used
};

}  // namespace viscor

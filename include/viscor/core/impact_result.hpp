// What solve_impact reports, and how to ask for it.
#pragma once

#include <viscor/core/outcome.hpp>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>

namespace viscor {

/// Which integrator solve_impact uses. Both end contact at zero overlap u = 0.
enum class integration_method {
  taylor,    ///< Taylor series with endpoint-regularised variables (the default)
  adaptive,  ///< the independent high-order adaptive method (GBS), for certification
};

/// "taylor" or "adaptive", as in the CLI's --method.
inline std::string_view to_string(integration_method m) { return m == integration_method::taylor ? "taylor" : "adaptive"; }

/// How solve_impact integrates: the method, the step tolerance and the step budget.
template <class Real>
struct solve_options {
  integration_method method = integration_method::taylor;
  /// Relative tolerance per step; 0 means the working precision epsilon<Real>().
  Real tolerance = 0;
  /// Step budget for the whole impact; exhausting it throws convergence_error.
  std::size_t max_steps = 1'000'000;
};

/// What solve_impact found: the outcome, e and 1 - e, the contact time, the maximal compression, an error estimate and the cost.
template <class Real>
struct impact_result {
  Real e = 0;            ///< coefficient of restitution -u'(T_f), or 0 when the bead sticks
  Real one_minus_e = 1;  ///< 1 - e at full relative precision (from the dissipated energy, eq. 6)
  impact_outcome outcome = impact_outcome::rebound;
  /// T_f for a rebound; for a stick, the time u' vanishes again with u > 0 (the
  /// bead stops separating), +infinity if it creeps to rest without turning back;
  /// empty (unknown) when undecided, or for a stick whose turn back is below the
  /// precision (the adaptive method, energy proven negative). std::optional, as in
  /// every result that may not know it (exact_result, table_row, evaluation).
  std::optional<Real> contact_time = Real(0);
  Real max_compression = 0;          ///< u_max
  /// For a stick, the overlap where the bead stops separating: u at contact_time,
  /// where u' returns to 0; when it creeps to rest instead (contact_time =
  /// +infinity), the static equilibrium u^alpha = g (0 for g = 0). 0 for a
  /// rebound, and from the adaptive method, which does not compute it (yet).
  Real stop_overlap = 0;
  Real time_of_max_compression = 0;  ///< tau at u_max
  /// Residual of the energy identity 1 - e^2 = 2 gamma beta int u'^2 u^(beta-1) dtau
  /// (rebound) as computed from the two sides: a built-in consistency check.
  Real energy_residual = 0;
  std::size_t steps = 0;  ///< integrator steps taken
  Real error_estimate = 0;  ///< estimated absolute error of e
  integration_method method = integration_method::taylor;
};

namespace detail {

/// An optional quantity (a contact time, a closed form's u_max) as a number, NaN when
/// unknown: for comparisons (agreement_digits gives 0 for NaN) and for the "nan" that
/// JSON and reports print for it.
template <class Real>
Real or_nan(const std::optional<Real>& x) {
  return x ? *x : std::numeric_limits<Real>::quiet_NaN();
}

}  // namespace detail

}  // namespace viscor

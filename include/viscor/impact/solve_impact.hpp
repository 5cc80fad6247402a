// The public entry point: the coefficient of restitution of one impact,
// integrated to the working precision of Real (report sec. 3, eq. 4).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <viscor/impact/adaptive_impact.hpp>

namespace viscor {

/// Solves u'' + gamma d/dtau(u_+^beta) + u_+^alpha = g, u(0) = 0, u'(0) = 1 for
/// the first return to u = 0 (rebound, e = -u'(T_f)) or sticking (e = 0).
/// Throws invalid_parameter for alpha < 1, beta < 1, gamma < 0, non-finite
/// gamma or g, a negative tolerance or a zero step budget; convergence_error
/// when the step budget options.max_steps is exhausted.
template <class Real>
impact_result<Real> solve_impact(const contact_law& law, const Real& gamma, const Real& g,
                                 const solve_options<Real>& options = {}) {
  impact_parameters<Real>{law, gamma, g}.validate();
  require_non_negative(options.tolerance, "tolerance");
  if (options.max_steps == 0) throw invalid_parameter("parameter max_steps must be > 0, got 0");
  switch (options.method) {
    case integration_method::taylor:
      return solve_impact_taylor(law, gamma, g, options);
    case integration_method::adaptive:
      return solve_impact_adaptive(law, gamma, g, options);
  }
  throw invalid_parameter("unknown integration method");
}

}  // namespace viscor

// The public entry point: the coefficient of restitution of one impact,
// integrated to the working precision of Real (report sec. 3, eq. 4).
#pragma once

#include <viscor/core/real_types.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <viscor/impact/adaptive_impact.hpp>

#include <limits>

namespace viscor {

namespace detail {

/// Refuses (throws precision_unavailable) a result its scalar type cannot carry in
/// full; nothing for the types whose exponent range holds every result. double_double
/// specialises it (below), whose range ends near 1e-292.
template <class Real>
void require_carried(const impact_result<Real>&) {}

/// A rebound with e > 1 beyond rounding contradicts the energy identity (with
/// gamma >= 0 the energy v^2/2 + u^(alpha+1)/(alpha+1) - g u never increases, and it
/// is e^2/2 at the return to u = 0, so e <= 1 under any load): the integration went
/// wrong (Hunt-Crossley, gamma 1e-30, g 1e12 in double gave e = 288 where the bead
/// sticks). Such a result is not a value viscor can stand behind: it becomes undecided.
template <class Real>
impact_result<Real> undecided_unless_energy_allows(impact_result<Real> r) {
  require_carried(r);
  if (r.outcome != impact_outcome::rebound || r.e <= 1 + 16 * epsilon<Real>()) return r;
  r.outcome = impact_outcome::undecided;
  r.error_estimate = r.e;  // all that is known: 0 <= e <= 1
  r.e = 0, r.one_minus_e = 1, r.energy_residual = 0;
  r.contact_time = std::nullopt;
  return r;
}

}  // namespace detail

/// Solves u'' + gamma d/dtau(u_+^beta) + u_+^alpha = g, u(0) = 0, u'(0) = 1 for
/// the first return to u = 0 (rebound, e = -u'(T_f)) or sticking (e = 0);
/// undecided when a solver's rebound has e > 1 (impossible: see detail above).
/// Throws invalid_parameter for alpha < 1, beta < 1, gamma < 0, non-finite
/// gamma or g, a tolerance outside [0, 1) or a zero step budget; convergence_error
/// when the step budget options.max_steps is exhausted; exponent_range_exceeded when
/// Real has double's exponent range (double, double-double) and a Taylor coefficient
/// below it would cost digits (tiny gamma under a large load): with_working_precision
/// then solves in a wider type.
template <class Real>
impact_result<Real> solve_impact(const contact_law& law, const Real& gamma, const Real& g,
                                 const solve_options<Real>& options = {}) {
  impact_parameters<Real>{law, gamma, g}.validate();
  require_non_negative(options.tolerance, "tolerance");
  if (!(options.tolerance < 1))
    throw invalid_parameter("parameter tolerance must be in [0, 1) (a relative tolerance per step; 0: the working "
                            "precision), got " + to_decimal_string(options.tolerance, 6));
  if (options.max_steps == 0) throw invalid_parameter("parameter max_steps must be > 0, got 0");
  switch (options.method) {
    case integration_method::taylor:
      return detail::undecided_unless_energy_allows(solve_impact_taylor(law, gamma, g, options));
    case integration_method::adaptive:
      return detail::undecided_unless_energy_allows(solve_impact_adaptive(law, gamma, g, options));
  }
  throw invalid_parameter("unknown integration method");
}

}  // namespace viscor

#if defined(VISCOR_HAS_QD) && VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>

namespace viscor::detail {
/// double_double: precision_unavailable where e, 1 - e, the contact time, the maximal
/// compression, its time or the stop overlap is nonzero and below 2^-939
/// (double_double_smallest_reported, core/double_double.hpp), where double-double has
/// lost digits to its exponent range.
template <>
inline void require_carried<double_double>(const impact_result<double_double>& r) {
  require_double_double_range(r.e, "e");
  require_double_double_range(r.one_minus_e, "1 - e");
  if (r.contact_time) require_double_double_range(*r.contact_time, "the contact time");
  require_double_double_range(r.max_compression, "the maximal compression");
  require_double_double_range(r.time_of_max_compression, "the time of maximal compression");
  require_double_double_range(r.stop_overlap, "the stop overlap");
}
}  // namespace viscor::detail
#endif

// solve_impact is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_SOLVE_IMPACT_TEMPLATES(PREFIX, Real) \
  PREFIX template impact_result<Real> solve_impact<Real>(const contact_law&, const Real&, const Real&, \
                                                         const solve_options<Real>&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_COMPILED_WITH(VISCOR_SOLVE_IMPACT_TEMPLATES, extern)
}
#endif

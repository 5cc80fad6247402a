// solve_impact in double-double (core/double_double.hpp) with its exponent limit
// handled: a double_double keeps its 104 bits only down to 2^-969 (about 2e-292), so a
// solve whose inputs or reported values come near that bound has lost digits that its
// result would otherwise claim. solve_impact<double_double> refuses a result with such a
// value (impact/solve_impact.hpp); this entry point refuses such inputs as well, with
// precision_unavailable, so that the caller escalates to a type with a wider exponent
// range (MPFR) instead of printing digits that are not there.
#pragma once

#include <viscor/core/double_double.hpp>

#if VISCOR_HAS_QD

#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/impact/solve_impact.hpp>

namespace viscor {

/// solve_impact<double_double> with its inputs checked too: throws precision_unavailable
/// when gamma or g is nonzero and below 2^-939 in magnitude
/// (double_double_smallest_reported), as solve_impact<double_double> itself does for the
/// result's e, 1 - e, contact time, maximal compression, its time and the stop overlap;
/// otherwise solve_impact's result and exceptions.
inline impact_result<double_double> solve_impact_double_double(const contact_law& law, const double_double& gamma,
                                                               const double_double& g,
                                                               const solve_options<double_double>& options = {}) {
  detail::require_double_double_range(gamma, "gamma");
  detail::require_double_double_range(g, "g");
  return solve_impact<double_double>(law, gamma, g, options);
}

}  // namespace viscor

#endif  // VISCOR_HAS_QD

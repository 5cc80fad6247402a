// solve_impact in double-double (core/double_double.hpp) with its exponent limit
// handled: a double_double keeps its 104 bits only down to 2^-969 (about 2e-292), so a
// solve whose inputs or reported values come near that bound has lost digits that its
// result would otherwise claim. This entry point refuses such a solve with
// precision_unavailable, so that the caller escalates to a type with a wider exponent
// range (MPFR) instead of printing digits that are not there.
#pragma once

#include <viscor/core/double_double.hpp>

#if VISCOR_HAS_QD

#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <cmath>
#include <string>

namespace viscor {

/// The smallest nonzero magnitude that a double-double solve accepts as an input or
/// reports as a value: 2^-939, i.e. 2^30 above 2^-969, where the lo part becomes
/// subnormal. NOTE: below 2^-969 each operation adds an absolute error of up to 2^-1075
/// (the lo part's rounding) besides its relative error; a value of at least 2^-939,
/// reached in fewer than 2^30 operations, keeps that share below 2^-105 relative.
inline double double_double_smallest_reported() { return std::ldexp(1.0, -939); }

namespace detail {
/// Throws precision_unavailable when x is nonzero, finite and below
/// double_double_smallest_reported() in magnitude; `what` names the value.
inline void require_double_double_range(const double_double& x, const std::string& what) {
  if (x.hi() == 0 || !std::isfinite(x.hi()) || std::fabs(x.hi()) >= double_double_smallest_reported()) return;
  throw precision_unavailable(what + " = " + to_decimal_string(x, 6) +
                              " is below 2^-939 = 2.2e-283, where double-double (double's exponent range) no "
                              "longer carries its 31 digits; solve in MPFR instead");
}
}  // namespace detail

/// solve_impact<double_double> with the exponent limit checked: throws
/// precision_unavailable when gamma or g, or the result's e, 1 - e, contact time, maximal
/// compression, its time or the stop overlap, is nonzero and below 2^-939 in magnitude
/// (double_double_smallest_reported); otherwise solve_impact's result and exceptions.
inline impact_result<double_double> solve_impact_double_double(const contact_law& law, const double_double& gamma,
                                                               const double_double& g,
                                                               const solve_options<double_double>& options = {}) {
  detail::require_double_double_range(gamma, "gamma");
  detail::require_double_double_range(g, "g");
  const impact_result<double_double> r = solve_impact<double_double>(law, gamma, g, options);
  detail::require_double_double_range(r.e, "e");
  detail::require_double_double_range(r.one_minus_e, "1 - e");
  detail::require_double_double_range(r.contact_time, "the contact time");
  detail::require_double_double_range(r.max_compression, "the maximal compression");
  detail::require_double_double_range(r.time_of_max_compression, "the time of maximal compression");
  detail::require_double_double_range(r.stop_overlap, "the stop overlap");
  return r;
}

}  // namespace viscor

#endif  // VISCOR_HAS_QD

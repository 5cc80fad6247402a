// Bracketed root finding at the working precision of Real.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_types.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <cstdint>
#include <string>
#include <utility>

namespace viscor::detail {

/// A bracket [lo, hi] of the root of f in [a, b], |hi - lo| at the last bit of
/// Real (TOMS 748). f(a) and f(b) must differ in sign; `what` names the
/// equation in the error message.
template <class Real, class F>
std::pair<Real, Real> root_bracket(F f, const Real& a, const Real& b, const std::string& what) {
  const Real fa = f(a), fb = f(b);
  if (fa == 0) return {a, a};
  if (fb == 0) return {b, b};
  if ((fa > 0) == (fb > 0)) throw convergence_error(what + ": root is not bracketed");
  // Bisection would need binary_digits steps; TOMS 748 needs far fewer.
  const std::uintmax_t budget = 8 * static_cast<std::uintmax_t>(binary_digits<Real>()) + 100;
  std::uintmax_t iterations = budget;
  auto bracket = boost::math::tools::toms748_solve(
      f, a, b, fa, fb, boost::math::tools::eps_tolerance<Real>(binary_digits<Real>()), iterations);
  if (iterations >= budget) throw convergence_error(what + ": root finder did not converge");
  return bracket;
}

/// Root of f in [a, b] (signs differ at the ends) to working precision.
template <class Real, class F>
Real bracketed_root(F f, const Real& a, const Real& b, const std::string& what) {
  const auto [lo, hi] = root_bracket(f, a, b, what);
  return (lo + hi) / 2;
}

/// Same, then one Newton step with df to settle the last ulp.
template <class Real, class F, class DF>
Real monotone_root(F f, DF df, const Real& a, const Real& b, const std::string& what) {
  const auto [lo, hi] = root_bracket(f, a, b, what);
  Real x = (lo + hi) / 2;
  const Real slope = df(x);
  if (slope != 0) {
    const Real newton = x - f(x) / slope;
    if (newton >= lo && newton <= hi) x = newton;
  }
  return x;
}

}  // namespace viscor::detail

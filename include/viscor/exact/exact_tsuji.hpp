// Exact CoR of the Tsuji law alpha = 3/2, beta = 5/4 at g = 0 (Antypov-Elliott):
// the map u = A x^(4/5), A = (5/4)^(2/5), carries the phase-plane curve onto that
// of a linear oscillator with damping ratio xi = sqrt(5) gamma / 4, so
//     e = exp(-xi pi / sqrt(1 - xi^2)),  and e = 0 (no return) for xi >= 1.
#pragma once

#include <viscor/exact/exact_result.hpp>
#include <viscor/core/parameters.hpp>

#include <boost/math/constants/constants.hpp>

#include <cmath>

namespace viscor {

/// The exact impact of the Tsuji law at g = 0 (see the header comment); throws invalid_parameter for gamma < 0.
template <class Real>
exact_result<Real> exact_tsuji(const Real& gamma) {
  require_non_negative(gamma, "gamma");
  using std::exp;
  using std::sqrt;
  using std::expm1;
  exact_result<Real> r;
  r.formula = "Tsuji g = 0, Antypov-Elliott: e = exp(-xi pi/sqrt(1 - xi^2)), xi = sqrt(5) gamma/4";
  const Real xi = sqrt(Real(5)) * gamma / 4;
  if (xi >= 1) {
    r.outcome = impact_outcome::stick;
    r.e = 0, r.one_minus_e = 1;
    return r;
  }
  const Real exponent = -xi * boost::math::constants::pi<Real>() / sqrt((1 - xi) * (1 + xi));
  r.outcome = impact_outcome::rebound;
  r.e = exp(exponent);
  r.one_minus_e = -expm1(exponent);
  return r;
}

}  // namespace viscor

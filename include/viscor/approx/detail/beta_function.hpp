// Euler's Beta function B(a, b) at the working precision of Real.
// NOTE: boost::math::beta is accurate to a few ulps in double, long double and
// float128, but at 100 MPFR digits it was measured 130 ulps off for
// B(4/3, 3/2) (7.6e-99 relative); MPFR's own correctly rounded Gamma, through
// Gamma(a) Gamma(b)/Gamma(a+b), is good to a few ulps there, and MPFR's exponent
// range rules out overflow.
#pragma once

#include <viscor/core/real_types.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <type_traits>

namespace viscor::detail {

/// B(a, b) for a, b > 0: accuracy first (closed forms, built once per law).
template <class Real>
Real beta_function(const Real& a, const Real& b) {
  if constexpr (is_mpfr<Real>::value) {
    using std::tgamma;
    return Real(tgamma(a) * tgamma(b) / tgamma(Real(a + b)));
  } else {
    return boost::math::beta(a, b);
  }
}

/// B(z, 1/2) = sqrt(pi) Gamma(z)/Gamma(z + 1/2), z > 0: speed first, for the many
/// moments of the Chebyshev-Beta scheme (53). NOTE: in double, Boost's default
/// policy evaluates beta in long double (1.5 us per call); tgamma_delta_ratio
/// without that promotion takes 27 ns and was measured within 3 ulps for the
/// arguments of (53).
template <class Real>
Real beta_half(const Real& z) {
  if constexpr (std::is_same_v<Real, double> || std::is_same_v<Real, long double>) {
    using no_promotion = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
    return boost::math::constants::root_pi<Real>() * boost::math::tgamma_delta_ratio(z, Real(0.5), no_promotion());
  } else {
    return beta_function<Real>(z, Real(1) / 2);
  }
}

}  // namespace viscor::detail

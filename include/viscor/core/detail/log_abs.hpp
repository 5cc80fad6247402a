// ln|x| in double for any Real: what step-size control needs (a few digits),
// without log at the working precision.
#pragma once

#include <viscor/core/real_types.hpp>

#include <cmath>
#include <type_traits>

namespace viscor::detail {

/// ln|x| in double for any Real, whose exponent range may exceed double's; -inf for 0.
template <class Real>
double log_abs(const Real& x) {
  constexpr double ln2 = 0.693147180559945309417;
  if constexpr (std::is_same_v<Real, double>) {
    return std::log(std::fabs(x));
#if VISCOR_HAS_MPFR
  } else if constexpr (is_mpfr<Real>::value) {
    long e = 0;
    const double m = mpfr_get_d_2exp(&e, x.backend().data(), MPFR_RNDN);
    return std::log(std::fabs(m)) + static_cast<double>(e) * ln2;
#endif
  } else {
    using std::frexp;
    int e = 0;
    const Real m = frexp(x, &e);
    return std::log(std::fabs(static_cast<double>(m))) + static_cast<double>(e) * ln2;
  }
}

}  // namespace viscor::detail

#if defined(VISCOR_HAS_QD) && VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>

namespace viscor::detail {
/// log_abs for double_double: its hi part has the magnitude (and double's exponent range).
template <>
inline double log_abs<double_double>(const double_double& x) {
  return std::log(std::fabs(x.hi()));
}
}  // namespace viscor::detail
#endif

// How many significant digits two computations of one quantity share: the single
// rule that certify and the checked closed forms use to turn agreement into digits.
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>

namespace viscor::detail {

/// -log10(|a - b| / |scale|) floored, in [0, cap]; cap when a == b (both infinite
/// and equal included), 0 when only one is infinite, 0 when either is NaN (an
/// undecided contact time agrees with nothing, not even another NaN).
template <class Ref>
int agreement_digits(const Ref& a, const Ref& b, const Ref& scale, int cap) {
  using boost::math::isinf;
  using boost::math::isnan;
  using std::abs;
  using std::floor;
  using std::log10;
  if (isnan(a) || isnan(b)) return 0;
  if (isinf(a) || isinf(b)) return a == b ? cap : 0;
  const Ref diff = abs(a - b);
  if (diff == 0) return cap;
  if (scale == 0) return 0;
  const Ref d = floor(-log10(Ref(diff / abs(scale))));
  if (d >= cap) return cap;
  if (d <= 0) return 0;
  return static_cast<int>(d);
}

}  // namespace viscor::detail

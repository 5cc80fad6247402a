// Evenly spaced values between two ends, linearly or logarithmically: a scene's range
// of impact speeds, an error map's nodes between its edges.
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace viscor {

/// `count` values from `from` to `to` (count >= 1; count 1 gives {from}), evenly
/// spaced, or evenly in the logarithm when `logarithmic` (then from, to > 0). The first and
/// last values are `from` and `to` exactly.
/// NOTE: from + (to - from) t rounds the last value to 0 when |from| dwarfs |to|
/// (1e25 to 2 in double), and from (to/from)^t overflows or underflows with the
/// ratio (1e-300 to 1e300): so the ends are copied, and an interior value whose
/// direct formula fails goes through (1 - t) from + t to, or through the logarithms.
template <class Real>
std::vector<Real> spaced_range(const Real& from, const Real& to, std::size_t count, bool logarithmic) {
  using boost::math::isfinite;
  using std::exp;
  using std::log;
  using std::pow;
  std::vector<Real> out;
  if (count == 0) return out;
  out.reserve(count);
  out.push_back(from);
  if (count == 1) return out;
  const Real span = to - from;
  const Real ratio = logarithmic ? Real(to / from) : Real(0);
  const bool direct = logarithmic ? isfinite(ratio) && ratio > 0 && isfinite(Real(Real(1) / ratio)) : isfinite(span);
  for (std::size_t i = 1; i + 1 < count; ++i) {
    const Real t = Real(i) / Real(count - 1);
    if (!logarithmic)
      out.push_back(direct ? Real(from + span * t) : Real((Real(1) - t) * from + t * to));
    else
      out.push_back(direct ? Real(from * pow(ratio, t)) : Real(exp((Real(1) - t) * log(from) + t * log(to))));
  }
  out.push_back(to);
  return out;
}

}  // namespace viscor

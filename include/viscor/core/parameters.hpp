// Validation of the scaled impact parameters (gamma, g) at the API boundary.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <string>

namespace viscor {

/// Throws invalid_parameter naming `name` unless x is finite.
template <class Real>
void require_finite(const Real& x, const std::string& name) {
  using boost::math::isfinite;
  if (!isfinite(x)) throw invalid_parameter("parameter " + name + " must be finite, got " + to_decimal_string(x));
}

/// Throws invalid_parameter naming `name` unless x is finite and x >= 0.
template <class Real>
void require_non_negative(const Real& x, const std::string& name) {
  require_finite(x, name);
  if (x < 0) throw invalid_parameter("parameter " + name + " must be >= 0, got " + to_decimal_string(x));
}

/// Throws invalid_parameter naming `name` unless x is finite and x > 0.
template <class Real>
void require_positive(const Real& x, const std::string& name) {
  require_finite(x, name);
  if (!(x > 0)) throw invalid_parameter("parameter " + name + " must be > 0, got " + to_decimal_string(x));
}

/// Throws invalid_parameter unless `x`, a quantity computed from valid inputs (`from`
/// names them), is finite and > 0 and, in double and long double, not subnormal:
/// inputs of extreme size can overflow or underflow the working precision there,
/// and a mass or stiffness of 0 or inf must not be passed on as if it were given.
template <class Real>
void require_representable_positive(const Real& x, const std::string& name, const std::string& from) {
  using boost::math::isfinite;
  if (!isfinite(x) || !(x > 0) || detail::underflowed(x))
    throw invalid_parameter(name + " = " + to_decimal_string(x) + ", computed from " + from +
                            ", is outside the range of the working precision (it overflows or underflows): "
                            "give inputs of a more moderate size, or ask for more digits");
}

/// Throws invalid_parameter unless the gravitational acceleration is finite and >= 0.
/// viscor's sign convention is "towards the wall is positive": some DEM codes write
/// gravity as -9.81 along z, and taking that sign here would silently turn the load
/// around (the damping changes by several percent), so a negative value is refused.
/// The message refusing a negative gravity `value` (as the user wrote it).
inline std::string negative_gravity_message(const std::string& value) {
  return "gravity " + value +
         " is negative: gravity is the acceleration towards the wall, counted positive (a bead dropped on a floor "
         "under Earth's gravity: 9.81, not -9.81); a load that pulls the bead away from the wall is a negative force";
}

/// Throws invalid_parameter unless the gravitational acceleration is finite and >= 0.
/// viscor counts gravity positive towards the wall; some DEM codes write it as -9.81
/// along z, and taking that sign here would silently turn the load around.
template <class Real>
void require_gravity_towards_wall(const Real& gravity) {
  require_finite(gravity, "gravity");
  if (gravity < 0) throw invalid_parameter(negative_gravity_message(to_decimal_string(gravity, 6)));
}

/// The scaled problem u'' + gamma d/dtau(u_+^beta) + u_+^alpha = g, u(0)=0, u'(0)=1.
template <class Real>
struct impact_parameters {
  contact_law law;
  Real gamma = 0;  ///< scaled damping, >= 0
  Real g = 0;      ///< scaled load (any sign: g < 0 pulls the bead away)

  /// Throws invalid_parameter naming the first invalid field (law, gamma >= 0, finite g).
  void validate() const {
    law.validate();
    require_non_negative(gamma, "gamma");
    require_finite(g, "g");
  }
};

}  // namespace viscor

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

// Physical <-> scaled parameters, eq. (2) of the report: with
//   T = (m/k)^(1/(alpha+1)) v0^((1-alpha)/(alpha+1)),  delta = v0 T,  x = -delta u, t = T tau,
//   gamma = gamma0 v0^(2 beta/(alpha+1) - 1) (k/m)^(1 - beta/(alpha+1)),
//   g     = (m/k)^(1/(alpha+1)) v0^(-2 alpha/(alpha+1)) (gravity + F/m).
#pragma once

#include <viscor/core/real_types.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/parameters.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

namespace viscor {

/// Physical impact data in SI units; k has units N/m^alpha, gamma0 s/m^(beta-alpha)...
/// (whatever makes k gamma0 d/dt(delta^beta) a force).
template <class Real>
struct physical_parameters {
  Real m = 0;        ///< mass, kg, > 0
  Real k = 0;        ///< contact stiffness, > 0
  Real gamma0 = 0;   ///< damping coefficient, >= 0
  Real v0 = 0;       ///< impact speed, m/s, > 0
  Real gravity = 0;  ///< gravitational acceleration towards the wall, m/s^2
  Real force = 0;    ///< constant external force F, N; F > 0 presses the bead on the wall

  /// Throws invalid_parameter naming the first invalid field.
  void validate() const {
    require_positive(m, "m");
    require_positive(k, "k");
    require_non_negative(gamma0, "gamma0");
    require_positive(v0, "v0");
    require_gravity_towards_wall(gravity);
    require_finite(force, "F");
  }
};

/// Scaled parameters with the time and length scales that produced them.
template <class Real>
struct scaled_parameters {
  Real gamma = 0;
  Real g = 0;
  Real time_scale = 0;    ///< T: physical time = T * tau
  Real length_scale = 0;  ///< delta = v0 T: physical overlap = delta * u
};

/// A scaled time tau in seconds, T * tau; a contact that never ends (tau infinite)
/// lasts forever in seconds too (double-double's inf * T would be NaN).
template <class Real>
Real in_seconds(const Real& tau, const Real& time_scale) {
  return (boost::math::isinf)(tau) ? tau : Real(tau * time_scale);
}

namespace detail {
template <class Real>
Real time_scale(const contact_law& law, const Real& m, const Real& k, const Real& v0) {
  using std::pow;
  const Real alpha = law.alpha.value<Real>();
  return Real(pow(m / k, 1 / (alpha + 1)) * pow(v0, (1 - alpha) / (alpha + 1)));
}
// gamma / gamma0 and g / (gravity + F/m): the two factors of eq. (2).
template <class Real>
Real damping_factor(const contact_law& law, const Real& m, const Real& k, const Real& v0) {
  using std::pow;
  const Real alpha = law.alpha.value<Real>(), beta = law.beta.value<Real>();
  return Real(pow(v0, 2 * beta / (alpha + 1) - 1) * pow(k / m, 1 - beta / (alpha + 1)));
}
template <class Real>
Real load_factor(const contact_law& law, const Real& m, const Real& k, const Real& v0) {
  using std::pow;
  const Real alpha = law.alpha.value<Real>();
  return Real(pow(m / k, 1 / (alpha + 1)) * pow(v0, -2 * alpha / (alpha + 1)));
}
}  // namespace detail

/// Physical -> scaled (eq. 2).
template <class Real>
scaled_parameters<Real> to_scaled(const contact_law& law, const physical_parameters<Real>& p) {
  using std::abs;
  law.validate();
  p.validate();
  // Inputs of extreme size can leave the working precision's range here (k / m
  // overflows for k = 1e3, m = 1e-307 in double): refused, naming the inputs, not
  // passed on as inf, NaN (0 * inf) or a damping or load lost to underflow.
  const std::string from = "m = " + to_decimal_string(p.m) + ", k = " + to_decimal_string(p.k) +
                           ", v0 = " + to_decimal_string(p.v0);
  const Real damping = detail::damping_factor(law, p.m, p.k, p.v0), load = detail::load_factor(law, p.m, p.k, p.v0);
  require_representable_positive(damping, "the damping scale gamma / gamma0", from);
  require_representable_positive(load, "the load scale g / (gravity + F/m)", from);
  scaled_parameters<Real> s;
  s.gamma = p.gamma0 * damping;
  const Real acceleration = p.gravity + p.force / p.m;
  s.g = load * acceleration;
  s.time_scale = detail::time_scale(law, p.m, p.k, p.v0);
  s.length_scale = p.v0 * s.time_scale;
  require_representable_positive(s.time_scale, "the time scale T", from);
  require_representable_positive(s.length_scale, "the length scale v0 T", from);
  if (p.gamma0 > 0)
    require_representable_positive(s.gamma, "the scaled damping gamma", from + ", gamma0 = " + to_decimal_string(p.gamma0));
  if (acceleration != 0)
    require_representable_positive(Real(abs(s.g)), "the scaled load |g|",
                                   from + ", gravity = " + to_decimal_string(p.gravity) + ", F = " + to_decimal_string(p.force));
  return s;
}

/// Scaled -> physical: given (gamma, g) and the bead (m, k, v0, gravity), the
/// damping gamma0 and the external force F that produce them.
template <class Real>
physical_parameters<Real> to_physical(const contact_law& law, const Real& gamma, const Real& g, const Real& m,
                                      const Real& k, const Real& v0, const Real& gravity) {
  law.validate();
  require_non_negative(gamma, "gamma");
  require_finite(g, "g");
  physical_parameters<Real> p;
  p.m = m, p.k = k, p.v0 = v0, p.gravity = gravity;
  p.gamma0 = 0, p.force = 0;
  p.validate();
  p.gamma0 = gamma / detail::damping_factor(law, m, k, v0);
  p.force = m * (g / detail::load_factor(law, m, k, v0) - gravity);
  return p;
}

}  // namespace viscor

// to_scaled is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_SCALING_TEMPLATES(PREFIX, Real) \
  PREFIX template scaled_parameters<Real> to_scaled<Real>(const contact_law&, const physical_parameters<Real>&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_COMPILED_WITH(VISCOR_SCALING_TEMPLATES, extern)
}
#endif

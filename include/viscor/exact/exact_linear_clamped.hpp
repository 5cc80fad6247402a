// Closed form of the clamped linear impact, u'' = g - max(0, u + gamma u') for
// u > 0, u(0) = 0, u'(0) = 1 (the linear spring-dashpot whose force cannot pull, as
// in YADE's visco-elastic law). Written independently of impact/clamped_impact.hpp,
// which it checks.
//
// Contact phase from (t0, u0, v0): w = u - g solves w'' + gamma w' + w = 0, so with
// xi = gamma/2, lambda = 1 - xi^2, C' = -lambda S, S' = C, C(0) = 1, S(0) = 0,
//   w(t)  = exp(-xi t) ( w0 C(t) + (v0 + xi w0) S(t) ),
//   w'(t) = exp(-xi t) ( v0 C(t) - (w0 + xi v0) S(t) ).
// It ends where the force u + gamma u' first changes sign (sampled on a grid finer
// than the oscillation and the decay, then TOMS 748 on the closed form). Then the
// parabola u = u_s + v_s t + g t^2/2: it reaches u = 0 with speed
// sqrt(v_s^2 - 2 g u_s) when that is real, else the bead falls back and the
// contact resumes where u + gamma u' = 0 again (root of a quadratic in t:
// u_s + v_s t + g t^2/2 + gamma (v_s + g t) = 0, which is u_s + gamma v_s = 0 at
// t = 0, so the other root t = -2 (v_s + gamma g) / g). Sticking: the energy
// W = u'^2/2 + u^2/2 - g u never increases, and is e^2/2 >= 0 at a return to u = 0.
#pragma once

#include <viscor/core/detail/root_finding.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>

#include <cmath>
#include <string>

namespace viscor {

/// The clamped linear impact in closed form: e (0 if the bead sticks) and its phases.
template <class Real>
struct exact_linear_clamped_result {
  Real e = 0;             ///< rebound speed at the return to u = 0, 0 for a stick
  bool sticks = false;    ///< the energy fell below zero: the bead never returns to u = 0
  int contact_phases = 0; ///< more than 1 when the contact resumed after falling back
  Real contact_time = 0;  ///< tau at the return to u = 0
};

/// e of u'' = g - max(0, u + gamma u') from u = 0, u' = 1, in closed form per phase (header comment).
template <class Real>
exact_linear_clamped_result<Real> exact_linear_clamped(const Real& gamma, const Real& g) {
  using std::abs;
  using std::cos;
  using std::exp;
  using std::sin;
  using std::sqrt;
  require_non_negative(gamma, "gamma");
  require_finite(g, "g");
  const Real xi = gamma / 2;
  const Real lambda = (1 - xi) * (1 + xi);
  const Real root = sqrt(abs(lambda));
  // exp(-xi t) C(t) and exp(-xi t) S(t), overflow-free when overdamped.
  auto damped = [&](const Real& t, Real& c, Real& s) {
    if (lambda > 0) {
      const Real d = exp(-xi * t);
      c = d * cos(root * t), s = d * sin(root * t) / root;
    } else if (lambda < 0) {
      const Real slow = exp((root - xi) * t), fast = exp(-(root + xi) * t);
      c = (slow + fast) / 2, s = (slow - fast) / (2 * root);
    } else {
      const Real d = exp(-xi * t);
      c = d, s = d * t;
    }
  };
  exact_linear_clamped_result<Real> r;
  Real t0 = 0, u0 = 0, v0 = 1;
  // Sampling step: a small part of the period and of the slowest decay time.
  const Real slowest = lambda < 0 ? Real(1 / (xi - root)) : Real(1);
  const Real dt = (lambda > 0 ? Real(Real(1) / (16 * root)) : Real(1) / 16) < slowest / 16
                      ? (lambda > 0 ? Real(Real(1) / (16 * root)) : Real(Real(1) / 16))
                      : Real(slowest / 16);
  while (true) {
    ++r.contact_phases;
    const Real w0 = u0 - g;
    auto state = [&](const Real& t, Real& u, Real& v) {
      Real c, s;
      damped(t, c, s);
      u = g + w0 * c + (v0 + xi * w0) * s;
      v = v0 * c - (w0 + xi * v0) * s;
    };
    auto force = [&](const Real& t) {
      Real u, v;
      state(t, u, v);
      return Real(u + gamma * v);
    };
    Real a = 0, u = u0, v = v0;
    for (long i = 1;; ++i) {
      if (i > 100000000L) throw convergence_error("exact_linear_clamped: no switch found");
      const Real b = Real(i) * dt;
      if (force(b) <= 0) {
        const Real t = detail::bracketed_root(force, a, b, "exact_linear_clamped: force zero");
        state(t, u, v);
        t0 += t;
        break;
      }
      state(b, u, v);
      if (v * v / 2 + u * u / 2 - g * u < 0) {
        r.sticks = true;
        return r;
      }
      a = b;
    }
    // Free flight from the switch (u, v), v < 0.
    const Real discriminant = v * v - 2 * g * u;
    if (!(g > 0) || discriminant > 0) {
      r.e = sqrt(discriminant);
      r.contact_time = t0 + 2 * u / (r.e - v);
      return r;
    }
    const Real t = -2 * (v + gamma * g) / g;
    u0 = u + t * (v + g * t / 2), v0 = v + g * t, t0 += t;
    if (v0 * v0 / 2 + u0 * u0 / 2 - g * u0 < 0) {
      r.sticks = true;
      return r;
    }
  }
}

}  // namespace viscor

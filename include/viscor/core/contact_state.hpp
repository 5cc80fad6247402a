// The state of a bead in contact, named once for the three methods that follow it:
// the Taylor solver (impact/taylor_impact.hpp), the GBS solver
// (impact/adaptive_impact.hpp) and the proof (enclose/proven_impact.hpp).
#pragma once

namespace viscor {

/// A point of the contact u'' + gamma d/dtau(u^beta) + u^alpha = g, u(0) = 0, u'(0) = 1,
/// in scaled variables: overlap u, velocity v = u' = du/dtau, time tau since first
/// contact, and D, the dissipated energy (report eq. 6):
///     D = 2 gamma beta int_0^tau v^2 u^(beta-1) dtau.
/// With E = v^2/2 + u^(alpha+1)/(alpha+1) - g u (E = 1/2 at first contact),
/// 2E + D = 1 along the whole path, so at the end of contact (u = 0, v = -e)
/// D = 1 - e^2, and 1 - e = D/(1 + e) keeps its relative precision as gamma -> 0.
/// This is the one D: the Taylor solver and the proof carry it as it stands; the GBS
/// solver carries D/(2 gamma beta) (its reduced_D) and applies the factor once, at
/// the end.
template <class Real>
struct contact_state {
  Real u;    ///< overlap
  Real v;    ///< velocity u'
  Real tau;  ///< scaled time since first contact
  Real D;    ///< dissipated energy 2 gamma beta int v^2 u^(beta-1) dtau: 1 - e^2 at the end
};

}  // namespace viscor

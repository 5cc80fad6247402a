// The codes' own e -> damping conversions, as the installed programs compute them,
// and their inverses (the deck e that makes the code use a given damping).
//   LAMMPS damping tsuji (pair_coeff / fix wall/gran): the deck's damping entry is
//     taken as e and replaced by the polynomial
//       eta'(e) = 1.2728 - 4.2783 e + 11.087 e^2 - 22.348 e^3 + 27.467 e^4 - 18.022 e^5 + 4.8218 e^6,
//     decreasing on [0, 1] from 1.2728 to 0.0003 (not 0: e = 1 still damps).
//   LIGGGHTS model hertz: coefficientRestitution e gives
//       b(e) = -ln e / sqrt(ln^2 e + pi^2)   (the code keeps the sign; the force uses |b|),
//     which is in [0, 1) for e in (0, 1].
//   YADE Hertz-Mindlin `en`: betan by Thornton et al.'s fit (yade_thornton_betan).
//   YADE ViscElMat(tc, en, et): kn and cn of a linear spring from tc, en and a
//     reduced mass that counts a wall with the bead's mass (yade_viscel_from_tc_en).
// All come from linear-spring or no-load fits; viscor measures how far off they
// are under load (dem_calibration.hpp).
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/scenes/calibration.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/precision.hpp>


namespace viscor::dem {

/// LAMMPS tsuji: the damping number the code derives from the deck's e.
template <class Real>
Real lammps_tsuji_damping(const Real& e) {
  // Horner form of the code's polynomial; coefficients as integer ratios.
  Real p = Real(48218) / 10000;
  p = p * e - Real(18022) / 1000;
  p = p * e + Real(27467) / 1000;
  p = p * e - Real(22348) / 1000;
  p = p * e + Real(11087) / 1000;
  p = p * e - Real(42783) / 10000;
  p = p * e + Real(12728) / 10000;
  return p;
}

/// LIGGGHTS hertz: |b(e)| = -ln e / sqrt(ln^2 e + pi^2), the damping ratio of a linear spring.
template <class Real>
Real liggghts_damping_ratio(const Real& e) {
  using std::log;
  using std::sqrt;
  const Real l = log(e);
  return Real(-l / sqrt(l * l + boost::math::constants::pi<Real>() * boost::math::constants::pi<Real>()));
}

/// YADE 2023.02a Ip2_FrictMat_FrictMat_MindlinPhys with `en`: the betan it derives from
/// the deck's e by the fit of Thornton et al. (2013, eqs. B6-B7),
///   betan = sqrt(1 / (1 - (1 + e)^2 exp(a(e))) - 1),  a(e) = e (h1 + e (h2 + ... + e h10)),
/// with the ten coefficients the code writes as decimals; betan(1) = 0.
template <class Real>
Real yade_thornton_betan(const Real& e) {
  using std::exp;
  using std::sqrt;
  if (e == 1) return Real(0);
  static const char* const h[] = {"-6.918798", "-16.41105", "146.8049", "-796.4559", "2928.711",
                                  "-7206.864", "11494.29",  "-11342.18", "6276.757", "-1489.915"};
  Real a = parse_real<Real>(h[9], "Thornton coefficient");
  for (int i = 8; i >= 0; --i) a = a * e + parse_real<Real>(h[i], "Thornton coefficient");
  a *= e;
  return Real(sqrt(1 / (1 - (1 + e) * (1 + e) * exp(a)) - 1));
}

/// YADE 2023.02a ViscElMat(tc, en, et) on both bodies (Ip2_ViscElMat_ViscElMat_ViscElPhys):
/// the contact's kn = (pi^2 + ln^2 en) m_R / tc^2 and cn = -2 ln(en) m_R / tc, with
/// m_R = m1 m2 / (m1 + m2) where a massless body (a wall) counts with the other's
/// mass: m_R = m/2 on a wall (where the bead's own mass m moves) and for a pair.
template <class Real>
struct yade_viscel_contact {
  Real kn = 0;  ///< N/m
  Real cn = 0;  ///< N s/m
};

/// The contact's kn, cn YADE derives from tc, en and the reduced mass m_R (above).
template <class Real>
yade_viscel_contact<Real> yade_viscel_from_tc_en(const Real& tc, const Real& en, const Real& reduced_mass) {
  using std::log;
  const Real l = log(en), pi = boost::math::constants::pi<Real>();
  return {Real((pi * pi + l * l) * reduced_mass / (tc * tc)), Real(-2 * l * reduced_mass / tc)};
}

/// The tc for which YADE's kn (yade_viscel_from_tc_en) equals the stiffness kn, N/m.
template <class Real>
Real yade_viscel_tc_for_stiffness(const Real& kn, const Real& en, const Real& reduced_mass) {
  using std::log;
  using std::sqrt;
  const Real l = log(en), pi = boost::math::constants::pi<Real>();
  return Real(sqrt((pi * pi + l * l) * reduced_mass / kn));
}

/// The e in [0, 1] whose LAMMPS tsuji polynomial equals `damping`; unreachable_target
/// outside [eta'(1), eta'(0)] = [0.0003, 1.2728].
template <class Real>
Real lammps_tsuji_deck_e(const Real& damping) {
  using std::abs;
  require_finite(damping, "damping");
  const Real lo_value = lammps_tsuji_damping(Real(1)), hi_value = lammps_tsuji_damping(Real(0));
  if (damping < lo_value || damping > hi_value)
    throw unreachable_target("LAMMPS tsuji damping " + to_decimal_string(damping) +
                             " is outside what a deck e in [0, 1] gives, [" + to_decimal_string(lo_value) + ", " +
                             to_decimal_string(hi_value) + "]");
  // NOTE: plain bisection down to two neighbouring numbers, then the one whose polynomial
  // is nearer: the C export (jobs/dem_export) states the same steps in C, so the deck e is
  // the same bits there. The polynomial decreases on [0, 1] (checked on a 1001-point grid,
  // see docs/dem.md); the iteration cap only guards a type whose midpoints never settle.
  Real lo = 0, hi = 1;  // lammps_tsuji_damping(lo) >= damping >= lammps_tsuji_damping(hi)
  for (int i = 0; i < 4 * boost::math::tools::digits<Real>() + 1100; ++i) {
    const Real mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    if (lammps_tsuji_damping(mid) >= damping)
      lo = mid;
    else
      hi = mid;
  }
  return abs(lammps_tsuji_damping(hi) - damping) < abs(lammps_tsuji_damping(lo) - damping) ? hi : lo;
}

/// The e whose LIGGGHTS damping ratio is b, for b in [0, 1): e = exp(-pi b / sqrt(1 - b^2)).
template <class Real>
Real liggghts_deck_e(const Real& b) {
  using std::exp;
  using std::sqrt;
  require_non_negative(b, "damping ratio");
  if (!(b < 1))
    throw unreachable_target("LIGGGHTS damping ratio " + to_decimal_string(b) +
                             " needs b < 1: no coefficientRestitution in (0, 1] gives it");
  return Real(exp(-boost::math::constants::pi<Real>() * b / sqrt(1 - b * b)));
}

}  // namespace viscor::dem

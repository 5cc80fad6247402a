#!/usr/bin/env python3
"""Reference values of the scaling of eq. (2), computed outside the library.

The physical model (docs/dem.md; docs/report-notes.md on the report's scaling): a bead of mass m on a
wall, overlap x(t) >= 0, force F_c = k x^alpha + gamma0 k d/dt(x^beta), gravity and a
constant force F pressing it on the wall:

    m x'' + gamma0 k d/dt(x^beta) + k x^alpha = m gravity + F,   x(0) = 0, x'(0) = v0.

With x = delta u, t = T tau and delta = v0 T (so u'(0) = 1), dividing by k delta^alpha:

    (m delta / (k delta^alpha T^2)) u'' + (gamma0 delta^(beta - alpha) / T) (u^beta)' + u^alpha
        = (m gravity + F) / (k delta^alpha).

T is chosen so that the first coefficient is 1: T^(alpha+1) = (m/k) v0^(1-alpha). Then
    gamma = gamma0 delta^(beta-alpha) / T,   g = (m gravity + F) / (k delta^alpha).
This script evaluates these expressions (not the closed exponents of
include/viscor/core/scaling.hpp) with mpmath at 130 digits, checks that the leading
coefficient is 1, and writes tests/data/scaling_reference.csv. Materials given by E, nu,
R, rho hit a rigid wall: k = (4/3) E/(1 - nu^2) sqrt(R), m = (4/3) pi R^3 rho.

Usage: python3 tools/scaling_reference.py > tests/data/scaling_reference.csv
"""

import sys

import mpmath

mpmath.mp.dps = 130  # printed to 110 digits: enough for the 100-digit types under test
LAWS = {  # name: (alpha, beta)
    "linear": ("1", "1"),
    "hertz_linear_damping": ("3/2", "1"),
    "tsuji": ("3/2", "5/4"),
    "kuwabara_kono": ("3/2", "3/2"),
    "hunt_crossley": ("3/2", "5/2"),
}


def q(s):
    """A decimal or a fraction 'p/q', exactly."""
    if "/" in s:
        p, d = s.split("/")
        return mpmath.mpf(p) / mpmath.mpf(d)
    return mpmath.mpf(s)


def wall_bead(E, nu, R, rho):
    k = mpmath.mpf(4) / 3 * q(E) / (1 - q(nu) ** 2) * mpmath.sqrt(q(R))
    m = mpmath.mpf(4) / 3 * mpmath.pi * q(R) ** 3 * q(rho)
    return m, k


def scale(law, m, k, gamma0, v0, gravity, force):
    alpha, beta = (q(x) for x in LAWS[law])
    T = ((m / k) * v0 ** (1 - alpha)) ** (1 / (alpha + 1))
    delta = v0 * T
    leading = m * delta / (k * delta**alpha * T**2)
    assert abs(leading - 1) < mpmath.mpf(10) ** -120, leading
    gamma = gamma0 * delta ** (beta - alpha) / T
    g = (m * gravity + force) / (k * delta**alpha)
    return gamma, g, T


def cases():
    """(case, law, m, k, gamma0, v0, gravity, F) as mpf; the tests look cases up by name."""
    every = list(LAWS)
    # The report's 8 mm steel bead (sec. 4.1) and the glass bead of its Fig. 2(b), with a force.
    for law in every:
        yield ("steel_bead", law, q("2.05e-3"), q("6.9716e9"), q("8.49e-7"), q("0.246"), q("9.8"), q("0"))
        yield ("heavy_bead_force", law, q("0.154"), q("3.6138e10"), q("1.5237e-6"), q("1"), q("9.80665"),
               q("0.0375"))
        yield ("light_fast_pull", law, q("1e-6"), q("2.5e7"), q("3e-5"), q("7.5"), q("0"), q("-2e-6"))
    # Unit damping (gamma = the damping factor): calibration and DEM tests divide by it.
    for law in every:
        yield ("steel_bead_unit_damping", law, q("2.05e-3"), q("6.9716e9"), q("1"), q("0.246"), q("9.8"), q("0"))
    # The scene of tests/scene_test.cpp: steel E = 2.0e11, nu = 0.3, R = 4 mm, rho = 7850, on a rigid wall.
    m, k = wall_bead("2.0e11", "0.3", "4e-3", "7850")
    for v0 in ("0.1", "0.246", "1"):
        yield ("scene_steel_v" + v0, "kuwabara_kono", m, k, q("8.5e-7"), q(v0), q("9.8"), q("0"))
    # The DEM bead of tests/dem_cli_test.cpp: E = 2e11, nu = 0.3, R = 1 mm, rho = 7800, wall, v0 = 0.01.
    m, k = wall_bead("2e11", "0.3", "1e-3", "7800")
    for law in ("hertz_linear_damping", "tsuji", "kuwabara_kono"):
        yield ("dem_steel_wall_unit_damping", law, m, k, q("1"), q("0.01"), q("9.81"), q("0"))


def main():
    out = sys.stdout
    out.write("# Scaled gamma, g and time scale T of eq. (2), computed outside the library by\n"
              "# tools/scaling_reference.py (mpmath, 130 digits; printed to 110):\n"
              "#   python3 tools/scaling_reference.py > tests/data/scaling_reference.csv\n"
              "# SI units: m kg, k N/m^alpha, gamma0 such that gamma0 k d/dt(x^beta) is a force, v0 m/s, gravity m/s^2, F N, T s.\n")
    out.write("case,law,m,k,gamma0,v0,gravity,F,gamma,g,T\n")
    for case, law, m, k, gamma0, v0, gravity, force in cases():
        gamma, g, T = scale(law, m, k, gamma0, v0, gravity, force)
        fields = [case, law] + [mpmath.nstr(x, 110, min_fixed=0, max_fixed=0)
                                for x in (m, k, gamma0, v0, gravity, force, gamma, g, T)]
        out.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()

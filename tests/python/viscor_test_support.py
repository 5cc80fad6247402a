"""Shared helpers of the Python tests: where the repository, its committed tables
and the CLI are (ctest sets VISCOR_SOURCE_DIR and VISCOR_CLI), and the linear
law's closed form, written here from the model (not from the library)."""

import csv
import os

SOURCE_DIR = os.environ.get("VISCOR_SOURCE_DIR",
                            os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
REFERENCE_DATA = os.path.join(SOURCE_DIR, "reference_data")
CLI = os.environ.get("VISCOR_CLI", "")

# CMake's VISCOR_REQUIRE_ALL_DEPS=ON (CI): what a test needs must be there; a missing
# module or committed file fails the test, naming it, instead of skipping it.
REQUIRE_ALL_DEPS = os.environ.get("VISCOR_REQUIRE_ALL_DEPS") == "1"


def optional_module(name, package):
    """The module, or None (its tests skip); raises naming the Debian package when all are required."""
    import importlib
    try:
        return importlib.import_module(name)
    except ImportError:
        if REQUIRE_ALL_DEPS:
            raise ImportError(f"VISCOR_REQUIRE_ALL_DEPS=1 but the Python module {name} is missing "
                              f"(apt-get install {package})") from None
        return None


def skip_or_fail(test, missing):
    """Skips `test` for lack of `missing`; fails it instead when all dependencies are required."""
    if REQUIRE_ALL_DEPS:
        test.fail(f"VISCOR_REQUIRE_ALL_DEPS=1 but missing: {missing}")
    test.skipTest(missing)


numpy = optional_module("numpy", "python3-numpy")  # None: the vectorised tests skip
mpmath = optional_module("mpmath", "python3-mpmath")


def reference_rows(name="cor_report_grid.csv"):
    """Rows of a committed certified table (reference_data/, provenance in its .json sidecar)."""
    with open(os.path.join(REFERENCE_DATA, name), newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def _mp(x):
    """str ('0.05', '1/3'), Fraction or int as mpf at the current precision."""
    import fractions
    f = fractions.Fraction(x)
    return mpmath.mpf(f.numerator) / f.denominator


def linear_law_e(gamma, g, dps=70):
    """e of u'' + gamma u' + u = g, u(0) = 0, u'(0) = 1 (underdamped, gamma < 2; gamma and g as str, Fraction or int) at
    the first return to u = 0, from the solution
        u(t) = g + exp(-gamma t / 2) (A cos(w t) + B sin(w t)),  w = sqrt(1 - gamma^2 / 4),
        A = -g, B = (1 - gamma g / 2) / w,
    with mpmath at `dps` digits. Returns (e, contact_time); e = 0 if it never returns
    (the first local maximum of -u', i.e. of the return, is not reached; not used here)."""
    with mpmath.workdps(dps):
        gm, gg = _mp(gamma), _mp(g)
        w = mpmath.sqrt(1 - gm**2 / 4)
        A, B = -gg, (1 - gm * gg / 2) / w

        def u(t):
            return gg + mpmath.exp(-gm * t / 2) * (A * mpmath.cos(w * t) + B * mpmath.sin(w * t))

        def du(t):
            s, c = mpmath.sin(w * t), mpmath.cos(w * t)
            return mpmath.exp(-gm * t / 2) * ((-gm / 2) * (A * c + B * s) + w * (-A * s + B * c))

        # The return lies after the maximum (du = 0, at t < pi / w) and before 2 pi / w:
        # bracket it on a grid, then refine.
        t_prev, u_prev = None, None
        n = 2000
        t_max = 2 * mpmath.pi / w
        for k in range(1, n + 1):
            t = t_max * k / n
            ut = u(t)
            if u_prev is not None and u_prev > 0 and ut <= 0:
                root = mpmath.findroot(u, (t_prev, t), solver="anderson")
                return -du(root), root
            t_prev, u_prev = t, ut
        raise ValueError("no return to u = 0 within 2 pi / w")


def write_synthetic_surrogate(path, G=0.5, abs_e=1e-3, safety_factor=4):
    """A surrogate file for the linear law whose values are known by construction,
    to test the plumbing (not a fit): one low-load patch on gamma in [0, 0.5],
    g in [0, 1] with the constant G = (1 - e^2) / gamma, so e = sqrt(1 - G gamma),
    and a claimed, 'verified' bound abs_e (safety_factor 0: unverified, nothing claimed). The format is that of
    include/viscor/surrogate/cor_surrogate.hpp (write_cor_surrogate)."""
    tree = "{name} 0 0.5 0 1 2 1 1\n2 0 0\n0.25 4 0.5 2\n{c} 0\n0 0\n"
    with open(path, "w") as f:
        f.write("viscor-cor-surrogate 1\nlaw linear 1 1\ndomain 0.5 0 1\nsplit 1.5 1\n"
                f"bound {abs_e!r} {abs_e!r} {abs_e!r} {safety_factor!r}\nthreshold 2 2\n0 1\n0 0\n"
                + tree.format(name="low_load", c=repr(G)) + tree.format(name="high_load", c="0") + "end\n")
    return path

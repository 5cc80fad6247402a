"""viscor: certified coefficient of restitution of visco-elastic impacts under load.

Python bindings of the C++ library (docs/python.md). Scaled model:
    u'' + gamma d/dtau(u_+^beta) + u_+^alpha = g,  u(0) = 0, u'(0) = 1;  e = -u'(T_f).

    >>> import viscor
    >>> r = viscor.cor('kuwabara_kono', '0.05', '1', digits=50)
    >>> r.e                      # a float, the double nearest to the 50-digit value
    >>> r.e_exact                # the exact decimal string at 50 digits
    >>> r.decimal('one_minus_e')  # decimal.Decimal

Field names are those of the JSON output (docs/json-schema.md); quantities read as
numbers, their exact decimals as NAME_exact. Bad input raises
InvalidParameter (a ValueError) with the library's message.
"""

import os as _os
import numbers as _numbers

from . import _viscor
from ._viscor import (CertificationError, ConvergenceError, Error, InvalidParameter, ParseError,
                      PrecisionUnavailable, Surrogate)
from ._inputs import NAMED_LAWS, check_digits as _check_digits, law_texts as _law_texts, number_text as _text
from ._result import Result
from ._table import Table
from ._commands import (Points, Scene, approx, calibrate, cor_points, dem, exact, run_cli, scale, scene, table, read_table,
                        find_surrogate)
from ._evaluate import EVALUATION_METHODS, Evaluation, evaluate
from ._surrogate_export import export_surrogates
from ._formula import FormulaCheck, PointCheck, compare, plot_formula_check

try:  # written by cmake --install: the installed data directory (the build tree's module reads reference_data/)
    from ._installed import DATA_DIR as _INSTALLED_DATA_DIR
    if not _os.environ.get("VISCOR_DATA") and _os.path.isdir(_INSTALLED_DATA_DIR):
        _os.environ["VISCOR_DATA"] = _INSTALLED_DATA_DIR
except ImportError:
    pass

__version__ = _viscor.version
git_commit = _viscor.git_commit
max_working_digits = _viscor.max_working_digits

__all__ = ["cor", "cor_points", "Points", "exact", "approx", "calibrate", "scale", "table", "read_table", "scene", "dem", "evaluate",
           "Evaluation", "EVALUATION_METHODS", "Surrogate", "find_surrogate", "export_surrogates", "run_cli", "Result", "Table", "Scene", "NAMED_LAWS", "compare", "FormulaCheck", "PointCheck", "plot_formula_check",
           "Error", "InvalidParameter", "PrecisionUnavailable", "ParseError", "ConvergenceError",
           "CertificationError", "data_directory"]


_SCALED_LOAD_NOT_GIVEN = object()  # cor()'s g when the caller gave none (0 in scaled mode)


def cor(law=None, gamma=None, g=_SCALED_LOAD_NOT_GIVEN, digits=None, certify=False, *, alpha=None, beta=None,
        method="taylor", tolerance="0", max_steps=None, strict=False, certified_digits=None, **physical):
    """The coefficient of restitution of one impact at `digits` working digits (default
    50), or with `certified_digits` certified digits.

    law: a name (NAMED_LAWS), or alpha= and beta= (str such as '3/2', Fraction, int,
    Decimal). gamma, g (default 0): the scaled damping and load, str, int, Decimal,
    Fraction or float (a float is its exact binary value). Or, instead of gamma and
    g, the physical inputs as ``viscor cor`` takes them: m (kg) and k (N/m^alpha),
    or youngs_modulus (Pa), poisson_ratio, radius (m) and m or density (kg/m^3);
    v0 (m/s), gamma0 (SI), gravity (m/s^2, required: 0 for none) and force (N,
    default 0); strict=True refuses inputs far outside their plausible range. A
    wall of its own material: wall_youngs_modulus, wall_poisson_ratio; two beads:
    contact='pair' (gravity drops out, force presses them together) and, for a
    second bead unlike the first, other_youngs_modulus, other_poisson_ratio,
    other_radius, other_density.
    certify=True adds ``certified`` (the digits three computations agree on, four
    where the adaptive one is repeated at the reference precision), as ``viscor cor
    --certify``. certified_digits=N (instead of digits) asks for at least N certified
    digits of e, 1 - e, contact_time and max_compression, as ``viscor cor
    --certified-digits N``: the working precision is chosen and raised until they are
    certified (``certified_digits_goal`` and ``precision_runs`` say how), or
    CertificationError says how many could be. Returns a Result with the fields of ``viscor cor --json``: e,
    one_minus_e, outcome, contact_time, max_compression, time_of_max_compression,
    energy_residual, error_estimate, steps, method, seconds, gamma, g, law,
    precision (and stop_overlap for a stick; physical, time_scale_s,
    length_scale_m, contact_time_s, max_compression_m in physical mode).
    """
    from ._commands import PHYSICAL_INPUTS, physical_text
    for key in physical:
        if key not in PHYSICAL_INPUTS:
            raise TypeError(f"cor() got an unexpected keyword argument {key!r}")
    physical = {k: physical_text(v, k) for k, v in physical.items() if v is not None}
    if gamma is None and not physical:
        raise TypeError("cor() needs gamma (and g), or the physical inputs m, k, v0, gamma0, gravity")
    if physical and (gamma is not None or g is not _SCALED_LOAD_NOT_GIVEN):
        raise InvalidParameter("give either the physical inputs (" + ", ".join(physical) +
                               ") or the scaled gamma and g, not both")
    name, a, b = _law_texts(law, alpha, beta)
    if not isinstance(certify, bool):
        raise TypeError(f"certify must be True or False, got {certify!r}")
    if not isinstance(strict, bool):
        raise TypeError(f"strict must be True or False, got {strict!r}")
    if method not in ("taylor", "adaptive"):
        raise InvalidParameter(f"method must be 'taylor' or 'adaptive', got {method!r}")
    if certified_digits is not None:
        if digits is not None:
            raise InvalidParameter("give either digits (the working precision) or certified_digits (the working "
                                   "precision is then chosen), not both")
        if isinstance(certified_digits, bool) or not isinstance(certified_digits, _numbers.Integral):
            raise TypeError(f"certified_digits must be a whole number, got {type(certified_digits).__name__} "
                            f"({certified_digits!r})")
        certified_digits = int(certified_digits)  # its range: the library's (certify_to_goal)
    digits = 50 if digits is None else digits
    if max_steps is None:
        max_steps = 0  # the library's default
    elif isinstance(max_steps, bool) or not isinstance(max_steps, int) or not 1 <= max_steps <= 10**12:
        raise InvalidParameter(f"max_steps must be a whole number from 1 to 1e12, got {max_steps!r}")
    if physical:
        return Result(_viscor.physical_cor(name, a, b, physical, _check_digits(digits), certified_digits, certify, method,
                                           _text(tolerance, "tolerance"), max_steps, strict))
    g = 0 if g is _SCALED_LOAD_NOT_GIVEN else g
    fields = _viscor.cor(name, a, b, _text(gamma, "gamma"), _text(g, "g"), _check_digits(digits), certified_digits,
                         certify, method, _text(tolerance, "tolerance"), max_steps)
    return Result(fields)


def data_directory():
    """The data directory in use (certified tables, error maps): $VISCOR_DATA, the
    installed share/viscor, or the source tree's reference_data/."""
    return _viscor.data_directory()

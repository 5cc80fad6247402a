"""Vectorised evaluation in double over NumPy arrays (scenes/evaluate.hpp)."""

import collections
import os

from . import _viscor
from ._inputs import law_texts

#: Names of the codes in Evaluation.method: evaluate's methods in its order of cost
#: (docs/scenes.md), then 'surrogate'.
EVALUATION_METHODS = tuple(_viscor.evaluation_methods)

Evaluation = collections.namedtuple("Evaluation", "e one_minus_e empirical_bound method outcome")
Evaluation.__doc__ = """Arrays of the broadcast shape of (gamma, g, tol):
e, one_minus_e, empirical_bound (float64; absolute on e, or relative on 1 - e with
relative=True), method (int8 codes into EVALUATION_METHODS), outcome (int8: 0
rebound, 1 stick, 2 undecided)."""


_committed_surrogates = {}


def _committed_surrogate(name):
    """find_surrogate(name), read once per process and surrogate directory:
    parsing a coefficient file costs milliseconds, an evaluation nanoseconds."""
    from ._commands import find_surrogate, surrogate_directory
    key = (name, surrogate_directory())
    if key not in _committed_surrogates:
        _committed_surrogates[key] = find_surrogate(name)
    return _committed_surrogates[key]


def _scaled_from_physical(name, a, b, tol, physical, strict):
    """(gamma, g, tol) arrays from arrays of physical inputs, broadcast together."""
    import numpy as np

    contact = physical.pop("contact", "wall")
    if not isinstance(contact, str):
        raise TypeError(f"evaluate: contact must be 'wall' or 'pair', got {contact!r}")
    # Which inputs are needed with which is the library's rule (physical_inputs::check_complete),
    # applied to these names by _viscor.scaled_arrays.
    names = list(physical)
    try:
        arrays = [np.asarray(physical[k], dtype=np.float64) for k in names] + [np.asarray(tol, dtype=np.float64)]
    except (TypeError, ValueError) as error:
        raise TypeError(f"evaluate: the physical inputs must be numbers or arrays of numbers") from error
    try:
        broadcast = np.broadcast_arrays(*arrays)
    except ValueError as error:
        raise _viscor.InvalidParameter("evaluate: the physical inputs and tol do not broadcast together ("
                                       + ", ".join(f"{k} {x.shape}" for k, x in zip(names + ["tol"], arrays))
                                       + ")") from error
    shape = broadcast[0].shape
    columns = {k: np.ascontiguousarray(x).reshape(-1) for k, x in zip(names, broadcast[:-1])}
    gamma, g = _viscor.scaled_arrays(name, a, b, columns, contact, strict)
    return gamma.reshape(shape), g.reshape(shape), broadcast[-1]


#: The physical inputs evaluate takes instead of gamma and g (as ``viscor cor`` names them).
_PHYSICAL = ("m", "k", "v0", "gamma0", "gravity", "force", "youngs_modulus", "poisson_ratio", "radius", "density",
             "contact", "wall_youngs_modulus", "wall_poisson_ratio", "other_youngs_modulus", "other_poisson_ratio",
             "other_radius", "other_density")


def evaluate(law=None, gamma=None, g=0.0, tol=1e-6, *, alpha=None, beta=None, relative=False, error_maps="default",
             surrogate="default", threads=0, strict=False, **physical):
    """e with an empirical error bound <= tol at every point, over arrays.

    gamma, g, tol: array-likes of float64, broadcast together (NumPy rules). Each
    point is evaluate()d by the cheapest method whose bound meets its tol
    (docs/scenes.md): an approximation inside an error map's cell, a closed form,
    a Taylor solve. error_maps: 'default' (the data directory's error_maps/),
    None (no approximations) or a directory. surrogate: 'default' (the
    committed surrogate of a named law when there is one, as `viscor scene`
    does; none otherwise), None (no surrogate), True (the committed surrogate
    of the law, docs/surrogate.md; an error if there is none), a path or a
    Surrogate; it is used first wherever its verified bound meets tol.
    threads: worker threads (0: every core); the GIL is released.

    Instead of gamma and g, the physical inputs as ``viscor cor`` takes them, each
    a number or an array (broadcast together with tol): m and k, or
    youngs_modulus, poisson_ratio, radius and m or density; v0, gamma0, gravity
    (required: 0 for none) and force (default 0); a wall of its own material
    (wall_youngs_modulus, wall_poisson_ratio), or contact='pair' (a second bead
    like the first, or other_youngs_modulus, other_poisson_ratio, other_radius,
    other_density; gravity drops out). They are scaled in double. Inputs far
    outside their quantity's range (a unit slip) are warned about on stderr as
    viscor.cor warns, naming the point; strict=True refuses them.

    Raises InvalidParameter naming the first bad point (NaN, gamma < 0, ...).
    """
    import numpy as np

    for key in physical:
        if key not in _PHYSICAL:
            raise TypeError(f"evaluate() got an unexpected keyword argument {key!r}")
    physical = {k: v for k, v in physical.items() if v is not None}
    name, a, b = law_texts(law, alpha, beta)
    if physical:
        if gamma is not None:
            raise _viscor.InvalidParameter("evaluate: give either the physical inputs (" + ", ".join(physical) +
                                           ") or the scaled gamma and g, not both")
        if not isinstance(strict, bool):
            raise TypeError(f"strict must be True or False, got {strict!r}")
        gamma, g, tol = _scaled_from_physical(name, a, b, tol, physical, strict)
    if gamma is None:
        raise TypeError("evaluate() needs gamma")
    arrays = []
    for label, value in (("gamma", gamma), ("g", g), ("tol", tol)):
        try:
            arrays.append(np.asarray(value, dtype=np.float64))
        except (TypeError, ValueError) as error:
            raise TypeError(f"evaluate: {label} must be numbers or an array of numbers, got {value!r}") from error
    try:
        gamma_b, g_b, tol_b = np.broadcast_arrays(*arrays)
    except ValueError as error:
        raise _viscor.InvalidParameter(f"evaluate: gamma {arrays[0].shape}, g {arrays[1].shape} and tol "
                                       f"{arrays[2].shape} do not broadcast together") from error
    shape = gamma_b.shape
    flat = [np.ascontiguousarray(x).reshape(-1) for x in (gamma_b, g_b, tol_b)]

    if error_maps == "default":
        maps = _viscor.default_error_maps()
    elif error_maps is None:
        maps = ""
    else:
        maps = os.fspath(error_maps)
    if surrogate == "default":
        surrogate = _committed_surrogate(name) if name else None
    elif surrogate is True:
        surrogate = _committed_surrogate(name) if name else None
        if surrogate is None:
            raise _viscor.InvalidParameter(f"evaluate: no committed surrogate for law {law!r} (docs/surrogate.md)")
    elif surrogate is not None and not isinstance(surrogate, _viscor.Surrogate):
        surrogate = _viscor.Surrogate(os.fspath(surrogate))
    if isinstance(threads, bool) or not isinstance(threads, int) or threads < 0:
        raise _viscor.InvalidParameter(f"evaluate: threads must be a whole number >= 0, got {threads!r}")

    evaluator = _viscor.Evaluator(name, a, b, bool(relative), maps, surrogate, threads)
    e, one_minus_e, bound, method, outcome = evaluator(*flat)
    return Evaluation(*(x.reshape(shape) for x in (e, one_minus_e, bound, method, outcome)))

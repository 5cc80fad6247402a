"""Regression tests of a CoR formula of your own (docs/formulas.md): compare().

Every check has one truth rule: ``bool(check)`` is its verdict, and a check that
judged nothing is false and says why (``check.reason``)."""

from . import _viscor
from ._inputs import number_text
from ._result import Result


class FormulaCheck(Result):
    """The check of a formula against the certified tables (the fields of ``viscor
    formula check --json``, numbers as numbers): pass, failed_cells, coverage,
    overall, cells (each with max_abs_e, median_abs_e, max_rel_one_minus_e, worst,
    outcome mismatches, pass). ``bool(check)`` is the verdict: false when a cell
    fails and when no cell was judged (``check.reason`` says which).
    ``str(check)`` is the readable summary; ``check.plot()`` draws the error map."""

    __slots__ = ()

    def __bool__(self):
        return self._fields["pass"] is True

    def __str__(self):
        return self._fields["text"]

    @property
    def reason(self):
        """Why the check is false ("" when it passes)."""
        if self:
            return ""
        if "reason" in self._fields:
            return self._fields["reason"]
        return f"{self._fields['failed_cells']} cell(s) fail"

    def column(self, name):
        """Field `name` of every cell as a NumPy array: float64 for numbers (NaN where
        absent), bool for `pass`, str for `outcome` (a pandas-free table)."""
        import numpy as np
        values = [c.get(name) for c in self._fields["cells"]]
        if name == "pass":
            return np.array(values, dtype=bool)
        if name == "outcome":
            return np.array(values, dtype=str)
        return np.array([float(v) if v not in (None, "") else float("nan") for v in values], dtype=np.float64)

    def plot(self, path=None, ax=None):
        """The per-cell largest |de| as a map over (gamma, g), failing cells outlined
        in red; saved to `path` when given. Returns the matplotlib Axes."""
        return plot_formula_check(self.to_dict(), path, ax)


class PointCheck:
    """A formula against evaluate() at points outside the tables: arrays of the
    broadcast shape (gamma, g, value, truth, abs_error, bound, bound_kind, method,
    passed); bound_kind says what the truth's bound is ('empirical': evaluate's
    error maps and solver estimates, not certified).

    A point passes when abs_error + bound <= tolerance (the formula is within the
    tolerance of the truth even where the truth is off by its bound) and its value is
    finite. ``bool(check)`` is the verdict: every point passes, and there is at least
    one point; ``check.reason`` says why it is false."""

    __slots__ = ("gamma", "g", "value", "truth", "abs_error", "bound", "bound_kind", "method", "tolerance", "passed")
    _fields = ("gamma", "g", "value", "truth", "abs_error", "bound", "bound_kind", "method")

    def __init__(self, gamma, g, value, truth, abs_error, bound, bound_kind, method, tolerance):
        import numpy as np
        for name, array in zip(self._fields, (gamma, g, value, truth, abs_error, bound, bound_kind, method)):
            object.__setattr__(self, name, array)
        object.__setattr__(self, "tolerance", tolerance)
        passed = np.isfinite(value) & np.isfinite(truth) & (abs_error + bound <= tolerance)
        object.__setattr__(self, "passed", passed)

    def __setattr__(self, name, value):
        raise AttributeError("viscor checks are read-only")

    def __bool__(self):
        return bool(self.passed.size > 0 and self.passed.all())

    @property
    def reason(self):
        """Why the check is false ("" when it passes)."""
        if self.passed.size == 0:
            return "no point judged: gamma and g hold no point"
        failed = int(self.passed.size - self.passed.sum())
        if failed == 0:
            return ""
        import numpy as np
        worst = float(np.nanmax(np.where(self.passed, -np.inf, self.abs_error + self.bound))) if failed else 0.0
        return (f"{failed} of {self.passed.size} point(s) fail: |de| + the truth's bound up to {worst:.3g} "
                f"(or not finite), tolerance {self.tolerance:.3g}")

    def __repr__(self):
        verdict = "pass" if self else "FAIL: " + self.reason
        return f"viscor.PointCheck({self.passed.size} points, tolerance {self.tolerance:.3g}, {verdict})"


def compare(fn, law, tol, *, quantity="e", region=None, gamma=None, g=None):
    """Checks a formula of e(gamma, g) against the certified e of a named law.

    fn takes NumPy float64 arrays gamma and g and returns e (or 1 - e with
    quantity='one_minus_e'). It is evaluated at the certified points that the law's
    committed error map was built from, and judged cell by cell of that map
    (|de| <= tol, outcomes right): a FormulaCheck, true when every judged cell
    passes and at least one cell was judged. tol is in [0, 1) (as the CLI's
    --tolerance). region=(gamma_min, gamma_max, g_min, g_max) keeps only the cells
    inside; None for an unbounded side.

    With gamma= and g= (array-likes, broadcast): points outside the tables, against
    evaluate() at tolerance tol / 10 instead: a PointCheck whose bounds are
    empirical, not certified, true when every point is within tol.
    """
    import numpy as np

    if not callable(fn):
        raise TypeError(f"compare() needs a function of (gamma, g), got {fn!r}")
    if quantity not in ("e", "one_minus_e"):
        raise _viscor.InvalidParameter(f"compare: quantity must be 'e' or 'one_minus_e', got {quantity!r}")
    tol_text = number_text(tol, "tolerance")
    tolerance = _viscor.formula_tolerance(tol_text)
    if gamma is not None or g is not None:
        if region is not None:
            raise _viscor.InvalidParameter("compare: give region= (certified cells) or gamma= and g= (points), not both")
        return _compare_with_evaluate(fn, law, tolerance, quantity, gamma, g)
    if region is None:
        region = (None, None, None, None)
    if len(region) != 4:
        raise _viscor.InvalidParameter(f"compare: region is (gamma_min, gamma_max, g_min, g_max), got {region!r}")
    names = ("gamma_min", "gamma_max", "g_min", "g_max")
    where = ["" if x is None else number_text(x, name) for x, name in zip(region, names)]
    points_gamma, points_g = _viscor.formula_points(law)
    values = np.asarray(fn(points_gamma.copy(), points_g.copy()), dtype=np.float64)
    if values.shape != points_gamma.shape:
        raise _viscor.InvalidParameter(f"compare: fn returned shape {values.shape} for {points_gamma.shape} points")
    return FormulaCheck(_viscor.compare_formula(law, values, quantity, tol_text, where))


def _compare_with_evaluate(fn, law, tol, quantity, gamma, g):
    import numpy as np
    from ._evaluate import EVALUATION_METHODS, evaluate

    gamma, g = np.broadcast_arrays(np.asarray(gamma, dtype=np.float64), np.asarray(g, dtype=np.float64))
    truth = evaluate(law, gamma, g, tol=tol / 10)
    values = np.asarray(fn(gamma.copy(), g.copy()), dtype=np.float64)
    if values.shape != gamma.shape:
        values = np.broadcast_to(values, gamma.shape)  # a constant formula, say
    e = values if quantity == "e" else 1 - values
    method = np.array([EVALUATION_METHODS[k] for k in truth.method.reshape(-1)]).reshape(truth.method.shape)
    return PointCheck(gamma, g, e, truth.e, np.abs(e - truth.e), truth.empirical_bound,
                      np.full(gamma.shape, "empirical"), method, tol)


def plot_formula_check(check, path=None, ax=None):
    """Draws a check (a FormulaCheck, its dict, or the path of ``viscor formula check
    -o FILE.json``): the largest |de| per cell over log gamma and g, failing cells
    outlined in red."""
    import json
    import math

    import matplotlib
    if path is not None and ax is None:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm
    from matplotlib.patches import Rectangle

    if isinstance(check, str):
        with open(check) as f:
            check = json.load(f)
    elif isinstance(check, Result):
        check = check.to_dict()
    cells = check["cells"]
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 5))
    errors = [float(c["max_abs_e"]) for c in cells if c.get("outcome") != "mixed"]
    positive = [x for x in errors if x > 0] or [1e-16]
    norm = LogNorm(vmin=max(min(positive), 1e-16), vmax=max(max(positive), 1e-15))
    cmap = plt.get_cmap("viridis")
    for c in cells:
        x0, x1, y0, y1 = (float(c[k]) for k in ("gamma_lo", "gamma_hi", "g_lo", "g_hi"))
        mixed = c.get("outcome") == "mixed"
        err = float(c["max_abs_e"])
        face = "lightgrey" if mixed else cmap(norm(max(err, norm.vmin)))
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, facecolor=face,
                               edgecolor="red" if not c["pass"] else "white", linewidth=2 if not c["pass"] else 0.5))
    xs = [float(c[k]) for c in cells for k in ("gamma_lo", "gamma_hi")]
    ys = [float(c[k]) for c in cells for k in ("g_lo", "g_hi")]
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=max(1e-4, min([y for y in ys if y > 0] or [1e-4])))
    ax.set_xlim(min(x for x in xs if x > 0), max(xs))
    ax.set_ylim(min(ys), max(ys))
    ax.set_xlabel("γ (scaled damping)")
    ax.set_ylabel("g (scaled load)")
    law = check["law"]["name"] or f"alpha={check['law']['alpha']}, beta={check['law']['beta']}"
    verdict = "pass" if check["pass"] else f"{check['failed_cells']} cell(s) fail"
    ax.set_title(f"{law}: max |Δe| per cell, tolerance {float(check['tolerance']):.1e} ({verdict}; grey: threshold cells)")
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="max |e_formula − e_certified|")
    if path is not None:
        ax.figure.savefig(path, dpi=120, bbox_inches="tight")
    return ax

"""The subcommands that read or write files, or convert units, run in-process.

Each function runs the CLI's own code (`viscor <command> ... --json`) inside this
process, so options, files, messages and JSON field names are exactly the
CLI's (docs/cli.md, docs/json-schema.md). Keyword arguments are the CLI's
options with '-' written '_' (gravity=9.8, youngs_modulus='2e11', target_e='0.9');
None leaves an option out, True gives a flag.
"""

import csv
import json
import os

from . import _viscor
from ._viscor import InvalidParameter
from ._inputs import check_digits, law_texts, number_text
from ._result import Result
from ._table import Table


def run_cli(*args):
    """Runs ``viscor ARGS...`` in this process and returns what it prints.

    Errors raise the exceptions of viscor (InvalidParameter for bad options or
    values) instead of exiting.
    """
    for a in args:
        if not isinstance(a, str):
            raise TypeError(f"run_cli takes strings (the command line's words), got {a!r}")
    return _viscor.run(list(args))


def _options(**options):
    words = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + key.replace("_", "-")
        if value is True:
            words.append(flag)
        elif isinstance(value, (list, tuple)):
            words += [flag, ",".join(number_text(v, key) for v in value)]
        elif isinstance(value, os.PathLike):
            words += [flag, os.fspath(value)]
        else:
            words += [flag, number_text(value, key)]
    return words


def _law_options(law, alpha, beta):
    name, a, b = law_texts(law, alpha, beta)
    return (["--model", name] if name else []) + (["--alpha", a] if a else []) + (["--beta", b] if b else [])


def _json_command(command, law_words, **options):
    if "digits" in options and options["digits"] is not None:
        options["digits"] = check_digits(options["digits"])
    text = run_cli(command, *law_words, *_options(**options), "--json")
    return Result(json.loads(text))


def exact(law=None, gamma=0, g=0, digits=15, *, alpha=None, beta=None):
    """The closed-form CoR where one exists (``viscor exact``): Result with exists,
    formula, e, one_minus_e, outcome, contact_time, max_compression, ..."""
    return _json_command("exact", _law_options(law, alpha, beta), gamma=gamma, g=g, digits=digits)


def approx(law=None, gamma=None, g=0, formula=None, *, alpha=None, beta=None, source=None, order=None, digits=None):
    """The report's approximate formulas (``viscor approx``): small_g, large_g,
    schwager_poschel, prop2, ... (formula='surrogate': the committed surrogate)."""
    if gamma is None:
        raise TypeError("approx() needs gamma")
    return _json_command("approx", _law_options(law, alpha, beta), gamma=gamma, g=g, formula=formula,
                         source=source, order=order, digits=digits)


def calibrate(law=None, target_e=None, g=None, *, alpha=None, beta=None, digits=15, **options):
    """The damping that gives a target CoR (``viscor calibrate``): scaled with g, or
    physical with m, k (or youngs_modulus, poisson_ratio, radius, density), v0,
    gravity, force. Also tolerance, gamma_max."""
    if target_e is None:
        raise TypeError("calibrate() needs target_e")
    return _json_command("calibrate", _law_options(law, alpha, beta), target_e=target_e, g=g, digits=digits,
                         **options)


def scale(law=None, *, alpha=None, beta=None, digits=15, **options):
    """Physical <-> scaled parameters, eq. (2) (``viscor scale``): m, k (or the
    material), v0, gravity, force, and gamma0 (-> gamma, g) or gamma and g
    (-> gamma0, force)."""
    return _json_command("scale", _law_options(law, alpha, beta), digits=digits, **options)


def dem(code, *, digits=None, **options):
    """Damping entries for a DEM deck (``viscor dem``, docs/dem.md): code 'lammps'
    or 'liggghts'; damping, contact, youngs_modulus, poisson_ratio, radius,
    density, target_e (or deck_damping), v0, gravity, force, speeds."""
    if not isinstance(code, str):
        raise TypeError(f"dem() needs the DEM code as a string ('lammps' or 'liggghts'), got {code!r}")
    return _json_command("dem", [code], digits=digits, **options)


def scene(file, out=None, *, error_maps=None):
    """Every impact of a scene file to its tolerance (the scene job, as ``viscor scene``,
    docs/scenes.md).

    Without `out`: a Result with the fields of ``viscor scene --json``. With `out`:
    writes it (CSV, or JSON when it ends in .json) like ``-o``, only on success, and
    returns the path."""
    maps = "" if error_maps is None else os.fspath(error_maps)
    if out is None:
        return Result(_viscor.scene(os.fspath(file), maps, ""))
    _viscor.scene(os.fspath(file), maps, os.fspath(out))
    return os.fspath(out)


def table(spec, out, *, resume=False, shard=None, threads=None, quiet=True, sticking=False):
    """A certified reference table from a grid spec (the table job, as ``viscor table
    SPEC -o OUT``, docs/tables.md): writes OUT (CSV) and OUT.json (its sidecar).

    spec: a spec file's path, or the spec as a dict (the file's JSON). Returns a Table:
    the path OUT (a str, as before) with the table's columns as NumPy arrays
    (``t.column('e')``) and as exact decimal strings (``t.strings('e')``).
    sticking=True computes sticking thresholds (``viscor table sticking``). The work
    runs without the GIL; Ctrl-C stops it after the rows in progress, which are kept:
    call again with resume=True to finish."""
    q = _viscor.TableRequest()
    if isinstance(spec, dict):
        q.spec_text = json.dumps(spec)
        q.spec_name = "<spec dict>"
    else:
        q.spec_name = os.fspath(spec)
        q.from_file = True
    q.output = os.fspath(out)
    for name, value in (("resume", resume), ("quiet", quiet), ("sticking", sticking)):
        if not isinstance(value, bool):
            raise TypeError(f"{name} must be True or False, got {value!r}")
    q.resume, q.quiet, q.sticking = resume, quiet, sticking
    if shard is not None:
        q.shard = shard if isinstance(shard, str) else f"{shard[0]}/{shard[1]}"
    if threads is not None:
        if isinstance(threads, bool) or not isinstance(threads, int):
            raise TypeError(f"threads must be a whole number, got {threads!r}")
        q.threads = threads
    _viscor.table(q)
    return Table(q.output)


def read_table(path):
    """The rows of a viscor CSV table (a certified table of reference_data/, or
    one written by table()) as dicts of strings, with its sidecar (or None)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    sidecar = None
    if os.path.exists(os.fspath(path) + ".json"):
        with open(os.fspath(path) + ".json") as f:
            sidecar = json.load(f)
    return rows, sidecar


def surrogate_directory():
    """Where the committed surrogates are read from: $VISCOR_SURROGATE_DIR, else
    <data directory>/surrogates."""
    return os.environ.get("VISCOR_SURROGATE_DIR") or os.path.join(_viscor.data_directory(), "surrogates")


def find_surrogate(law):
    """The committed surrogate of a named law (a Surrogate), or None: read from
    $VISCOR_SURROGATE_DIR, else <data directory>/surrogates/<law>.surrogate."""
    path = os.path.join(surrogate_directory(), f"{law}.surrogate")
    return _viscor.Surrogate(path) if os.path.exists(path) else None


class Points(list):
    """The results of cor_points: a list of Result (one per point, in input order;
    a refused point has ``line`` and ``error``), with columns across the points."""

    def strings(self, name):
        """Field `name` of every point as its exact decimal string (None where absent)."""
        return [r.get(name) for r in self]

    def column(self, name):
        """Field `name` of every point as a NumPy float64 array (NaN where absent)."""
        import numpy
        return numpy.array([float(v) if v not in (None, "") else float("nan") for v in self.strings(name)],
                           dtype=numpy.float64)


def cor_points(points, digits=15, *, threads=1, method="taylor", tolerance="0", max_steps=None):
    """Many impacts in one call (the point-batch job, as ``viscor cor --points``).

    points: a file's path (CSV with a header, or JSON lines: docs/cli.md), or a list
    of dicts with law (or alpha and beta), gamma, g and optionally digits. Returns
    Points: one Result per point with the fields of ``viscor cor --json`` plus
    ``line``; a refused point has ``line`` and ``error`` instead (the others are
    still solved)."""
    if isinstance(points, (str, os.PathLike)):
        source, from_file = os.fspath(points), True
    else:
        lines = []
        for p in points:
            if not isinstance(p, dict):
                raise TypeError(f"cor_points takes a path or a list of dicts, got an item {p!r}")
            lines.append(json.dumps({k: v if isinstance(v, str) else number_text(v, k) for k, v in p.items()}))
        source, from_file = "\n".join(lines) + "\n", False
    if max_steps is None:
        max_steps = 0
    elif isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
        raise InvalidParameter(f"max_steps must be a whole number >= 1, got {max_steps!r}")
    if isinstance(threads, bool) or not isinstance(threads, int):
        raise TypeError(f"threads must be a whole number, got {threads!r}")
    results = _viscor.solve_points(source, from_file, check_digits(digits), threads, method,
                                   number_text(tolerance, "tolerance"), max_steps)
    return Points(Result(r) for r in results)

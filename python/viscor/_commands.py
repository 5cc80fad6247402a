"""The jobs of the library (include/viscor/jobs/), called through the compiled module.

Each function calls the C++ job the command-line tool calls for the same
subcommand, without the GIL, and returns its result as Python objects: the
fields and messages are the CLI's (docs/cli.md, docs/json-schema.md). Keyword
arguments are the CLI's options with '-' written '_' (gravity=9.8,
youngs_modulus='2e11', target_e='0.9'); None leaves an input out.
"""

import contextlib
import csv
import json
import os
import signal
import subprocess
import threading

from . import _viscor
from ._viscor import InvalidParameter
from ._inputs import check_digits, law_texts, number_text, spec_json
from ._progress import progress_reporter
from ._result import Result
from ._table import Table

#: The physical inputs, named as the CLI's options (docs/cli.md): the bead (m, k or
#: the material), the impact speed, the damping and the load.
PHYSICAL_INPUTS = ("m", "k", "v0", "gamma0", "gravity", "force", "youngs_modulus", "poisson_ratio", "radius",
                   "density", "contact", "wall_youngs_modulus", "wall_poisson_ratio", "other_youngs_modulus",
                   "other_poisson_ratio", "other_radius", "other_density")


def run_cli(*args):
    """Runs the command-line tool ``viscor ARGS...`` and returns what it prints.

    For what the Python functions do not cover; every job has a function of its
    own. The tool is the one built or installed with this module ($VISCOR_CLI
    overrides). Exit code 2 (bad input) raises InvalidParameter with the tool's
    message, any other failure viscor.Error.
    """
    for a in args:
        if not isinstance(a, str):
            raise TypeError(f"run_cli takes strings (the command line's words), got {a!r}")
    candidates = [os.environ.get("VISCOR_CLI")] + list(_viscor.cli_candidates)
    tool = next((c for c in candidates if c and os.access(c, os.X_OK)), None)
    if tool is None:
        raise _viscor.Error("run_cli: the viscor command-line tool was not found (looked in "
                            + ", ".join(c for c in candidates if c) + "; set VISCOR_CLI)")
    done = subprocess.run([tool, *args], capture_output=True, text=True)
    if done.returncode == 2:
        raise InvalidParameter(done.stderr.strip())
    if done.returncode != 0:
        raise _viscor.Error(done.stderr.strip() or f"viscor exited with {done.returncode}")
    return done.stdout


def _texts(options, command):
    """The given options as exact decimal text (None: not given)."""
    return {k: physical_text(v, k) for k, v in options.items() if v is not None}


def physical_text(value, name):
    """A physical input as text: a number's exact decimal, or the contact ('wall' or 'pair') as given."""
    if name == "contact":
        if not isinstance(value, str):
            raise TypeError(f"contact must be 'wall' or 'pair', got {value!r}")
        return value
    return number_text(value, name)


def _physical(options, command, allowed=PHYSICAL_INPUTS):
    """Splits `options` into the physical inputs (as text) and refuses any other keyword."""
    for key in options:
        if key not in allowed:
            raise TypeError(f"{command}() got an unexpected keyword argument {key!r}")
    return _texts(options, command)


def _optional_text(value, name):
    return "" if value is None else number_text(value, name)


def _flag(value, name):
    if not isinstance(value, bool):
        raise TypeError(f"{name} must be True or False, got {value!r}")
    return value


def exact(law=None, gamma=0, g=0, digits=15, *, alpha=None, beta=None):
    """The closed-form CoR where one exists (``viscor exact``): Result with exists,
    formula, e, one_minus_e, outcome, contact_time, max_compression, ..."""
    name, a, b = law_texts(law, alpha, beta)
    return Result(_viscor.exact(name, a, b, number_text(gamma, "gamma"), number_text(g, "g"), check_digits(digits)))


def approx(law=None, gamma=None, g=0, formula=None, *, alpha=None, beta=None, source=None, order=None, digits=None):
    """The report's approximate formulas (``viscor approx``): small_g, large_g,
    schwager_poschel, prop2, ... (formula='surrogate': the committed surrogate)."""
    if gamma is None:
        raise TypeError("approx() needs gamma")
    if order is not None and (isinstance(order, bool) or not isinstance(order, int)):
        raise TypeError(f"order must be a whole number, got {order!r}")
    name, a, b = law_texts(law, alpha, beta)
    return Result(_viscor.approx(name, a, b, number_text(gamma, "gamma"), number_text(g, "g"), formula or "all",
                                 source or "all", 21 if order is None else order,
                                 15 if digits is None else check_digits(digits)))


def calibrate(law=None, target_e=None, g=None, *, alpha=None, beta=None, digits=15, tolerance="0", gamma_max="100",
              method="solve", strict=False, **physical):
    """The damping that gives a target CoR (``viscor calibrate``): scaled with g, or
    physical with m, k (or youngs_modulus, poisson_ratio, radius, density), v0,
    gravity, force. Also tolerance, gamma_max, method ('solve' or 'surrogate')."""
    if target_e is None:
        raise TypeError("calibrate() needs target_e")
    name, a, b = law_texts(law, alpha, beta)
    inputs = _physical(physical, "calibrate", tuple(k for k in PHYSICAL_INPUTS if k != "gamma0"))
    return Result(_viscor.calibrate(name, a, b, inputs, number_text(target_e, "target_e"), _optional_text(g, "g"),
                                    number_text(tolerance, "tolerance"), number_text(gamma_max, "gamma_max"),
                                    str(method), check_digits(digits), _flag(strict, "strict")))


def scale(law=None, *, alpha=None, beta=None, digits=15, gamma=None, g=None, strict=False, **physical):
    """Physical <-> scaled parameters, eq. (2) (``viscor scale``): m, k (or the
    material), v0, gravity, force, and gamma0 (-> gamma, g) or gamma and g
    (-> gamma0, force)."""
    name, a, b = law_texts(law, alpha, beta)
    return Result(_viscor.scale(name, a, b, _physical(physical, "scale"), _optional_text(gamma, "gamma"),
                                _optional_text(g, "g"), check_digits(digits), _flag(strict, "strict")))


_DEM_INPUTS = ("damping", "contact", "youngs_modulus", "poisson_ratio", "k", "radius", "density", "target_e",
               "deck_damping", "deck_en", "v0", "gravity", "force", "speeds", "drop_deck", "wall_youngs_modulus",
               "wall_poisson_ratio", "other_youngs_modulus", "other_poisson_ratio", "other_radius", "other_density",
               "variables", "method", "timestep")


def dem(code, *, digits=15, strict=False, **options):
    """Damping entries for a DEM deck (``viscor dem``, docs/dem.md): code 'lammps',
    'liggghts' or 'yade'; damping, contact, youngs_modulus, poisson_ratio (or k),
    radius, density, target_e (or deck_damping, deck_en), v0, gravity, force,
    speeds (a list), drop_deck (a path to write a complete drop deck to); a wall
    of its own material: wall_youngs_modulus, wall_poisson_ratio; contact='pair'
    with another bead: other_youngs_modulus, other_poisson_ratio, other_radius,
    other_density; variables (a path to write the LAMMPS/LIGGGHTS ``variable`` block
    of ``viscor dem --variables`` to); method 'solve' (default) or 'surrogate' (the
    committed surrogate's inverse in double: the C export's entries); timestep (seconds,
    or 'T/N' or 'contact/N'): entries for the e the code's own update gives at that step."""
    if not isinstance(code, str):
        raise TypeError(f"dem() needs the DEM code as a string ('lammps', 'liggghts' or 'yade'), got {code!r}")
    fields = {"code": code}
    for key, value in options.items():
        if key not in _DEM_INPUTS:
            raise TypeError(f"dem() got an unexpected keyword argument {key!r}")
        if value is None:
            continue
        if key in ("damping", "contact", "method") or (key == "timestep" and isinstance(value, str)):
            fields[key] = str(value)
        elif key in ("drop_deck", "variables"):
            fields[key] = os.fspath(value)
        elif key == "speeds" and isinstance(value, (list, tuple)):
            fields[key] = ",".join(number_text(v, key) for v in value)
        else:
            fields[key] = number_text(value, key)
    return Result(_viscor.dem(fields, check_digits(digits), _flag(strict, "strict")))


def _float_column(strings):
    import numpy
    return numpy.array([float(v) if v not in (None, "") else float("nan") for v in strings], dtype=numpy.float64)


class Scene(Result):
    """The result of scene(): the fields of ``viscor scene --json``, with columns
    across its impacts (``rows``)."""

    __slots__ = ()

    def strings(self, name):
        """Field `name` of every impact as its exact decimal string (None where absent)."""
        return [row.get(name) for row in self._fields.get("rows", [])]

    def column(self, name):
        """Field `name` of every impact as a NumPy float64 array (NaN where absent)."""
        return _float_column(self.strings(name))


def scene(file, out=None, *, error_maps=None):
    """Every impact of a scene file to its tolerance (the scene job, as ``viscor scene``,
    docs/scenes.md).

    Without `out`: a Scene (a Result with the fields of ``viscor scene --json``, and
    its impacts' fields as columns: ``s.column('e')``, ``s.strings('e')``). With `out`:
    writes it (CSV, or JSON when it ends in .json) like ``-o``, only on success, and
    returns the path."""
    maps = "" if error_maps is None else os.fspath(error_maps)
    if out is None:
        return Scene(_viscor.scene(os.fspath(file), maps, ""))
    _viscor.scene(os.fspath(file), maps, os.fspath(out))
    return os.fspath(out)


def table(spec, out=None, *, resume=False, shard=None, threads=None, quiet=True, sticking=False, progress=True,
          estimate=False, format="csv"):
    """A certified reference table from a grid spec (the table job, as ``viscor table
    SPEC -o OUT``, docs/tables.md): writes OUT (CSV) and OUT.json (its sidecar).

    spec: a spec file's path, or the spec as a dict (the file's JSON; its numbers may be
    int, float, Decimal, Fraction or NumPy scalars, read as viscor.cor reads them: a
    float is its exact binary value, so write '0.1' or Decimal('0.1') for the decimal).
    Returns a Table:
    the path OUT (a str, as before) with the table's columns as NumPy arrays
    (``t.column('e')``) and as exact decimal strings (``t.strings('e')``).
    sticking=True computes sticking thresholds (``viscor table sticking``). The work
    runs without the GIL; Ctrl-C, and SIGTERM (a batch scheduler's) while the call
    runs in the main thread, stop it after the rows in progress, which are kept, the
    output's lock released, and raise KeyboardInterrupt: call again with resume=True to
    finish. progress=True shows a progress bar (tqdm, where installed, on a terminal);
    a callable(done, total) is called instead, about every 0.2 s.
    format="netcdf" also writes OUT's NetCDF form (OUT.csv -> OUT.nc, as ``viscor table
    --format netcdf``), published with the table; Table.to_xarray() gives the same.
    estimate=True computes nothing and returns the estimate of the run as a Result
    (``viscor table SPEC --estimate``): rows, cpu_time_s, wall_time_s at `threads`
    (default: every core) for `shard`, and per law its rows and cpu_time_per_row_s
    (out is not needed)."""
    q = _viscor.TableRequest()
    if isinstance(spec, dict):
        q.spec_text = spec_json(spec)
        q.spec_name = "<spec dict>"
    else:
        q.spec_name = os.fspath(spec)
        q.from_file = True
    for name, value in (("resume", resume), ("quiet", quiet), ("sticking", sticking), ("estimate", estimate)):
        if not isinstance(value, bool):
            raise TypeError(f"{name} must be True or False, got {value!r}")
    q.resume, q.quiet, q.sticking = resume, quiet, sticking
    if shard is not None:
        q.shard = shard if isinstance(shard, str) else f"{shard[0]}/{shard[1]}"
    if threads is not None:
        if isinstance(threads, bool) or not isinstance(threads, int):
            raise TypeError(f"threads must be a whole number, got {threads!r}")
        q.threads = threads
    if format not in ("csv", "netcdf"):
        raise InvalidParameter(f"format must be 'csv' or 'netcdf', got {format!r}")
    q.netcdf = format == "netcdf"
    if estimate:
        if sticking or resume:
            raise InvalidParameter("estimate=True is for a CoR table run: give it without sticking and resume")
        return Result(_viscor.table_estimate(q))
    if out is None:
        raise TypeError("table() needs the output file out (or estimate=True)")
    q.output = os.fspath(out)
    q.progress = progress_reporter(progress, "row", "viscor table")
    try:
        with _sigterm_interrupts():
            _viscor.table(q)
    finally:
        q.progress.close()
    return Table(q.output)


@contextlib.contextmanager
def _sigterm_interrupts():
    """SIGTERM raises KeyboardInterrupt for the duration, as Ctrl-C does, so that a
    table run stops after its rows in progress and keeps them (signal handlers can only
    be set from the main thread: elsewhere, SIGTERM keeps its handler)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def interrupt(signum, frame):
        raise KeyboardInterrupt("SIGTERM")

    previous = signal.signal(signal.SIGTERM, interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous if previous is not None else signal.SIG_DFL)


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
        return [r.exact(name) if name in r else None for r in self]

    def column(self, name):
        """Field `name` of every point as a NumPy float64 array (NaN where absent)."""
        return _float_column(self.strings(name))


def cor_points(points, digits=15, *, threads=1, method="taylor", tolerance="0", max_steps=None,
               certified_digits=None):
    """Many impacts in one call (the point-batch job, as ``viscor cor --points``).

    points: a file's path (CSV with a header, or JSON lines: docs/cli.md), or a list
    of dicts with law (or alpha and beta), gamma, g and optionally digits or
    certified_digits. certified_digits=N: the certified digits of a point that gives
    neither (as ``viscor cor --points FILE --certified-digits N``). Returns
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
    if certified_digits is not None and (isinstance(certified_digits, bool) or not isinstance(certified_digits, int)):
        raise TypeError(f"certified_digits must be a whole number, got {certified_digits!r}")
    results = _viscor.solve_points(source, from_file, check_digits(digits), certified_digits, threads, method,
                                   number_text(tolerance, "tolerance"), max_steps)
    return Points(Result(r) for r in results)

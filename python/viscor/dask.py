"""viscor on a Dask cluster (``dask.distributed``): tables, point batches and
evaluate spread over the workers of a Client (docs/python.md, "Many machines").

Every task calls the library through the Python module on its worker; the
results are identical to a one-process run (a table byte for byte: the shards are
merged by the library's merge). Finished work is kept: a table's shards are written
next to the output as they arrive, so a call that fails or is interrupted can be
repeated with the same arguments and computes only the shards that are missing;
Dask retries a failed task (``retries``) before giving up.

    from dask.distributed import Client, LocalCluster
    import viscor.dask
    with Client(LocalCluster(n_workers=2, threads_per_worker=1)) as client:
        viscor.dask.table("spec.json", "table.csv", client)
        points = viscor.dask.cor_points(list_of_dicts, client)
        r = viscor.dask.evaluate(client, "tsuji", gamma, g, tol=1e-8)
"""

import json
import os
import re
import tempfile
import warnings

from . import _viscor
from ._commands import Points, cor_points as _cor_points, table as _table
from ._evaluate import Evaluation, evaluate as _evaluate
from ._inputs import spec_json
from ._progress import progress_reporter
from ._result import Result
from ._table import Table


def _scratch_root():
    """Where a task keeps its scratch files: the worker's own local directory, which
    Dask removes when the worker's process is gone (also after a kill), so a killed
    task leaves no folder behind; the system's temporary directory outside a worker."""
    try:
        from distributed import get_worker
        return get_worker().local_directory
    except (ImportError, ValueError):
        return None


def _shard_task(spec_text, index, count, sticking):
    """On a worker: one shard of the table in a scratch directory; returns its files' text."""
    with tempfile.TemporaryDirectory(prefix="viscor-shard-", dir=_scratch_root()) as scratch:
        out = os.path.join(scratch, f"shard-{index}-of-{count}.csv")
        _table(json.loads(spec_text), out, shard=(index, count), threads=1, sticking=sticking, progress=False)
        with open(out) as f:
            csv_text = f.read()
        with open(out + ".json") as f:
            sidecar_text = f.read()
    return index, csv_text, sidecar_text


_SHARD_FILE = re.compile(r"shard-(\d+)-of-(\d+)\.csv(\.json)?(\.tmp\.\d+)?$")


def _keep_only_this_split(kept, shards):
    """The shards folder of an earlier call may hold shards of another count, and the
    temporaries of a call killed while it wrote one (no other call is writing: this one
    holds the folder's lock): both are discarded, with a warning, never mixed in.
    Anything else in it is not ours: refused."""
    stale = []
    for name in sorted(os.listdir(kept)):
        match = _SHARD_FILE.match(name)
        if match is None:
            raise _viscor.Error(f"'{os.path.join(kept, name)}' is not a shard viscor.dask.table wrote; the folder "
                                f"'{kept}' holds only finished shards: remove it, or choose another output")
        if int(match.group(2)) != shards or match.group(4):
            stale.append(name)
    if stale:
        warnings.warn(f"viscor.dask.table: discarding {len(stale)} files in '{kept}' of shards of another count or "
                      f"left by a killed call (this call splits the table into {shards})", stacklevel=3)
        for name in stale:
            os.remove(os.path.join(kept, name))


def _spec_text(spec):
    if isinstance(spec, dict):
        return spec_json(spec)  # numbers as viscor.table reads them
    with open(os.fspath(spec)) as f:
        return f.read()


def table(spec, out, client, *, shards=None, sticking=False, retries=2, progress=True):
    """A certified table of a spec (a file or a dict, as viscor.table) computed on the
    workers of `client`, one task per shard, merged into `out` (and `out.json`).

    shards: the number of shards (default: 4 per worker). Finished shards are kept in
    the directory `out + '.shards'` until the merge succeeds; calling again with the
    same arguments computes only the missing ones (with another shard count, the old
    shards are discarded with a warning). The call holds the lock of that directory
    (a second call on the same output stops at once) and the merge holds out's lock,
    as `viscor table merge` does. progress=True shows the finished shards as a progress
    bar (tqdm, where installed, on a terminal); a callable(done, total) is called
    instead. Returns a Table (as viscor.table).
    """
    from distributed import as_completed

    text = _spec_text(spec)
    json.loads(text)  # a spec that is not JSON fails here, before any task
    if shards is None:
        shards = 4 * max(1, len(client.scheduler_info().get("workers", {})))
    if isinstance(shards, bool) or not isinstance(shards, int) or shards < 1:
        raise TypeError(f"shards must be a whole number >= 1, got {shards!r}")
    out = os.fspath(out)
    kept = out + ".shards"
    os.makedirs(kept, exist_ok=True)
    with _viscor.OutputLock(kept):  # one call at a time on these shards; the merge takes out's own lock
        with _viscor.OutputLock(out):  # before any task: stop now if a table run or a merge is writing out
            pass
        _keep_only_this_split(kept, shards)
        paths = [os.path.join(kept, f"shard-{i}-of-{shards}.csv") for i in range(shards)]
        missing = [i for i in range(shards) if not (os.path.exists(paths[i]) and os.path.exists(paths[i] + ".json"))]
        futures = [client.submit(_shard_task, text, i, shards, sticking, retries=retries, pure=False) for i in missing]
        report = progress_reporter(progress, "shard", "viscor.dask.table")
        try:
            report(shards - len(missing), shards)
            for done, future in enumerate(as_completed(futures), start=shards - len(missing) + 1):
                index, csv_text, sidecar_text = future.result()
                # both or neither, through the library's writer (exclusive temporaries, checked writes)
                _viscor.write_together([(paths[index] + ".json", sidecar_text), (paths[index], csv_text)])
                report(done, shards)
        finally:
            report.close()
        _viscor.merge_tables(paths, out)
        for path in paths:
            for p in (path, path + ".json"):
                os.remove(p)
    os.rmdir(kept)
    return Table(out)


def _points_task(points, options):
    """On a worker: one chunk of a point batch, as plain dicts (they travel back pickled)."""
    return [r.to_dict() for r in _cor_points(points, **options)]


def _chunks(n, size):
    return [(start, min(n, start + size)) for start in range(0, n, size)]


def cor_points(points, client, *, chunk=64, retries=2, progress=True, **options):
    """viscor.cor_points over the workers of `client`, `chunk` points per task; the
    options are cor_points's (digits, certified_digits, method, tolerance, max_steps).
    progress as in table (counting points). Returns Points in input order, as one
    process would."""
    if isinstance(points, (str, os.PathLike)):  # JSON lines; a CSV file: read it into dicts first
        with open(os.fspath(points)) as f:
            points = [json.loads(line) for line in f if line.strip()]
    futures = [client.submit(_points_task, points[a:b], options, retries=retries, pure=False)
               for a, b in _chunks(len(points), chunk)]
    results = Points()
    report = progress_reporter(progress, "point", "viscor.dask.cor_points")
    try:
        for (a, b), future in zip(_chunks(len(points), chunk), futures):
            for fields in future.result():
                if "line" in fields:
                    fields["line"] = fields["line"] + a  # the line in the whole batch, not in the chunk
                results.append(Result(fields))
            report(b, len(points))
    finally:
        report.close()
    return results


def evaluate(client, law=None, gamma=None, g=0.0, tol=1e-6, *, chunk=100000, retries=2, **options):
    """viscor.evaluate over the workers of `client`, `chunk` points per task (each task
    uses one thread); arrays broadcast as in evaluate. Returns an Evaluation."""
    import numpy as np

    gamma_b, g_b, tol_b = np.broadcast_arrays(np.asarray(gamma, dtype=np.float64), np.asarray(g, dtype=np.float64),
                                              np.asarray(tol, dtype=np.float64))
    shape = gamma_b.shape
    flat = [np.ascontiguousarray(x).reshape(-1) for x in (gamma_b, g_b, tol_b)]
    options.setdefault("threads", 1)
    futures = [client.submit(_evaluate, law, flat[0][a:b], flat[1][a:b], flat[2][a:b], retries=retries, pure=False,
                             **options) for a, b in _chunks(flat[0].size, chunk)]
    parts = [f.result() for f in futures]
    if not parts:
        return _evaluate(law, gamma_b, g_b, tol_b, **options)
    return Evaluation(*(np.concatenate([getattr(p, k) for p in parts]).reshape(shape) for k in Evaluation._fields))

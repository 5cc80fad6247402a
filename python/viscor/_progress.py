"""Progress of long runs (table, dask.table, dask.cor_points): a tqdm bar where tqdm
is installed (python3-tqdm) and standard error is a terminal (tqdm's disable=None),
nothing otherwise; or the caller's own callable(done, total)."""


class _Silent:
    def __call__(self, done, total):
        pass

    def close(self):
        pass


class _Callback(_Silent):
    def __init__(self, function):
        self._function = function

    def __call__(self, done, total):
        self._function(done, total)


class _Bar(_Silent):
    def __init__(self, tqdm, unit, desc):
        self._bar = tqdm(total=None, unit=unit, desc=desc, disable=None)

    def __call__(self, done, total):
        if self._bar.total != total:
            self._bar.total = total
        self._bar.update(done - self._bar.n)

    def close(self):
        self._bar.close()


def progress_reporter(progress, unit, desc):
    """A callable(done, total) with close(): progress=True shows a tqdm bar (where tqdm
    is installed), False or None shows nothing, a callable is called with (done, total)."""
    if progress is None or progress is False:
        return _Silent()
    if progress is True:
        try:
            from tqdm import tqdm
        except ImportError:
            return _Silent()
        return _Bar(tqdm, unit, desc)
    if callable(progress):
        return _Callback(progress)
    raise TypeError(f"progress must be True, False or a callable(done, total), got {progress!r}")

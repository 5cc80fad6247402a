"""Table: what viscor.table returns, the path of the table written (a str, as
before) that also gives the table's columns."""

import json
import os

from . import _viscor

# Columns that hold numbers; the others (law, outcome, method, ...) are text.
_TEXT_COLUMNS = {"law", "alpha", "beta", "outcome", "method", "outcome_proven", "bead", "contact", "wall"}


class Table(str):
    """The path of a viscor table (CSV, with its sidecar OUT.json).

    >>> t = viscor.table(spec, "out.csv")      # doctest: +SKIP
    >>> t.column("e")                          # NumPy float64 array (NaN where empty)
    >>> t.strings("e")                         # the exact decimal strings
    >>> t.columns, t.sidecar

    The file is read once, on first use, by the library's own reader, which checks
    every row (a damaged file raises ParseError)."""

    def __new__(cls, path):
        self = super().__new__(cls, os.fspath(path))
        self._columns = None
        self._rows = None
        return self

    def _load(self):
        if self._rows is None:
            self._columns, self._rows = _viscor.table_columns(str(self))

    @property
    def columns(self):
        """The column names, in file order."""
        self._load()
        return list(self._columns)

    @property
    def rows(self):
        """The number of rows (len() stays the length of the path, as for any str)."""
        self._load()
        return len(self._rows)

    def strings(self, name):
        """Column `name` as the exact strings of the file."""
        self._load()
        try:
            k = self._columns.index(name)
        except ValueError:
            raise KeyError(f"no column {name!r} in {str(self)!r} (columns: {', '.join(self._columns)})") from None
        return [row[k] for row in self._rows]

    def column(self, name):
        """Column `name` as a NumPy float64 array (empty fields NaN; 'inf' infinite).
        Text columns (law, outcome, method, ...) come back as a list of str."""
        values = self.strings(name)
        if name in _TEXT_COLUMNS:
            return values
        import numpy
        return numpy.array([float(v) if v != "" else float("nan") for v in values], dtype=numpy.float64)

    def to_xarray(self):
        """The table as an xarray.Dataset over its axes (law, g, gamma; for a table from a
        spec in SI law, bead, wall, gravity, force, gamma0 or target_e, v0, with gamma, g,
        contact_time_s and max_compression_m as variables): e, one_minus_e,
        contact_time, max_compression (float64, with their exact decimals as NAME_exact
        strings), outcome, certified_digits, method, and for a proven table the
        enclosures (rounded outwards, so still bounds), proven_digits and outcome_proven;
        the sidecar's provenance (version, commit, spec, method, precision, checksums)
        as attributes. The layout is the library's (jobs/table_dataset.hpp), the same as
        the NetCDF form that table(..., format="netcdf") writes. Needs python3-xarray."""
        import numpy
        import xarray
        d = _viscor.table_dataset(str(self))

        def variables(arrays):
            out = {}
            for name, dims, values, attrs in arrays:
                if isinstance(values, list):  # texts: object arrays, as xarray reads NetCDF strings
                    shape = tuple(d["dims"][dim] for dim in dims)
                    flat = numpy.empty(len(values), dtype=object)
                    flat[:] = values
                    values = flat.reshape(shape)
                out[name] = (dims, values, attrs)
            return out

        return xarray.Dataset(data_vars=variables(d["data_vars"]), coords=variables(d["coords"]), attrs=d["attrs"])

    @property
    def sidecar(self):
        """The sidecar OUT.json (provenance) as a dict."""
        with open(str(self) + ".json") as f:
            return json.load(f)

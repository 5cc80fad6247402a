"""Table: what viscor.table returns, the path of the table written (a str, as
before) that also gives the table's columns."""

import json
import os

from . import _viscor

# Columns that hold numbers; the others (law, outcome, method, ...) are text.
_TEXT_COLUMNS = {"law", "alpha", "beta", "outcome", "method", "outcome_proven"}


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

    @property
    def sidecar(self):
        """The sidecar OUT.json (provenance) as a dict."""
        with open(str(self) + ".json") as f:
            return json.load(f)

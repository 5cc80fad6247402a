"""Result: a JSON object of viscor (docs/json-schema.md) read as attributes, its
numbers as numbers."""

import decimal
import re

# A decimal number as the library writes it (numbers are JSON strings at the working
# precision); "nan" is an unknown quantity (a contact time), "inf" a bound that is none.
_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[+-]?(?:inf|nan)")
# Fields whose text is not a quantity: law exponents are exact fractions ("3/2", "1"),
# versions and commits are names.
_TEXT_FIELDS = frozenset({"name", "alpha", "beta", "version", "viscor_version", "commit", "git_commit", "source", "line",
                          "description", "table", "spec_file", "command"})
_EXACT_SUFFIX = "_exact"


def _number(name, value):
    """`value` as a float when it is the decimal text of a quantity, else as it is."""
    if isinstance(value, str) and name not in _TEXT_FIELDS and _NUMBER.fullmatch(value):
        return float(value)
    return value


class Result:
    """The fields of one viscor JSON object, under their JSON names.

    ``r.e`` is a number: the float nearest to the working precision's value (so
    ``r.e * 2`` and ``r.e < 0.9`` work). The exact value is ``r.e_exact``, the
    decimal string the library printed, also as ``decimal.Decimal``
    (``r.decimal('e')``) and as ``mpmath.mpf`` at the working binary precision
    (``r.mpf('e')``, needs mpmath). Text stays text (outcome, method, the law's
    exact exponents). Nested objects (``r.law``, ``r.precision``, ``r.certified``)
    are Results too; ``r.to_dict()`` gives the plain JSON data (numbers as the
    exact strings).
    """

    __slots__ = ("_fields", "_binary_digits")

    def __init__(self, fields, binary_digits=None):
        object.__setattr__(self, "_fields", dict(fields))
        precision = fields.get("precision")
        if isinstance(precision, dict) and "binary_digits" in precision:
            binary_digits = precision["binary_digits"]
        object.__setattr__(self, "_binary_digits", binary_digits)

    def _wrap(self, value, name=""):
        if isinstance(value, dict):
            return Result(value, self._binary_digits)
        if isinstance(value, list):
            return [self._wrap(v, name) for v in value]
        return _number(name, value)

    def _field(self, name):
        if name in self._fields:
            return self._wrap(self._fields[name], name)
        if name.endswith(_EXACT_SUFFIX) and isinstance(self._fields.get(name[:-len(_EXACT_SUFFIX)]), str):
            return self._fields[name[:-len(_EXACT_SUFFIX)]]  # e_exact: the exact decimal string of e
        raise KeyError(name)

    def __getattr__(self, name):
        if name.startswith("__") or name == "_fields":  # copy and pickle probe these before _fields is set
            raise AttributeError(name)
        try:
            return self._field(name)
        except KeyError:
            raise AttributeError(f"no field {name!r} in this result (fields: {', '.join(self._fields)})") from None

    def __setattr__(self, name, value):
        raise AttributeError("viscor results are read-only")

    def __getitem__(self, name):
        return self._field(name)

    def __contains__(self, name):
        return name in self._fields

    def __iter__(self):
        return iter(self._fields)

    def __eq__(self, other):
        return isinstance(other, Result) and self._fields == other._fields

    __hash__ = None

    def keys(self):
        return self._fields.keys()

    def get(self, name, default=None):
        try:
            return self._field(name)
        except KeyError:
            return default

    def exact(self, name):
        """Field `name` as the library wrote it: the exact decimal string of a number."""
        return self._fields[name]

    def to_dict(self):
        """The JSON data (decimal strings stay strings)."""
        return _copy(self._fields)

    def __repr__(self):
        shown = ", ".join(f"{k}={v!r}" for k, v in self._fields.items() if not isinstance(v, (dict, list)))
        return f"viscor.Result({shown})"

    @property
    def working_digits(self):
        """The decimal digits a computation worked with (precision.digits; a
        ``certified`` object's own working_digits)."""
        if "working_digits" in self._fields:
            return self._fields["working_digits"]
        precision = self._fields.get("precision")
        if isinstance(precision, dict):
            return precision.get("digits")
        raise AttributeError("no field 'working_digits' in this result")

    @property
    def digits(self):
        """The older name: the working precision of a computation (precision.digits),
        or, in a ``certified`` object, the certified significant digits (read
        ``working_digits`` or ``certified_digits``)."""
        if "digits" in self._fields:
            return self._fields["digits"]
        precision = self._fields.get("precision")
        if isinstance(precision, dict):
            return precision.get("digits")
        raise AttributeError("no field 'digits' in this result")

    def decimal(self, name):
        """Field `name` as decimal.Decimal, exactly the printed value (no rounding)."""
        return decimal.Decimal(self._text(name))

    def mpf(self, name):
        """Field `name` as mpmath.mpf at the working binary precision (needs mpmath)."""
        try:
            import mpmath
        except ImportError as error:
            raise ImportError("Result.mpf needs mpmath (Debian: python3-mpmath); "
                              "Result.decimal works without it") from error
        bits = self._binary_digits or 53
        with mpmath.workprec(max(int(bits), 53)):
            return mpmath.mpf(self._text(name))

    def _text(self, name):
        value = self._fields[name]
        if not isinstance(value, str):
            raise TypeError(f"field {name!r} is {value!r}, not a decimal string")
        return value


def _copy(value):
    if isinstance(value, dict):
        return {k: _copy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_copy(v) for v in value]
    return value

"""Python values -> the exact decimal text the library parses (docs/python.md, "Inputs")."""

import decimal
import fractions
import json
import numbers

from ._viscor import InvalidParameter, PrecisionUnavailable, max_working_digits

NAMED_LAWS = ("linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley")


def _finite_decimal_text(d, name):
    if not d.is_finite():
        raise InvalidParameter(f"parameter {name} must be a finite decimal number, but got {d}")
    return format(d, "f") if -30 <= d.adjusted() <= 30 else format(d, "e")


def _fraction_text(f):
    """p/q exactly: a terminating decimal when q = 2^a 5^b, else the text p/q."""
    q = f.denominator
    twos = fives = 0
    while q % 2 == 0:
        q //= 2
        twos += 1
    while q % 5 == 0:
        q //= 5
        fives += 1
    if q != 1:
        return f"{f.numerator}/{f.denominator}"
    places = max(twos, fives)
    scaled = f.numerator * 10**places // f.denominator  # exact: the denominator divides 10^places
    sign = "-" if scaled < 0 else ""
    digits = str(abs(scaled)).rjust(places + 1, "0")
    return sign + (digits[:-places] + "." + digits[-places:] if places else digits)


def number_text(x, name):
    """The exact decimal (or p/q) text of x.

    str is passed as given (the library checks it); int, Decimal and Fraction are
    exact; a float is taken as its exact binary value (0.1 is
    0.1000000000000000055511151231257827021181583404541015625): pass '0.1' or
    Decimal('0.1') for the decimal. NaN and infinities are refused.
    """
    if isinstance(x, bool):
        raise TypeError(f"{name} must be a number or a decimal string, not a bool ({x!r})")
    if isinstance(x, str):
        return x.strip()
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, decimal.Decimal):
        return _finite_decimal_text(x, name)
    if isinstance(x, fractions.Fraction):
        return _fraction_text(x)
    if isinstance(x, float):
        if x != x or x in (float("inf"), float("-inf")):
            raise InvalidParameter(f"parameter {name} must be a finite decimal number, but got {x!r}")
        return _finite_decimal_text(decimal.Decimal(x), name)  # Decimal(float) is exact
    if isinstance(x, numbers.Rational):
        return _fraction_text(fractions.Fraction(x.numerator, x.denominator))
    if isinstance(x, numbers.Real):  # numpy.float64, mpmath.mpf, ...: via float is inexact for mpf
        raise TypeError(f"{name} must be a str, int, float, Decimal or Fraction, got {type(x).__name__} "
                        f"({x!r}); convert it with str() or Decimal() to say which value you mean")
    raise TypeError(f"{name} must be a str, int, float, Decimal or Fraction, got {type(x).__name__} ({x!r})")


def law_texts(law, alpha, beta):
    """(name, alpha, beta) as text for the library; the library checks them."""
    if law is not None and not isinstance(law, str):
        raise TypeError(f"law must be a name such as 'kuwabara_kono' (or give alpha= and beta=), got {law!r}")
    name = law or ""
    a = "" if alpha is None else number_text(alpha, "alpha")
    b = "" if beta is None else number_text(beta, "beta")
    return name, a, b


def check_digits(digits):
    """A whole number of decimal digits, 1 to max_working_digits."""
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral):
        raise TypeError(f"digits must be a whole number, got {type(digits).__name__} ({digits!r})")
    digits = int(digits)
    if digits < 1:
        raise PrecisionUnavailable(f"requested precision digits = {digits} must be >= 1")
    if digits > max_working_digits:
        raise PrecisionUnavailable(f"requested precision digits = {digits} exceeds the maximum of "
                                   f"{max_working_digits}")
    return digits


def spec_json(spec, where="spec"):
    """A table spec given as a dict, as the JSON text the library reads: numbers as
    number_text writes them (an int as itself; a float as its exact binary value, as
    viscor.cor reads it; a Decimal or a NumPy integer or float64 exactly; a Fraction
    p/q that is not a terminating decimal as the string "p/q"), so that a spec means
    the same numbers in every call. `where` names the field in errors."""
    if isinstance(spec, dict):
        items = []
        for key, value in spec.items():
            if not isinstance(key, str):
                raise TypeError(f"{where}: keys must be strings, got {key!r}")
            items.append(json.dumps(key) + ": " + spec_json(value, f"{where}.{key}"))
        return "{" + ", ".join(items) + "}"
    if isinstance(spec, (list, tuple)):
        return "[" + ", ".join(spec_json(v, f"{where}[{i}]") for i, v in enumerate(spec)) + "]"
    if spec is None or isinstance(spec, (str, bool)):
        return json.dumps(spec)
    if isinstance(spec, numbers.Number):
        text = number_text(spec, where)
        return json.dumps(text) if "/" in text else text
    raise TypeError(f"{where} must be a JSON value (dict, list, str, number, bool or None), got "
                    f"{type(spec).__name__} ({spec!r})")

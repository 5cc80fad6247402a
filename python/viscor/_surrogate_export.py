"""The committed CoR surrogates as self-contained C99 files (docs/surrogate.md,
"Exporting to C"): the Python side of ``viscor surrogate export --language c``."""

from . import _viscor


def export_surrogates(output, law="all", language="c", surrogate_directory=None):
    """Write a C99 header and source with the committed surrogate of `law` (a name, a
    list of names, or "all": one pair with every committed law) into the directory
    `output` (created if absent); returns the paths written (header first).

    The C code needs only <math.h> and gives the library's values bit for bit
    (e(gamma, g), 1 - e, the outcome, gamma_c(g), the inverse gamma(e, g), and the
    physical entry points such as the damping for a target e). surrogate_directory:
    where the .surrogate files are (default: $VISCOR_SURROGATE_DIR, else the data
    directory's surrogates/). Raises InvalidParameter for an unknown law or language.
    """
    laws = [law] if isinstance(law, str) else list(law)
    if not all(isinstance(name, str) for name in laws):
        raise TypeError(f"law must be a name or a list of names, got {law!r}")
    return _viscor.surrogate_export(str(output), laws, str(language),
                                    "" if surrogate_directory is None else str(surrogate_directory))

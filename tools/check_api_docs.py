#!/usr/bin/env python3
"""Checks that the API reference covers every public function and type.

Usage: check_api_docs.py DOXYGEN ROOT

Runs Doxygen over ROOT/include/viscor (detail/ folders and viscor::detail
excluded, as in the `doc` target) with undocumented-entity warnings on, and fails
listing every public function, class or struct that has no /// comment. Struct
fields are not required to have one (most are self-explanatory numbers).
"""
import pathlib
import re
import subprocess
import sys
import tempfile

# Doxygen's wording for an undocumented function or compound type.
UNDOCUMENTED = re.compile(r"warning: (Member .*\(function\)|Compound \S+) .*is not documented")


def undocumented(doxygen, include_dir, work):
    warn_log = work / "warnings.log"
    (work / "Doxyfile").write_text(
        "\n".join(
            [
                f"INPUT = {include_dir}",
                "RECURSIVE = YES",
                "FILE_PATTERNS = *.hpp",
                "EXCLUDE_PATTERNS = */detail/*",
                "EXCLUDE_SYMBOLS = viscor::detail viscor::detail::* viscor::*::detail viscor::*::detail::*",
                f"OUTPUT_DIRECTORY = {work / 'out'}",
                "GENERATE_HTML = NO",
                "GENERATE_LATEX = NO",
                "GENERATE_XML = YES",
                "EXTRACT_ALL = NO",
                "WARN_IF_UNDOCUMENTED = YES",
                f"WARN_LOGFILE = {warn_log}",
                "QUIET = YES",
            ]
        )
        + "\n"
    )
    run = subprocess.run([doxygen, str(work / "Doxyfile")], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"check_api_docs: doxygen failed ({run.returncode}):\n{run.stderr}")
    found = []
    for line in warn_log.read_text().splitlines():
        if UNDOCUMENTED.search(line) and "::detail" not in line:
            found.append(line.replace(str(include_dir.parent.parent) + "/", ""))
    return found


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    doxygen, root = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
    include_dir = root / "include" / "viscor"
    if not include_dir.is_dir():
        sys.exit(f"check_api_docs: no include/viscor under {root}")
    with tempfile.TemporaryDirectory() as tmp:
        found = undocumented(doxygen, include_dir, pathlib.Path(tmp))
    if found:
        print(f"{len(found)} public functions or types without a /// comment:")
        print("\n".join(sorted(found)))
        sys.exit(1)
    print(f"every public function and type under {include_dir.relative_to(root)} is documented")


if __name__ == "__main__":
    main()

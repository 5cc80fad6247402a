#!/usr/bin/env python3
"""Checks that no issue number sits in the code, the tests, the tools or the reference docs.

How a figure or a fix came about belongs in docs/history.md and CHANGELOG.md; code
comments and reference pages keep the reason, not the ticket. An "issue number" is
any of (case-insensitive):

  issue N, issues N-M, issue #N, Issue N item K   word "issue(s)", then a number
  PR N, pull request N                            the same for pull requests
  (#N)                                            a number in parentheses after #
  #N                                              # and 1-5 digits, alone

(N, M, K standing for numbers; tests/history_fixture/ has each form with real ones.)

The last form does not count when the # follows a letter, a digit, "&", "/", "$",
"{" or "]" (a URL fragment, an HTML entity, "$#", "${#a}", a markdown link's anchor
"](#1-intro)"), when the digits run on into a letter, "_", "-" or "." and a letter
or digit (hex colours, "#1-intro" anchors, "#1.2"), or in a line that starts with a preprocessor directive
("#include", "#define 1", "#if 0").

Exits 1 and prints file:line: text for each one found, 0 when there is none.
Run: python3 tools/check_history.py [repo root]
"""
import pathlib
import re
import sys

# What is checked, relative to the repository root: folders (every text file below
# them) and single files or globs.
ROOTS = ["include", "src", "python", "tools", "tests", "benchmarks", "examples", "docs/*.md"]

# History pages: the only places an issue number belongs.
ALLOWED = {"docs/history.md", "CHANGELOG.md"}

# Fixtures of this check's own test (tests/CMakeLists.txt, check_history_catches_issue_numbers).
FIXTURES = {"tests/history_fixture"}

# Fuzzer inputs: data (some copied from reference_data/), not prose.
FUZZ_INPUTS = {"tests/fuzz/corpus", "tests/fuzz/findings"}


PATTERNS = [
    re.compile(r"\bissues?\s*#?\d+", re.IGNORECASE),
    re.compile(r"\b(?:pull\s+request|PR)\s*#?\d+", re.IGNORECASE),
    re.compile(r"\(#\d+\)"),
    re.compile(r"(?<![\w&/${\]])#\d{1,5}(?![\w\-]|\.\w)"),
]
DIRECTIVE = re.compile(r"^\s*#\s*[a-z]+")

SKIPPED_SUFFIXES = {".png", ".svg", ".pdf", ".gz", ".zip", ".ico", ".jpg", ".jpeg"}


def files_under(root: pathlib.Path, spec: str):
    if any(c in spec for c in "*?["):
        yield from sorted(p for p in root.glob(spec) if p.is_file())
        return
    path = root / spec
    if path.is_file():
        yield path
    elif path.is_dir():
        yield from sorted(p for p in path.rglob("*") if p.is_file())


def excluded(rel: str) -> bool:
    for prefix in list(FIXTURES) + list(FUZZ_INPUTS):
        if rel == prefix or rel.startswith(prefix.rstrip("/") + "/"):
            return True
    return rel in ALLOWED


def findings(line: str):
    """The issue numbers in one line, each once (the forms overlap: "(#N)" is also "#N")."""
    spans = []
    for pattern in PATTERNS:
        for match in pattern.finditer(line):
            if pattern is PATTERNS[-1] and DIRECTIVE.match(line) and match.start() == line.index("#"):
                continue
            if any(a < match.end() and match.start() < b for a, b in spans):
                continue
            spans.append((match.start(), match.end()))
            yield match.group(0)


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    # A fixture is checked as a repository of its own: only the history pages are allowed.
    fixture = (root / ".history-fixture").is_file()
    bad = 0
    seen = set()
    for spec in ROOTS:
        for path in files_under(root, spec):
            rel = path.relative_to(root).as_posix()
            if rel in seen or path.suffix in SKIPPED_SUFFIXES or "/.git/" in f"/{rel}":
                continue
            seen.add(rel)
            if rel in ALLOWED or (not fixture and excluded(rel)):
                continue
            try:
                text = path.read_text(encoding="utf-8")
            except (UnicodeDecodeError, OSError):
                continue  # binary data
            for number, line in enumerate(text.splitlines(), 1):
                for found in findings(line):
                    print(f"{rel}:{number}: issue number '{found}': {line.strip()[:120]}")
                    bad += 1
    if bad:
        print(f"{bad} issue number(s): history goes to docs/history.md or CHANGELOG.md; "
              "keep the reason in the comment, not the ticket")
        return 1
    print("no issue numbers in code, tests, tools or reference docs")
    return 0


if __name__ == "__main__":
    sys.exit(main())

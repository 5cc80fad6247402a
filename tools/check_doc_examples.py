#!/usr/bin/env python3
"""Runs the examples that the docs show with their output, and compares.

A ```console block of a page under docs/ holds commands, each on a line that starts
with "$ ", followed by the output the page shows for it. This script runs every
command (bash, in a scratch directory that sees the repository's docs/, tools/,
examples/ and reference_data/, with the build tree's `viscor` first on PATH) and
compares what it prints with what the page shows, the way doctest compares (a
"..." in the shown output matches anything, so timings can be elided). A page that
shows an output the program does not print fails, naming the page and line.

Usage: check_doc_examples.py SOURCE_DIR BUILD_DIR [PAGE.md ...]  (default: every docs/*.md)
"""
import doctest
import glob
import os
import shutil
import subprocess
import sys
import tempfile


def examples(page):
    """(line number, command, shown output) of every command in the page's ```console blocks."""
    found, inside, command, shown, at = [], False, None, [], 0
    with open(page, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if line.startswith("```"):
                if inside and command is not None:
                    found.append((at, command, "\n".join(shown)))
                inside, command, shown = line == "```console", None, []
                continue
            if not inside:
                continue
            if line.startswith("$ "):
                if command is not None:
                    found.append((at, command, "\n".join(shown)))
                at, command, shown = number, line[2:], []
            elif command is not None:
                shown.append(line)
    return found


def scratch_directory(source, build):
    """A directory where the docs' relative paths resolve as in the repository."""
    scratch = tempfile.mkdtemp(prefix="viscor_doc_examples_")
    os.mkdir(os.path.join(scratch, "bin"))
    os.symlink(os.path.join(build, "viscor"), os.path.join(scratch, "bin", "viscor"))
    for name in ("docs", "tools", "examples", "reference_data"):
        os.symlink(os.path.join(source, name), os.path.join(scratch, name))
    os.symlink(build, os.path.join(scratch, "build"))
    return scratch


def main(argv):
    source, build = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    pages = argv[3:] or sorted(glob.glob(os.path.join(source, "docs", "*.md")))
    scratch = scratch_directory(source, build)
    env = dict(os.environ, PATH=os.path.join(scratch, "bin") + os.pathsep + os.environ.get("PATH", ""))
    for name in ("VISCOR_DATA", "VISCOR_ERROR_MAPS"):
        env.pop(name, None)
    try:
        checked, failures = check_pages(pages, source, scratch, env)
    finally:
        shutil.rmtree(scratch)
    print("doc examples: %d commands checked, %d failures" % (checked, failures))
    if checked == 0:
        print("no ```console example found: the check would pass vacuously", file=sys.stderr)
        return 1
    return 1 if failures else 0


def check_pages(pages, source, scratch, env):
    """Runs every example of the pages; returns (commands checked, failures)."""
    checker, checked, failures = doctest.OutputChecker(), 0, 0
    for page in pages:
        for line, command, shown in examples(page):
            checked += 1
            done = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=scratch, env=env,
                                  capture_output=True, text=True, timeout=600)
            got = done.stdout
            where = "%s:%d" % (os.path.relpath(page, source), line)
            if done.returncode != 0:
                failures += 1
                print("%s: '%s' exited %d:\n%s" % (where, command, done.returncode, done.stderr), file=sys.stderr)
            elif not checker.check_output(shown + "\n" if shown else "", got, doctest.ELLIPSIS):  # "": prints nothing
                failures += 1
                print("%s: '%s' prints what the page does not show:\n--- page\n%s\n--- program\n%s"
                      % (where, command, shown, got), file=sys.stderr)
    return checked, failures


if __name__ == "__main__":
    sys.exit(main(sys.argv))

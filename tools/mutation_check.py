#!/usr/bin/env python3
"""Mutation check: applies each named mutation of tools/mutations.json to the source
tree, builds the tests it names, runs them (ctest -R, default label) and reports
whether the suite kills it (a test fails). Every listed mutation must be killed; add
one whenever a bug slips past the tests. docs/testing.md describes it.

Each mutation: name, why, file (relative to the repository), search (must occur
exactly once), replace, targets (CMake test targets to build), tests (ctest -R regex).
The file is restored after each mutation, also on error or Ctrl-C, and the targets
are rebuilt from the restored tree at the end. With --scratch DIR the mutations are
applied to a copy of the work tree in DIR (configured in DIR/build), so that the
work tree and its build stay untouched and usable meanwhile.

Usage: python3 tools/mutation_check.py [--build-dir build | --scratch DIR] [--only NAME ...] [--list]
Exit status: 0 when every mutation run was killed, 1 otherwise."""

import argparse
import json
import os
import shlex
import shutil
import signal
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE = ROOT  # the tree mutated: the work tree, or its copy with --scratch


def run(cmd, log):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        return subprocess.run(cmd, cwd=SOURCE, stdout=f, stderr=subprocess.STDOUT).returncode


def check(mutation, build_dir, jobs, log):
    path = os.path.join(SOURCE, mutation["file"])
    with open(path) as f:
        original = f.read()
    count = original.count(mutation["search"])
    if count != 1:
        return f"error: the search string occurs {count} times in {mutation['file']}"
    try:
        with open(path, "w") as f:
            f.write(original.replace(mutation["search"], mutation["replace"]))
        if run(["cmake", "--build", build_dir, "-j", str(jobs), "--target", *mutation["targets"]], log) != 0:
            return "error: the mutant does not build (not a useful mutation)"
        # A regex that matches no test must not count as a kill (ctest's exit code alone
        # cannot tell "no tests" from "a test failed"), so the tests are counted first.
        listed = subprocess.run(["ctest", "--test-dir", build_dir, "-N", "-R", mutation["tests"], "-LE", "slow"],
                                cwd=SOURCE, capture_output=True, text=True).stdout
        if "Total Tests: 0" in listed or "Total Tests:" not in listed:
            return f"error: no test matches '{mutation['tests']}'"
        rc = run(["ctest", "--test-dir", build_dir, "-R", mutation["tests"], "-LE", "slow", "--no-tests=error",
                  "-j", str(jobs)], log)
        return "killed" if rc != 0 else "SURVIVED"
    finally:
        with open(path, "w") as f:
            f.write(original)


def make_scratch(scratch, log, cmake_args):
    """Copies the work tree's files (tracked and untracked, not ignored) to scratch and configures scratch/build."""
    files = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                           check=True, capture_output=True).stdout.decode().split("\0")
    for name in filter(None, files):
        source, target = os.path.join(ROOT, name), os.path.join(scratch, name)
        if not os.path.isfile(source):
            continue
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if not os.path.exists(target) or open(source, "rb").read() != open(target, "rb").read():
            shutil.copy2(source, target)
    build = os.path.join(scratch, "build")
    if run(["cmake", "-S", scratch, "-B", build, *cmake_args], log) != 0:
        sys.exit("cannot configure the scratch copy (see " + log + ")")
    return build


def main():
    global SOURCE
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--mutations", default=os.path.join(ROOT, "tools", "mutations.json"))
    parser.add_argument("--only", nargs="*", help="run only these mutations (by name)")
    parser.add_argument("--scratch", help="mutate a copy of the work tree in this directory instead")
    parser.add_argument("--cmake-args", default="",
                        help="configure options of the scratch build, e.g. '-DVISCOR_BUILD_CLI=OFF' (faster; the "
                             "tests that run the CLI then skip, so name only mutations that other tests kill)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--log", default=None, help="build and test output (default: BUILD_DIR/mutation_check.log)")
    parser.add_argument("--list", action="store_true", help="list the mutations and exit")
    args = parser.parse_args()
    with open(args.mutations) as f:
        mutations = json.load(f)
    if args.list:
        for m in mutations:
            print(f"{m['name']:32} {m['file']}: {m['why']}")
        return 0
    if args.only:
        unknown = set(args.only) - {m["name"] for m in mutations}
        if unknown:
            sys.exit("unknown mutations: " + ", ".join(sorted(unknown)))
        mutations = [m for m in mutations if m["name"] in args.only]
    if args.scratch:
        SOURCE = os.path.abspath(args.scratch)
        os.makedirs(SOURCE, exist_ok=True)
        log = args.log or os.path.join(SOURCE, "mutation_check.log")
        open(log, "w").close()
        args.build_dir = make_scratch(SOURCE, log, shlex.split(args.cmake_args))
    else:
        log = args.log or os.path.join(args.build_dir, "mutation_check.log")
        open(log, "w").close()
    # A kill restores the mutated file too (the finally clauses run).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("terminated"))
    results = []
    targets = set()
    try:
        for m in mutations:
            targets.update(m["targets"])
            status = check(m, args.build_dir, args.jobs, log)
            results.append((m["name"], status))
            print(f"{m['name']:32} {status}", flush=True)
    finally:
        if targets:  # leave the build tree as the source tree is
            run(["cmake", "--build", args.build_dir, "-j", str(args.jobs), "--target", *sorted(targets)], log)
    survived = [n for n, s in results if s != "killed"]
    print(f"{len(results) - len(survived)} of {len(results)} mutations killed (log: {log})")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())

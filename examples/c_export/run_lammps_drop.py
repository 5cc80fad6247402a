#!/usr/bin/env python3
"""Builds the committed C export as a shared library with plain `cc` and runs
lammps_drop.in (LAMMPS calling the export through its python command): with `damping
velocity` at its recommended dt = T/800 and at half of it, T/1600, with the loaded
conversion, and at T/800 with the unloaded one; with `damping tsuji` (the entry is the
e LAMMPS' polynomial reads) at T/400, T/800 and T/1600, and unloaded.

Checks: LAMMPS' Velocity Verlet with a velocity-dependent force is first order, so
the error in e halves with the step (measured 5.6e-5 at T/800; 1.1e-4 at T/400, which
is why the deck takes T/800): |e(T/800) - target| <= 1e-4, |e(T/1600) - target|
smaller, the ratio of the two errors in [1.5, 2.5], and the extrapolation
2 e(T/1600) - e(T/800) within 5e-6 of the target (what is left is the surrogate's
1e-13 and the second-order part of the stepping error).
The unloaded conversion must miss by more than 0.1 (measured: e = 0.298 for 0.5).
Tsuji: within 1e-4 at every step and closer at each halving (measured +5.3e-5, +1.4e-5,
-5.2e-6; its damping ~ x^(1/4) x' is not smooth where contact starts, so the error is
not first order), the unloaded entry off by more than 0.1 (measured e = 0.255).
Usage: run_lammps_drop.py SOURCE_DIR WORK_DIR [LMP]"""
import os
import re
import subprocess
import sys

source, work = sys.argv[1], sys.argv[2]
lmp = sys.argv[3] if len(sys.argv) > 3 else "lmp"
os.makedirs(work, exist_ok=True)
lib = os.path.join(work, "libviscor_surrogates.so")
subprocess.run(["cc", "-std=c99", "-O2", "-shared", "-fPIC", os.path.join(source, "viscor_surrogates.c"), "-lm", "-o", lib],
               check=True)


def rebound_e(*variables):
    command = [lmp, "-in", os.path.join(source, "lammps_drop.in"), "-log", "none", "-var", "lib", lib, *variables]
    out = subprocess.run(command, check=True, capture_output=True, text=True, cwd=work).stdout
    for line in out.splitlines():
        if line.startswith("viscor:"):
            print(line)
    found = re.search(r"^rebound e = (\S+) \(target (\S+)\)", out, re.M)
    if not found:
        sys.exit("no rebound e in the output of " + " ".join(command) + ":\n" + out)
    print(f"rebound e = {found.group(1)} (target {found.group(2)})")
    return float(found.group(1)), float(found.group(2))


e800, target = rebound_e()  # the deck's own step, T/800
e1600, _ = rebound_e("-var", "per_T", "1600")
unloaded, _ = rebound_e("-var", "conversion", "unloaded")
d800, d1600, extrapolated = abs(e800 - target), abs(e1600 - target), abs(2 * e1600 - e800 - target)
print(f"|e - target|: {d800:.3e} at T/800, {d1600:.3e} at T/1600 (ratio {d800 / d1600:.2f}); "
      f"extrapolated {extrapolated:.3e}; unloaded conversion {abs(unloaded - target):.3e}")
failures = []
if not d800 <= 1e-4:
    failures.append("e at the deck's T/800 misses the target by more than 1e-4")
if not d1600 < d800:
    failures.append("e at half the step is not closer to the target")
if not 1.5 <= d800 / d1600 <= 2.5:
    failures.append("the error does not halve with the step")
if not extrapolated <= 5e-6:
    failures.append("the extrapolated e misses the target by more than 5e-6")
if not abs(unloaded - target) > 0.1:
    failures.append("the unloaded conversion should miss by more than 0.1")
tsuji = [rebound_e("-var", "damping", "tsuji", "-var", "per_T", str(n))[0] for n in (400, 800, 1600)]
tsuji_unloaded, _ = rebound_e("-var", "damping", "tsuji", "-var", "conversion", "unloaded")
misses = [abs(e - target) for e in tsuji]
print(f"tsuji |e - target|: {misses[0]:.3e} at T/400, {misses[1]:.3e} at T/800, {misses[2]:.3e} at T/1600; "
      f"unloaded entry {abs(tsuji_unloaded - target):.3e}")
if not max(misses) <= 1e-4:
    failures.append("tsuji: e misses the target by more than 1e-4")
if not misses[0] > misses[1] > misses[2]:
    failures.append("tsuji: e does not come closer as the step halves")
if not abs(tsuji_unloaded - target) > 0.1:
    failures.append("tsuji: the unloaded entry should miss by more than 0.1")
if failures:
    sys.exit("FAILED: " + "; ".join(failures))

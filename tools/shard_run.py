#!/usr/bin/env python3
"""Runs a table as W concurrent one-thread shard processes and measures it.

For each W given, starts `viscor table SPEC --shard i/W --threads 1 --quiet` for
i = 0..W-1 at once (W = 1: the whole table, no --shard), waits for all, merges
the shards with `viscor table merge` and checks that the merged CSV is byte for
byte the first run's table. Prints the wall time, the CPU time (user + system) of
all shard processes, the slowest/mean shard CPU, the wall-time speed-up over the
first run, the CPU speed-up (the first one-worker run's CPU time over the slowest
shard's: the wall-time speed-up W free cores would give) and the load average
before the run (the machine may be shared: the wall-time speed-up is only
meaningful when W cores are free).

Usage:
  tools/shard_run.py VISCOR SPEC.json --workers 1,2
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time


def run(viscor, spec, workers, work, attempt):
    out = os.path.join(work, f"run{attempt}-w{workers}")
    os.makedirs(out)
    load = os.getloadavg()[0]
    start = time.monotonic()
    procs = {}
    for i in range(workers):
        cmd = [viscor, "table", spec, "-o", os.path.join(out, f"part-{i}.csv"), "--threads", "1", "--quiet"]
        if workers > 1:
            cmd += ["--shard", f"{i}/{workers}"]
        procs[subprocess.Popen(cmd).pid] = i
    cpu = [0.0] * workers
    while procs:
        pid, status, usage = os.wait4(-1, 0)
        if pid in procs:
            if os.waitstatus_to_exitcode(status) != 0:
                sys.exit(f"shard_run: shard {procs[pid]} of {workers} failed")
            cpu[procs.pop(pid)] = usage.ru_utime + usage.ru_stime
    wall = time.monotonic() - start
    table = os.path.join(out, "part-0.csv")
    if workers > 1:
        table = os.path.join(out, "table.csv")
        subprocess.run([viscor, "table", "merge", *[os.path.join(out, f"part-{i}.csv") for i in range(workers)],
                        "-o", table], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return wall, cpu, load, table


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("viscor")
    p.add_argument("spec")
    p.add_argument("--workers", default="1,2")
    a = p.parse_args()
    viscor, spec = os.path.abspath(a.viscor), os.path.abspath(a.spec)
    with tempfile.TemporaryDirectory(prefix="viscor-shard-run-") as work:
        first = None
        first_cpu = None
        print(f"{'workers':>7s} {'wall s':>8s} {'CPU s':>8s} {'slowest/mean CPU':>16s} {'speed-up':>8s} "
              f"{'CPU speed-up':>12s} {'load before':>11s}")
        for attempt, w in enumerate(int(x) for x in a.workers.split(",")):
            wall, cpu, load, table = run(viscor, spec, w, work, attempt)
            if first is None:
                first = (wall, table)
            else:
                with open(first[1], "rb") as f1, open(table, "rb") as f2:
                    if f1.read() != f2.read():
                        sys.exit(f"shard_run: the merged table of {w} workers differs from the first run's")
            if w == 1 and first_cpu is None:
                first_cpu = sum(cpu)
            print(f"{w:7d} {wall:8.1f} {sum(cpu):8.1f} {max(cpu) / (sum(cpu) / w):16.3f} "
                  f"{first[0] / wall:8.2f} {(first_cpu or sum(cpu)) / max(cpu):12.2f} {load:11.2f}", flush=True)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Measures the CPU time of table rows, one row per `viscor table` process.

For a grid spec (a CoR table spec, docs/tables.md), every `stride`-th gamma value
of every law and g block is computed alone (a one-row spec, --threads 1) at the
given digits and methods, and the CPU time (user + system) of that process,
less the start-up cost of the program (the median CPU time of `viscor --version`),
is written as one CSV line:

    index,law,g,gamma,digits,method,outcome,cpu_seconds

`index` is the row's index in the full table, so tools/shard_balance.py can map
the sample onto the table. The CSV is what docs/performance.md ("Tables on many
machines") is computed from; the commands that made the committed files are
there.

Usage:
  tools/cost_measure.py VISCOR SPEC.json --digits 50 --methods certify,proven \
      --stride 5 -o costs.csv
"""

import argparse
import csv
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from decimal import Decimal


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cpu(command, cwd):
    before = child_cpu()
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {' '.join(command)} failed: {done.stderr.strip()}")
    return child_cpu() - before


def axis_values(axis):
    """The values of a gamma or g axis as exact decimals, sorted, duplicates once."""
    items = axis if isinstance(axis, list) else [axis]
    values = set()
    for item in items:
        if isinstance(item, dict) and "value" in item:
            values.add(Decimal(str(item["value"])))
        elif isinstance(item, dict):
            lo, hi = Decimal(str(item["from"])), Decimal(str(item["to"]))
            if "step" in item:
                step = Decimal(str(item["step"]))
                n = int((hi - lo) / step)
                values.update(lo + k * step for k in range(n + 1))
            else:
                if item.get("spacing", "linear") != "linear":
                    sys.exit("cost_measure: log ranges are not supported; list the values")
                count = int(item["count"])
                step = (hi - lo) / (count - 1)
                values.update(lo + k * step for k in range(count))
        else:
            values.add(Decimal(str(item)))
    return sorted(values)


def text(d):
    s = format(d.normalize(), "f")
    return s if s != "-0" else "0"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("viscor")
    p.add_argument("spec")
    p.add_argument("--digits", default="50", help="comma-separated digits (default 50)")
    p.add_argument("--methods", default="certify,proven", help="comma-separated table methods")
    p.add_argument("--stride", type=int, default=5, help="every stride-th gamma of each block (default 5)")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--resume", action="store_true", help="keep the rows already in OUTPUT, measure the others")
    a = p.parse_args()

    with open(a.spec) as f:
        spec = json.load(f)
    laws = spec.get("laws", spec.get("law"))
    laws = laws if isinstance(laws, list) else [laws]
    gammas = axis_values(spec["gamma"])
    gs = axis_values(spec["g"])
    viscor = os.path.abspath(a.viscor)

    with tempfile.TemporaryDirectory(prefix="viscor-cost-") as work:
        startup = statistics.median(run_cpu([viscor, "--version"], work) for _ in range(21))
        done = set()
        if a.resume and os.path.exists(a.output):
            with open(a.output) as f:
                done = {(r["index"], r["digits"], r["method"]) for r in csv.DictReader(f)}
        with open(a.output, "a" if done else "w", newline="") as out:
            w = csv.writer(out, lineterminator="\n")
            if not done:
                w.writerow(["index", "law", "g", "gamma", "digits", "method", "outcome", "cpu_seconds"])
            index = 0
            for law in laws:
                for g in gs:
                    for k, gamma in enumerate(gammas):
                        if k % a.stride == 0:
                            for digits in a.digits.split(","):
                                for method in a.methods.split(","):
                                    if (str(index), digits, method) in done:
                                        continue
                                    one = {"laws": [law], "gamma": text(gamma), "g": text(g),
                                           "digits": int(digits), "method": method}
                                    with open(os.path.join(work, "row.json"), "w") as f:
                                        json.dump(one, f)
                                    cpu = run_cpu([viscor, "table", "row.json", "-o", "row.csv", "--threads", "1",
                                                   "--quiet"], work)
                                    with open(os.path.join(work, "row.csv")) as f:
                                        row = list(csv.DictReader(f))[0]
                                    w.writerow([index, law if isinstance(law, str) else json.dumps(law), text(g),
                                                text(gamma), digits, method, row["outcome"],
                                                f"{max(cpu - startup, 0.0):.4f}"])
                                    out.flush()
                        index += 1
        print(f"cost_measure: start-up {startup:.4f} s CPU subtracted; wrote {a.output}", file=sys.stderr)


if __name__ == "__main__":
    main()

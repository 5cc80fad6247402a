#!/usr/bin/env python3
"""Cost model of table rows, and the plan for a large table, from measured costs (no SciPy).

Input: CSV files of per-row CPU times written by tools/cost_measure.py.

  tools/cost_model.py summary COSTS.csv...
      mean, median and largest CPU-seconds per row by law, g (the region: g = 0,
      small g, g = 1 near and past sticking), outcome, digits and method.

  tools/cost_model.py threshold COSTS.csv [--digits 50 --method proven]
      the cost of the sampled rows beside each switch from rebound to stick (the
      sticking threshold), against the median of their law and g block.

  tools/cost_model.py sum COSTS.csv --block 1001 --every 4 [--digits 50 --method proven]
      the summed cost of every 4th sampled row of each law and g block: what a
      table of those rows should cost, to compare with its measured CPU time.

  tools/cost_model.py scaling COSTS.csv --rows 15015 --block 1001 --digits 50 \
      --method proven [--table-rows 1000000] [--start 0.02] [--hours 24]
      the predicted wall time and speed-up of 1, 2, 4, ..., 256 workers, each
      computing one interleaved shard (`viscor table --shard i/W`) with one thread,
      simulated from the measured per-row costs: row t of the simulated table is row
      t % rows of the measured table, with the measured cost of one of the four
      sampled rows nearest to it drawn at random (so the simulated rows keep the
      measured spread from row to row, timing noise included): a worker's time
      is --start seconds (program start and spec parsing; a batch scheduler adds its
      own) plus the sum of its rows' costs, and the table is done when the slowest
      worker is. Then the number of workers that make the whole table in --hours.
"""

import argparse
import collections
import csv
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shard_balance import full_costs, load_costs, resampled_costs  # noqa: E402


def summary(paths):
    groups = collections.defaultdict(list)
    for path in paths:
        with open(path) as f:
            for r in csv.DictReader(f):
                groups[(r["law"], r["g"], r["outcome"], int(r["digits"]), r["method"])].append(float(r["cpu_seconds"]))
    print(f"{'law':22s} {'g':>5s} {'outcome':8s} {'digits':>6s} {'method':8s} {'rows':>5s} "
          f"{'mean ms':>8s} {'median':>8s} {'max':>8s}")
    for key in sorted(groups):
        v = groups[key]
        print(f"{key[0]:22s} {key[1]:>5s} {key[2]:8s} {key[3]:6d} {key[4]:8s} {len(v):5d} "
              f"{1000 * statistics.fmean(v):8.1f} {1000 * statistics.median(v):8.1f} {1000 * max(v):8.1f}")
    by = collections.defaultdict(list)
    per_law = collections.defaultdict(list)
    for (law, g, outcome, digits, method), v in groups.items():
        by[(digits, method)].extend(v)
        per_law[(law, digits, method)].extend(v)
        per_law[("all laws", digits, method)].extend(v)
    columns = sorted(by)
    print("\nmean ms a row by law (all g and outcomes)")
    print(f"{'law':22s}" + "".join(f" {f'{d} {m}':>12s}" for d, m in columns))
    laws = list(dict.fromkeys(k[0] for k in sorted(groups))) + ["all laws"]
    for law in laws:
        print(f"{law:22s}" + "".join(f" {1000 * statistics.fmean(per_law[(law, d, m)]):12.1f}"
                                     if per_law[(law, d, m)] else f" {'':>12s}" for d, m in columns))
    print()
    for (digits, method), v in sorted(by.items()):
        print(f"all laws, {digits} digits, {method}: {len(v)} rows, mean {1000 * statistics.fmean(v):.1f} ms a row")


def threshold(a):
    """The sampled rows on either side of each rebound/stick switch of a law and g block,
    against the block's median cost."""
    blocks = collections.defaultdict(list)
    with open(a.costs) as f:
        for r in csv.DictReader(f):
            if r["digits"] == str(a.digits) and r["method"] == a.method:
                blocks[(r["law"], r["g"])].append(r)
    for (law, g), rs in blocks.items():
        rs.sort(key=lambda r: int(r["index"]))
        median = statistics.median(float(r["cpu_seconds"]) for r in rs)
        for i in range(1, len(rs)):
            if rs[i]["outcome"] != rs[i - 1]["outcome"]:
                near = rs[max(0, i - a.around):i + a.around]
                print(f"{law} g = {g}: {rs[i - 1]['outcome']} -> {rs[i]['outcome']} between gamma = "
                      f"{rs[i - 1]['gamma']} and {rs[i]['gamma']}; block median {1000 * median:.1f} ms; beside it: " +
                      ", ".join(f"{r['gamma']} {1000 * float(r['cpu_seconds']):.1f} ms "
                                f"({float(r['cpu_seconds']) / median:.2f}x)" for r in near))


def sum_every(a):
    """The summed cost of every k-th sampled row of each block (block: --block table rows)."""
    rows = load_costs(a.costs, a.digits, a.method)
    stride = a.block // (sum(1 for i in rows if i < a.block) - 1)  # table rows between two samples
    picked = [c for i, c in rows.items() if (i % a.block) % (stride * a.every) == 0]
    print(f"{len(picked)} rows (every {a.every}th sample, every {stride * a.every}th gamma), {a.method} at "
          f"{a.digits} digits: {sum(picked):.1f} CPU-s measured one row per process")


def scaling(a):
    n = a.table_rows or a.rows
    costs = resampled_costs(load_costs(a.costs, a.digits, a.method), a.rows, a.block, n)
    total = sum(costs)
    print(f"{n} rows, {a.method} at {a.digits} digits: {total:.0f} CPU-s ({total / 3600:.2f} CPU-h), "
          f"{1000 * total / n:.1f} ms a row; start-up {a.start} s a worker")
    print(f"{'workers':>7s} {'wall s':>10s} {'speed-up':>9s} {'efficiency':>10s} {'slowest/mean':>12s}")
    one = total + a.start
    w = 1
    while w <= 256:
        shards = [0.0] * w
        for i, c in enumerate(costs):
            shards[i % w] += c
        wall = max(shards) + a.start
        print(f"{w:7d} {wall:10.1f} {one / wall:9.2f} {one / wall / w:10.3f} {max(shards) / (total / w):12.3f}")
        w *= 2
    budget = a.hours * 3600
    w = max(1, math.ceil(total / budget))
    while True:
        shards = [0.0] * w
        for i, c in enumerate(costs):
            shards[i % w] += c
        if max(shards) + a.start <= budget:
            break
        w += 1
    print(f"{a.hours} h: {w} workers (one core each), slowest shard {(max(shards) + a.start) / 3600:.2f} h")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("summary")
    s.add_argument("costs", nargs="+")
    c = sub.add_parser("scaling")
    c.add_argument("costs")
    c.add_argument("--rows", type=int, required=True)
    c.add_argument("--block", type=int, required=True)
    c.add_argument("--digits", default="50")
    c.add_argument("--method", default="proven")
    c.add_argument("--table-rows", type=int, default=0, help="rows of the simulated table (default: --rows)")
    c.add_argument("--start", type=float, default=0.02, help="seconds to start one worker")
    c.add_argument("--hours", type=float, default=24)
    e = sub.add_parser("sum")
    e.add_argument("costs")
    e.add_argument("--block", type=int, required=True)
    e.add_argument("--every", type=int, required=True)
    e.add_argument("--digits", default="50")
    e.add_argument("--method", default="proven")
    t = sub.add_parser("threshold")
    t.add_argument("costs")
    t.add_argument("--digits", default="50")
    t.add_argument("--method", default="proven")
    t.add_argument("--around", type=int, default=3, help="sampled rows on each side")
    a = p.parse_args()
    if a.command == "threshold":
        threshold(a)
    elif a.command == "summary":
        summary(a.costs)
    elif a.command == "sum":
        sum_every(a)
    else:
        scaling(a)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Shard balance of a table from measured per-row costs (no SciPy).

Reads the per-row CPU times that tools/cost_measure.py wrote for a sample of a
table's rows (every stride-th gamma of each law and g block), fills in the rows
between two sampled ones by linear interpolation in the row index within their
block, and reports, for N shards, the cost of the slowest shard over the mean
shard cost for

  interleaved: row % N == i (what `viscor table --shard i/N` computes), and
  contiguous:  N consecutive runs of rows of (almost) equal length.

The same two figures for the measured rows alone, taken as a table of their own
(no interpolation, so each row's own timing noise is in them), are printed beside.

Usage:
  tools/shard_balance.py COSTS.csv --rows 15015 --block 1001 --digits 50 \
      --method proven --shards 32
  (--block: rows per law and g block, that is the number of gamma values; the
  sampled rows must include the first and the last row of each block.)
"""

import argparse
import csv
import random
import sys


def load_costs(path, digits, method):
    costs = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            if r["digits"] == str(digits) and r["method"] == method:
                costs[int(r["index"])] = float(r["cpu_seconds"])
    if not costs:
        sys.exit(f"shard_balance: no rows at {digits} digits, method {method} in {path}")
    return costs


def full_costs(sampled, rows, block):
    """A cost for every row 0..rows-1, interpolated between sampled rows of the same block."""
    out = [0.0] * rows
    for start in range(0, rows, block):
        end = min(start + block, rows)
        known = sorted(i for i in sampled if start <= i < end)
        if not known or known[0] != start or known[-1] != end - 1:
            sys.exit(f"shard_balance: block {start}..{end - 1} must have its first and last rows sampled")
        for a, b in zip(known, known[1:]):
            for i in range(a, b + 1):
                t = (i - a) / (b - a)
                out[i] = (1 - t) * sampled[a] + t * sampled[b]
    return out


def resampled_costs(sampled, rows, block, n, seed=1):
    """n rows of synthetic costs: row t is row t % rows of the table, and its cost the
    measured cost of one of the (up to) four sampled rows nearest to it in its block,
    drawn at random (fixed seed), so that the rows keep the measured row-to-row spread."""
    rng = random.Random(seed)
    near = []
    for start in range(0, rows, block):
        known = sorted(i for i in sampled if start <= i < min(start + block, rows))
        for i in range(start, min(start + block, rows)):
            near.append([sampled[k] for k in sorted(known, key=lambda k: (abs(k - i), k))[:4]])
    return [rng.choice(near[t % rows]) for t in range(n)]


def shard_costs(costs, shards, assignment):
    total = [0.0] * shards
    n = len(costs)
    for i, c in enumerate(costs):
        if assignment == "interleaved":
            total[i % shards] += c
        else:  # contiguous: shard k holds rows [k n / N, (k + 1) n / N)
            total[i * shards // n] += c
    return total


def ratio(totals):
    return max(totals) / (sum(totals) / len(totals))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("costs")
    p.add_argument("--rows", type=int, required=True, help="rows of the full table")
    p.add_argument("--block", type=int, required=True, help="rows per law and g block (gamma values)")
    p.add_argument("--digits", default="50")
    p.add_argument("--method", default="proven")
    p.add_argument("--shards", default="32", help="comma-separated shard counts")
    p.add_argument("--max-ratio", type=float, default=None,
                   help="exit 1 when an interleaved slowest/mean (full table) exceeds this")
    a = p.parse_args()

    sampled = load_costs(a.costs, a.digits, a.method)
    costs = full_costs(sampled, a.rows, a.block)
    measured = [sampled[i] for i in sorted(sampled)]  # the measured rows alone, as a table of their own
    print(f"{a.costs}: {a.rows} rows ({len(sampled)} measured), "
          f"{a.method} at {a.digits} digits, {sum(costs):.1f} CPU-s in all, {sum(costs) / a.rows * 1000:.1f} ms a row")
    print("        full table (interpolated)       the measured rows alone")
    print("shards  interleaved  contiguous         interleaved  contiguous   (slowest shard / mean)")
    worst = 0.0
    for n in (int(x) for x in a.shards.split(",")):
        worst = max(worst, ratio(shard_costs(costs, n, "interleaved")))
        print(f"{n:6d}  {ratio(shard_costs(costs, n, 'interleaved')):11.3f}  "
              f"{ratio(shard_costs(costs, n, 'contiguous')):10.3f}         "
              f"{ratio(shard_costs(measured, n, 'interleaved')):11.3f}  "
              f"{ratio(shard_costs(measured, n, 'contiguous')):10.3f}")
    if a.max_ratio is not None and worst > a.max_ratio:
        sys.exit(f"shard_balance: interleaved slowest/mean {worst:.3f} exceeds {a.max_ratio}")


if __name__ == "__main__":
    main()

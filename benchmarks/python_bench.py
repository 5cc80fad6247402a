#!/usr/bin/env python3
"""Cost of the Python module (docs/performance.md, "Python module").

1. viscor.cor at 50 digits against the C++ solve it wraps: the wall time of each
   Python call (parsing, the solve, the JSON-named result) against the solve's own
   time, measured inside C++ around solve_impact (the result's `seconds`), over the
   same calls. Ratio = median call / median solve.
2. viscor.evaluate throughput: N points (gamma uniform in [1e-3, 0.1], g in [0, 1])
   at tol in double on all cores, optionally with a surrogate.

  PYTHONPATH=build/python python3 benchmarks/python_bench.py [--calls 200] [--points 1000000] [--tol 1e-4]
      [--law kuwabara_kono] [--threads 0] [--surrogate default|none|committed|FILE]
"""
import argparse
import os
import statistics
import time

import viscor


def bench_cor(calls, law, gamma, g, digits):
    viscor.cor(law, gamma, g, digits=digits)  # warm-up: first-call allocations, MPFR caches
    walls, solves = [], []
    for _ in range(calls):
        start = time.perf_counter()
        r = viscor.cor(law, gamma, g, digits=digits)
        walls.append(time.perf_counter() - start)
        solves.append(r.seconds)
    return statistics.median(walls), statistics.median(solves), min(walls), min(solves)


def bench_evaluate(points, tol, law, threads, surrogate):
    import numpy as np
    rng = np.random.default_rng(1)
    gamma = rng.uniform(1e-3, 0.1, points)
    g = rng.uniform(0, 1, points)
    start = time.perf_counter()
    r = viscor.evaluate(law, gamma, g, tol, threads=threads, surrogate=surrogate)
    seconds = time.perf_counter() - start
    methods = np.bincount(r.method, minlength=len(viscor.EVALUATION_METHODS))
    used = {viscor.EVALUATION_METHODS[k]: int(n) for k, n in enumerate(methods) if n}
    return seconds, used, float(r.empirical_bound.max())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--calls", type=int, default=200)
    parser.add_argument("--law", default="kuwabara_kono")
    parser.add_argument("--gamma", default="0.05")
    parser.add_argument("--g", default="1")
    parser.add_argument("--digits", type=int, default=50)
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--tol", type=float, default=1e-4)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--surrogate", default="default",
                        help="'default' (evaluate's default: the law's committed surrogate where there is one), "
                             "'none', 'committed' (the law's, an error without one) or a file")
    a = parser.parse_args()
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    if a.calls:
        wall, solve, wall_min, solve_min = bench_cor(a.calls, a.law, a.gamma, a.g, a.digits)
        print(f"cor {a.law} gamma={a.gamma} g={a.g} digits={a.digits}, {a.calls} calls: median call "
              f"{wall * 1e3:.3f} ms, median solve {solve * 1e3:.3f} ms, ratio {wall / solve:.3f} "
              f"(minima {wall_min * 1e3:.3f} / {solve_min * 1e3:.3f} ms)")
    if a.points:
        surrogate = {"committed": True, "none": None}.get(a.surrogate, a.surrogate)
        seconds, used, worst = bench_evaluate(a.points, a.tol, a.law, a.threads, surrogate)
        print(f"evaluate {a.law}, {a.points} points (gamma 1e-3..0.1, g 0..1) at tol {a.tol:g}, threads "
              f"{a.threads or os.cpu_count()}: {seconds:.3f} s ({a.points / seconds:.3g} points/s); "
              f"largest bound {worst:.2e}; methods {used}")


if __name__ == "__main__":
    main()

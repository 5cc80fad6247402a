#!/usr/bin/env python3
"""The cost model of `viscor table --estimate`: CPU seconds per row by law, working
digits and table method, measured as whole tables, one `viscor table` process each
(--threads 1), over a calibration grid (gamma 0.01 to 0.1 in steps of 0.01, g 0,
0.05 and 1: 30 rows per law). Each table's CPU time (user + system of the process,
less the median CPU time of `viscor --version`) is divided by its rows:

    law,digits,method,rows,cpu_seconds_per_row

The digits are those where the arithmetic changes (15 double, 18 long double, 30
double-double, 33 float128) and MPFR's 40 to 150; src/jobs/table_estimate.cpp holds
the numbers of the committed file tools/cost_data/row_cost_by_digits.csv
(tests/table_estimate_test.cpp checks they agree), and docs/performance.md ("Cost
before work") how the estimate compares with real runs.

It also writes the same numbers as the C++ initialisers that src/jobs/table_estimate.cpp
includes (--inc).

Usage:
  tools/cost_by_digits.py build/viscor -o tools/cost_data/row_cost_by_digits.csv \
      --inc src/jobs/row_cost_by_digits.inc
"""

import argparse
import csv
import json
import os
import statistics
import sys
import tempfile

from cost_measure import run_cpu  # CPU seconds of one command (tools/ is on the path)

LAWS = ["linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"]
DIGITS = [15, 18, 30, 33, 40, 50, 70, 100, 150]
METHODS = ["certify", "proven"]
GRID = {"gamma": [{"from": 0.01, "to": 0.1, "step": 0.01}], "g": [0, 0.05, 1]}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("viscor")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--inc", required=True, help="the C++ initialisers of src/jobs/table_estimate.cpp")
    a = p.parse_args()
    viscor = os.path.abspath(a.viscor)
    with tempfile.TemporaryDirectory(prefix="viscor-cost-") as work:
        startup = statistics.median(run_cpu([viscor, "--version"], work) for _ in range(21))
        with open(a.output, "w", newline="") as out:
            w = csv.writer(out, lineterminator="\n")
            w.writerow(["law", "digits", "method", "rows", "cpu_seconds_per_row"])
            for law in LAWS:
                for digits in DIGITS:
                    for method in METHODS:
                        spec = dict(GRID, laws=[law], digits=digits, method=method)
                        with open(os.path.join(work, "spec.json"), "w") as f:
                            json.dump(spec, f)
                        for name in os.listdir(work):
                            if name.startswith("t.csv"):
                                os.remove(os.path.join(work, name))
                        cpu = run_cpu([viscor, "table", "spec.json", "-o", "t.csv", "--threads", "1", "--quiet"], work)
                        with open(os.path.join(work, "t.csv")) as f:
                            rows = sum(1 for _ in csv.DictReader(f))
                        w.writerow([law, digits, method, rows, f"{max(cpu - startup, 0.0) / rows:.6f}"])
                        out.flush()
                        print(f"cost_by_digits: {law} {digits} {method}: {cpu:.2f} s CPU, {rows} rows",
                              file=sys.stderr)
    write_initialisers(a.output, a.inc)


def write_initialisers(csv_path, inc_path):
    """{law, digits, certify, proven} per law and digits, from the CSV just written."""
    costs = {}
    with open(csv_path) as f:
        for r in csv.DictReader(f):
            costs.setdefault((r["law"], int(r["digits"])), {})[r["method"]] = r["cpu_seconds_per_row"]
    with open(inc_path, "w") as f:
        f.write(f"// Written by tools/cost_by_digits.py from {os.path.basename(csv_path)}: law, digits, CPU seconds per row\n"
                "// certified, and certified and proven. Do not edit; measure again.\n")
        for (law, digits), m in costs.items():
            f.write(f'{{"{law}", {digits}, {m["certify"]}, {m["proven"]}}},\n')


if __name__ == "__main__":
    main()

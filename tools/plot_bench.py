#!/usr/bin/python3
"""Accuracy versus time per CoR, one point per method, from `viscor bench --json`.

  viscor bench --certified --precisions 30,50,100,200 --error-maps reference_data/error_maps \
      --json -o bench.json
  tools/plot_bench.py bench.json docs/figures/bench_accuracy_time.png

x: median time per CoR (s); y: max absolute error of e over the bench's point set
(against the certified tables), filled; the median error, hollow. Needs Debian's
python3-matplotlib.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"approx": ("s", "C1"), "surrogate": ("*", "C4"), "taylor": ("o", "C0"), "certify": ("D", "C3"),
           "evaluate": ("^", "C2")}


def main(source, target):
    with open(source) as f:
        bench = json.load(f)
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for n, row in enumerate(bench["rows"]):
        if not row["points"] or not row["max_abs_error"]:
            continue
        error = float(row["max_abs_error"])
        # An exact zero error (e = 1 or a certified stick everywhere) has no place on log axes.
        if error <= 0:
            continue
        kind = row["method"].split()[0]
        marker, colour = MARKERS.get(kind, ("x", "k"))
        ax.loglog(row["median_seconds"], error, marker=marker, color=colour, linestyle="none")
        if row["median_abs_error"] and float(row["median_abs_error"]) > 0:
            ax.loglog(row["median_seconds"], float(row["median_abs_error"]), marker=marker, color=colour,
                      markerfacecolor="none", linestyle="none")
        scalar = row.get("scalar", row.get("precision", ""))  # "precision" in files written before 0.2.0
        label = row["method"].replace("approx ", "") + ("" if scalar == "double" else ", " + scalar)
        # Alternate label heights: the approximations sit close together.
        ax.annotate(label, (row["median_seconds"], error), textcoords="offset points", xytext=(5, 3 + 9 * (n % 3)),
                    fontsize=7)
    for kind, (marker, colour) in MARKERS.items():
        ax.plot([], [], marker=marker, color=colour, linestyle="none", label=kind)
    ax.set_ylim(top=1e4)  # room for the labels of the approximations
    ax.set_xlabel("median time per CoR (s)")
    ax.set_ylabel("absolute error of e: max (filled), median (hollow)")
    ax.set_title("viscor: accuracy versus time (" + bench.get("laws", "") + ")", fontsize=9)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)
    fig.text(0.01, 0.01, "reference: " + bench.get("reference", ""), fontsize=6)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(target, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: tools/plot_bench.py bench.json out.png")
    main(sys.argv[1], sys.argv[2])

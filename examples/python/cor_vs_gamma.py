#!/usr/bin/env python3
"""e against gamma for Kuwabara-Kono at g = 0, 0.05, 1 and 10, with Prop. 2's
approximation (36) and its absolute error: the figure docs/figures/cor_kuwabara_kono.png
of docs/tables.md (drawn there by tools/plot_reference.py from the committed
tables), here from Python: the reference curve by viscor.evaluate to 1e-10, the
approximation by viscor.approx. Before drawing, the reference curve is checked
against the committed certified tables reference_data/cor_report_grid.csv and
reference_data/cor_report_g10_kuwabara_kono.csv.

  build/python/python3 examples/python/cor_vs_gamma.py [--out DIR] [--points N]
Needs NumPy and matplotlib (Debian: python3-numpy python3-matplotlib).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import viscor  # noqa: E402

LAW = "kuwabara_kono"
LOADS = ("0", "0.05", "1", "10")
GAMMA_MAX = {"10": 0.00184}  # the report's range at g = 10 (reference_data/cor_report_g10_*.csv); else 0.1
SOURCES = (("exact_at_zero", "Exact coeffs. (39),(40)", "C2", "-"),
           ("numeric", "Num. coeffs. (41),(42)", "C1", "--"),
           ("chebyshev_beta", "Approx. coeffs. (48),(49)", "C3", ":"))


def check_against_certified_table(repository):
    """The evaluate curve agrees with the certified rows within its bound (raises otherwise)."""
    path = "reference_data/cor_report_grid.csv and cor_report_g10_" + LAW + ".csv"
    rows = []
    for name in ("cor_report_grid.csv", f"cor_report_g10_{LAW}.csv"):
        with open(os.path.join(repository, "reference_data", name), newline="") as f:
            rows += [r for r in csv.DictReader(f) if r["law"] == LAW]
    gamma = np.array([float(r["gamma"]) for r in rows])
    g = np.array([float(r["g"]) for r in rows])
    ref = np.array([float(r["e"]) for r in rows])
    r = viscor.evaluate(LAW, gamma, g, 1e-10)
    worst = np.max(np.abs(r.e - ref) - r.empirical_bound)
    if worst > 1e-15:
        raise SystemExit(f"evaluate disagrees with {path} beyond its bound by {worst:.2e}")
    return len(rows)


def prop2_curves(gamma, g):
    """e of Prop. 2 for each coefficient source (NaN where it does not apply)."""
    curves = {source: np.full(len(gamma), np.nan) for source, *_ in SOURCES}
    for i, x in enumerate(gamma):
        r = viscor.approx(LAW, repr(float(x)), g, formula="prop2")
        prop2 = r.get("prop2")
        if prop2 is None:
            continue
        for source in curves:
            if source in prop2 and "e" in prop2[source]:
                curves[source][i] = float(prop2[source].e)
    return curves


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=".", help="directory of the figure cor_kuwabara_kono.png")
    parser.add_argument("--points", type=int, default=100, help="gamma values per curve")
    parser.add_argument("--repository", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    a = parser.parse_args()

    checked = check_against_certified_table(a.repository)
    fig, axes = plt.subplots(2, len(LOADS), figsize=(3.2 * len(LOADS), 5.6), squeeze=False)
    for j, g in enumerate(LOADS):
        gamma = np.linspace(0, GAMMA_MAX.get(g, 0.1), a.points)
        ref = viscor.evaluate(LAW, gamma, float(g), 1e-10)
        top, bottom = axes[0][j], axes[1][j]
        top.plot(gamma, ref.e, "k-", lw=2.5, alpha=0.35, label="viscor.evaluate (1e-10)")
        curves = prop2_curves(gamma, g)
        for source, label, color, style in SOURCES:
            e = curves[source]
            top.plot(gamma, e, color=color, ls=style, label=label)
            err = np.abs(e - ref.e)
            bottom.semilogy(gamma[1:], np.maximum(err[1:], 1e-17), color=color, ls=style)
        top.set_title(f"g = {g}")
        top.set_xlabel("gamma")
        bottom.set_xlabel("gamma")
        if j == 0:
            top.set_ylabel("e")
            bottom.set_ylabel("|e - e_ref|")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("Kuwabara-Kono (alpha = beta = 3/2): Prop. 2 against the reference")
    fig.tight_layout()
    path = os.path.join(a.out, "cor_kuwabara_kono.png")
    fig.savefig(path, dpi=110)
    print(f"wrote {path} ({checked} certified rows checked)")


if __name__ == "__main__":
    main()

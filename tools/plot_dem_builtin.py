#!/usr/bin/python3
"""Figure of reference_data/dem/builtin_conversion_error.csv: the e the codes'
own conversions produce when the target e is written into the deck, as error in
e and in % of (1 - e), against the target, for a bead on a rigid wall under
gravity (dash-dot: v0 = 0.001 m/s, solid: 0.01, dashed: 0.1, dotted: 1; grey: no load).
Needs Debian's python3-matplotlib.

  tools/plot_dem_builtin.py [--data reference_data/dem] [--out docs/figures]
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLORS = {"steel": "C0", "glass": "C2", "polymer": "C3"}
STYLES = {"0.001": "-.", "0.01": "-", "0.1": "--", "1": ":"}
TITLES = {("lammps", "tsuji"): "LAMMPS 29Sep2021, damping tsuji",
          ("liggghts", "hertz"): "LIGGGHTS 3.8.0, model hertz",
          ("yade", "mindlin"): "YADE 2023.02a, Hertz-Mindlin en (Thornton's fit, clamped)"}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--data", default="reference_data/dem")
    p.add_argument("--out", default="docs/figures")
    a = p.parse_args()
    with open(os.path.join(a.data, "builtin_conversion_error.csv")) as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(len(TITLES), 2, figsize=(11, 4 * len(TITLES)), sharex=True)
    for i, key in enumerate(TITLES):
        sel = [r for r in rows if (r["code"], r["damping"]) == key and r["outcome"] == "rebound"]
        for j, column in enumerate(["error", "error_percent_of_one_minus_e"]):
            ax = axes[i][j]
            for mat in COLORS:
                nl = [r for r in sel if r["material"] == mat and r["gravity"] == "0" and r["v0"] == "1"]
                if mat == "steel":
                    ax.plot([float(r["target_e"]) for r in nl], [float(r[column]) for r in nl], color="0.5", lw=3,
                            alpha=0.5, label="no load (any v0, any material)")
                for v0, style in STYLES.items():
                    pts = [r for r in sel if r["material"] == mat and r["gravity"] != "0" and r["v0"] == v0]
                    ax.plot([float(r["target_e"]) for r in pts], [float(r[column]) for r in pts], style,
                            color=COLORS[mat], label="%s, v0 = %s m/s" % (mat, v0))
            ax.axhline(0, color="k", lw=0.5)
            ax.set_title(TITLES[key], fontsize=10)
            ax.set_ylabel("e_code - e_target" if j == 0 else "(e_code - e_target) / (1 - e_target)  [%]")
            if i == len(TITLES) - 1:
                ax.set_xlabel("target e (written into the deck)")
    axes[0][0].legend(fontsize=7, ncol=2)
    fig.suptitle("Built-in e -> damping conversions: bead R = 1 mm on a rigid wall, gravity 9.81 m/s^2", fontsize=11)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "dem_builtin_conversion_error.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()

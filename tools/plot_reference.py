#!/usr/bin/python3
"""Figures in the style of the report's Figs. 12-23 and 8-11, from the committed tables.

  e versus gamma at fixed g (certified reference and Prop. 2's approximation (36) with
  exact / numeric / Chebyshev-Beta coefficients), and their absolute errors on log axes;
  g_c(gamma): certified thresholds (sticking_hertz.csv) against eq. (24).

The approximation values come from `viscor report --values FILE` (double precision);
this script only reads CSV files and draws. Needs Debian's python3-matplotlib.

  tools/plot_reference.py --viscor build/viscor [--data reference_data] [--out docs/figures]
  tools/plot_reference.py --values values.csv ...      (reuse a values file)
"""
import argparse
import csv
import math
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LAWS = {"hertz_linear_damping": ("Hertz + linear damping", "3/2", "1"),
        "tsuji": ("Tsuji", "3/2", "5/4"),
        "kuwabara_kono": ("Kuwabara-Kono", "3/2", "3/2"),
        "hunt_crossley": ("Hunt-Crossley", "3/2", "5/2")}
SERIES = [("prop2_exact_at_zero", "Exact coeffs. (39),(40)", "C2", "-"),
          ("prop2_numeric", "Num. coeffs. (41),(42)", "C1", "--"),
          ("prop2_chebyshev_beta", "Approx. coeffs. (48),(49)", "C3", ":"),
          ("schwager_poschel", "Schwager-Poschel (25),(30)", "C4", "-.")]


def read_values(path):
    rows = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if not r["table"].startswith("cor_report_"):
                continue
            rows.setdefault((r["law"], r["g"]), []).append(r)
    for v in rows.values():
        v.sort(key=lambda r: float(r["gamma"]))
    return rows


def fnum(s):
    return float(s) if s != "" else math.nan


def plot_law(law, rows, out_dir):
    title, alpha, beta = LAWS[law]
    gs = [g for g in ("0", "0.05", "1", "10") if (law, g) in rows]
    fig, axes = plt.subplots(2, len(gs), figsize=(3.2 * len(gs), 5.6), squeeze=False)
    for j, g in enumerate(gs):
        data = rows[(law, g)]
        gamma = [float(r["gamma"]) for r in data]
        ref = [float(r["e_ref"]) for r in data]
        top, bottom = axes[0][j], axes[1][j]
        top.plot(gamma, ref, "k-", lw=2.2, label="certified reference")
        for key, label, color, style in SERIES:
            vals = [fnum(r[key]) for r in data]
            if all(math.isnan(v) for v in vals):
                continue
            if key == "prop2_numeric" and g == "0":
                continue  # identical to the exact coefficients at g = 0
            top.plot(gamma, vals, color=color, ls=style, lw=1.3, label=label)
            err = [abs(v - e) for v, e in zip(vals, ref)]
            pts = [(x, y) for x, y in zip(gamma, err) if y > 0 and x > 0]
            if pts:
                bottom.loglog(*zip(*pts), color=color, ls=style, lw=1.3, label=label)
        top.set_title(f"g = {g}", fontsize=10)
        top.set_xlabel("γ")
        bottom.set_xlabel("γ")
        if j == 0:
            top.set_ylabel("e")
            bottom.set_ylabel("|e_approx − e_ref|")
        bottom.grid(True, which="major", alpha=0.3)
        top.grid(True, alpha=0.3)
    handles = {}
    for ax in axes[0]:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(lab, h)
    axes[0][0].legend(handles.values(), handles.keys(), fontsize=7, loc="lower left")
    fig.suptitle(f"{title} (α = {alpha}, β = {beta}): Prop. 2 O(γ²) approximation vs certified CoR", fontsize=11)
    fig.tight_layout()
    path = os.path.join(out_dir, f"cor_{law}.png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def plot_gc(data_dir, out_dir, viscor):
    path = os.path.join(data_dir, "sticking_hertz.csv")
    if not os.path.exists(path):
        print("plot_reference: no sticking_hertz.csv yet, g_c figure skipped")
        return None
    by_law = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r["solve_for"] == "g":
                by_law.setdefault(r["law"], []).append((float(r["gamma"]), float(r["g"])))
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for i, (law, pts) in enumerate(sorted(by_law.items())):
        pts.sort()
        gamma = [p[0] for p in pts]
        gc = [p[1] for p in pts]
        eq24 = [critical_g(viscor, law, x) for x in gamma]
        color = f"C{i}"
        a.loglog(gamma, gc, "o", color=color, ms=4, label=f"{LAWS[law][0]} certified")
        a.loglog(gamma, eq24, "-", color=color, lw=1, label=f"{LAWS[law][0]} eq. (24)")
        b.loglog(gamma, [abs(x - y) / y for x, y in zip(eq24, gc)], "o-", color=color, ms=3, label=LAWS[law][0])
    a.set_xlabel("γ"), a.set_ylabel("g_c"), a.legend(fontsize=7), a.grid(True, alpha=0.3)
    b.set_xlabel("γ"), b.set_ylabel("|g_c(24) − g_c| / g_c"), b.legend(fontsize=7), b.grid(True, alpha=0.3)
    fig.suptitle("Sticking threshold g_c(γ): certified vs eq. (24) (report Figs. 8-11)", fontsize=11)
    fig.tight_layout()
    out = os.path.join(out_dir, "sticking_gc.png")
    fig.savefig(out, dpi=90)
    plt.close(fig)
    return out


_C_CACHE = {}


def critical_g(viscor, law, gamma):
    """g_c of eq. (24) = (2 gamma C)^(-1/p), C and p from `viscor approx --json`."""
    if law not in _C_CACHE:
        import json
        out = subprocess.run([viscor, "approx", "--model", law, "--gamma", "0.01", "--formula", "small_g", "--json"],
                             check=True, capture_output=True, text=True).stdout
        c = json.loads(out)["closed_forms"]
        _C_CACHE[law] = (float(c["C"]), float(c["p"]))
    C, p = _C_CACHE[law]
    return (2 * gamma * C) ** (-1 / p)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--viscor", default="build/viscor", help="the viscor executable")
    ap.add_argument("--data", default="reference_data", help="directory of the committed tables")
    ap.add_argument("--values", help="a `viscor report --values` CSV (default: run viscor to make one)")
    ap.add_argument("--out", default="docs/figures", help="output directory for the PNGs")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    values = args.values
    if values is None:
        tmp = tempfile.NamedTemporaryFile(suffix=".csv", delete=False)
        tmp.close()
        values = tmp.name
        subprocess.run([args.viscor, "report", "--data", args.data, "--values", values, "-o", os.devnull], check=True)
    rows = read_values(values)
    written = [plot_law(law, rows, args.out) for law in LAWS if any(k[0] == law for k in rows)]
    written.append(plot_gc(args.data, args.out, args.viscor))
    for w in written:
        if w:
            print(f"plot_reference: wrote {w} ({os.path.getsize(w) // 1024} KB)")


if __name__ == "__main__":
    main()

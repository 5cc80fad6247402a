#!/usr/bin/env python3
"""Measure the overdamped extremes (docs/performance.md, "Overdamped extremes").

Runs `viscor cor` once per point of a log grid of gamma in [2, 1e10] and g in
[-1e6, 1e12], for every named law, both methods and the chosen precisions, each
in its own process under a wall-clock timeout, and records what happened:
a value (rebound), a stick, an undecided outcome, a refusal (exit code and the
first line of the message) or a timeout. Writes one CSV row per run and prints
a summary table (counts per law, method and digits; the slowest runs).

Usage:
  tools/overdamped_sweep.py VISCOR [--grid full|reduced] [--digits 15,50]
                            [--methods taylor,adaptive] [--laws ...]
                            [--timeout 1:3,50:10] [--certify] -o sweep.csv

Run it with one thread at low priority (nice -n 10); the full grid takes tens
of minutes when many points time out.
"""
import argparse
import csv
import json
import subprocess
import sys
import time

LAWS = ["linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"]
GRIDS = {
    # gamma from 2 to 1e10, g from -1e6 to 1e12: the box the solvers must decide
    "full": (["2", "10", "1e2", "1e3", "1e4", "1e6", "1e8", "1e10"],
             ["-1e6", "-1e3", "-1", "-1e-3", "0", "1e-3", "1", "1e3", "1e6", "1e9", "1e12"]),
    "reduced": (["2", "1e2", "1e4", "1e10"], ["-1e6", "-1", "0", "1", "1e6", "1e12"]),
}


def run_point(viscor, law, method, digits, gamma, g, timeout, certify):
    cmd = [viscor, "cor", "--model", law, "--gamma", gamma, "--g", g, "--digits", str(digits), "--method", method,
           "--json"]
    if certify:
        cmd.append("--certify")
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "wall": time.monotonic() - start}
    wall = time.monotonic() - start
    if p.returncode != 0:
        msg = (p.stderr.strip().splitlines() or [""])[0]
        kind = "refused"
        if "step budget" in msg:
            kind = "budget"
        return {"status": kind, "wall": wall, "message": msg[:160], "rc": p.returncode}
    j = json.loads(p.stdout)
    out = {"status": j["outcome"], "wall": wall, "seconds": j.get("seconds"), "e": j.get("e"),
           "error_estimate": j.get("error_estimate"), "steps": j.get("steps"), "contact_time": j.get("contact_time")}
    if certify and "certified" in j:
        c = j["certified"]
        out["certified_outcome"] = c.get("outcome_certified")
        out["certified_digits"] = c.get("digits")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("viscor")
    ap.add_argument("--grid", default="full", choices=GRIDS)
    ap.add_argument("--digits", default="15,50")
    ap.add_argument("--methods", default="taylor,adaptive")
    ap.add_argument("--laws", default=",".join(LAWS))
    ap.add_argument("--timeout", default="15:3,50:10", help="digits:seconds per precision")
    ap.add_argument("--certify", action="store_true")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    gammas, gs = GRIDS[a.grid]
    timeouts = {int(k): float(v) for k, v in (x.split(":") for x in a.timeout.split(","))}
    fields = ["law", "method", "digits", "gamma", "g", "status", "wall", "seconds", "steps", "e", "error_estimate",
              "contact_time", "certified_outcome", "certified_digits", "rc", "message"]
    rows = []
    with open(a.output, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for digits in (int(d) for d in a.digits.split(",")):
            for method in a.methods.split(","):
                for law in a.laws.split(","):
                    for gamma in gammas:
                        for g in gs:
                            r = run_point(a.viscor, law, method, digits, gamma, g, timeouts.get(digits, 10),
                                          a.certify)
                            r.update(law=law, method=method, digits=digits, gamma=gamma, g=g)
                            r["wall"] = round(r["wall"], 3)
                            w.writerow(r)
                            f.flush()
                            rows.append(r)
    # Summary: per (digits, method, law) the counts of each status and the slowest wall time.
    print("digits method   law                   rebound stick undecided budget refused timeout  max_wall_s")
    keys = sorted({(r["digits"], r["method"], r["law"]) for r in rows})
    for k in keys:
        sel = [r for r in rows if (r["digits"], r["method"], r["law"]) == k]
        c = {s: sum(1 for r in sel if r["status"] == s)
             for s in ["rebound", "stick", "undecided", "budget", "refused", "timeout"]}
        print(f"{k[0]:>6} {k[1]:<8} {k[2]:<21} {c['rebound']:>7} {c['stick']:>5} {c['undecided']:>9} "
              f"{c['budget']:>6} {c['refused']:>7} {c['timeout']:>7}  {max(r['wall'] for r in sel):>9.2f}")
    bad = [r for r in rows if r["status"] in ("budget", "refused", "timeout")]
    print(f"{len(bad)} of {len(rows)} runs refused or timed out")
    return 0


if __name__ == "__main__":
    sys.exit(main())

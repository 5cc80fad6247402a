#!/usr/bin/python3
"""How far off the DEM codes' own e -> damping conversions are under gravity.

For each code conversion (LAMMPS damping tsuji, LIGGGHTS model hertz with
coefficientRestitution, YADE Hertz-Mindlin with `en`: betan by Thornton's fit,
force clamped at 0), bead material (steel, glass, polymer; R = 1 mm, on a
rigid wall, gravity 0 and 9.81 m/s^2) and target e, writes the target e itself into the
deck (for YADE as `en`: `--deck-en E`) and asks `viscor dem ... --deck-damping E
--speeds ...` for the e the code
then produces (viscor's exact solve of the code's force law, which the drop
tests check against the real programs). One row per (code, material, e, v0).

  tools/dem_builtin_error_table.py --viscor build/viscor [--out reference_data/dem]

Writes builtin_conversion_error.csv and its sidecar builtin_conversion_error.csv.json.
"""
import argparse
import csv
import datetime
import json
import os
import platform
import subprocess
import sys
import time

MATERIALS = [  # name, E (Pa), nu, radius (m), density (kg/m^3)
    ("steel", "2e11", "0.3", "1e-3", "7800"),
    ("glass", "7e10", "0.22", "1e-3", "2500"),
    ("polymer", "3e9", "0.35", "1e-3", "1200"),
]
CONVERSIONS = [("lammps", "tsuji"), ("liggghts", "hertz"), ("yade", "mindlin")]
DECK_OPTION = {"yade": "--deck-en"}  # YADE's betan is a coefficient; its own conversion is the input `en`
TARGETS = ["0.05", "0.1", "0.15", "0.2", "0.25", "0.3", "0.35", "0.4", "0.45", "0.5", "0.55", "0.6", "0.65",
           "0.7", "0.75", "0.8", "0.85", "0.9", "0.95", "0.97", "0.99"]
SPEEDS = "0.001,0.003,0.01,0.03,0.1,0.3,1,3"
GRAVITY = "9.81"
COLUMNS = ["code", "damping", "material", "youngs_modulus", "poisson_ratio", "radius", "density", "gravity", "v0",
           "target_e", "builtin_e", "error", "error_percent_of_one_minus_e", "outcome"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--viscor", required=True)
    parser.add_argument("--out", default="reference_data/dem")
    args = parser.parse_args()
    start = time.time()
    rows = []
    for code, damping in CONVERSIONS:
        for name, E, nu, R, rho in MATERIALS:
            for target in TARGETS:
                command = [args.viscor, "dem", code, "--damping", damping, "--youngs-modulus", E, "--poisson-ratio", nu,
                           "--radius", R, "--density", rho, "--gravity", GRAVITY, DECK_OPTION.get(code, "--deck-damping"), target,
                           "--speeds", SPEEDS, "--json"]
                out = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
                for row in out["table"]:  # each speed without load (gravity 0) and under gravity
                    e = float(row["e"])
                    t = float(target)
                    rows.append([code, damping, name, E, nu, R, rho, row["gravity"], row["v0"], target, row["e"],
                                 "%.6e" % (e - t), "%.6e" % (100 * (e - t) / (1 - t)), row["outcome"]])
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "builtin_conversion_error.csv")
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerows(rows)
    os.replace(path + ".tmp", path)
    commit = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True).stdout.strip()
    version = subprocess.run([args.viscor, "--version"], capture_output=True, text=True).stdout.strip()
    sidecar = {
        "table": "builtin_conversion_error.csv",
        "what": "e produced by the DEM codes' own e -> damping conversions when the target e is written into the deck: "
                "bead on a rigid wall without load (gravity 0) and under gravity, exact solve of each code's force law (include/viscor/dem)",
        "columns": ",".join(COLUMNS),
        "conversions": {c + " " + d: v for (c, d), v in zip(CONVERSIONS, [
            "LAMMPS 29 Sep 2021 update 2, fix wall/gran granular hertz/material ... damping tsuji",
            "LIGGGHTS-PUBLIC 3.8.0, model hertz with coefficientRestitution",
            "YADE 2023.02a, Ip2_FrictMat_FrictMat_MindlinPhys(en=target): betan by Thornton et al.'s fit, "
            "Law2_ScGeom_MindlinPhys_Mindlin (total normal force clamped at 0)"])},
        "materials": [dict(zip(["name", "youngs_modulus", "poisson_ratio", "radius", "density"], m)) for m in MATERIALS],
        "targets": TARGETS,
        "speeds": SPEEDS.split(","),
        "gravity": ["0", GRAVITY],
        "rows": len(rows),
        "viscor": version,
        "git_commit": commit,
        "command_line": " ".join([os.path.relpath(sys.argv[0])] + sys.argv[1:]),
        "host": platform.node(),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "wall_time_seconds": round(time.time() - start, 1),
    }
    with open(path + ".json", "w") as f:
        json.dump(sidecar, f, indent=2)
        f.write("\n")
    print("wrote %s (%d rows) in %.1f s" % (path, len(rows), time.time() - start))


if __name__ == "__main__":
    main()

#!/usr/bin/env bash
# Batch mode against in-process solves: 200 points (5 named laws x 4 gamma x 10 g)
# at DIGITS digits (default 50) through one `viscor cor --points` process; prints
# the process's wall time, the sum of the solve times it reports per point (the
# in-process cost), their ratio, and the first solve against the median one.
# Usage: tools/bench_points.sh [VISCOR] [DIGITS] [THREADS]
set -euo pipefail
viscor=${1:-viscor}
digits=${2:-50}
threads=${3:-1}
points=$(mktemp)
out=$(mktemp)
trap 'rm -f "$points" "$out"' EXIT
echo "law,gamma,g,digits" > "$points"
for law in linear hertz_linear_damping tsuji kuwabara_kono hunt_crossley; do
  for gamma in 0.001 0.01 0.05 0.1; do
    for g in 0 0.01 0.02 0.05 0.1 0.2 0.3 0.5 0.7 1; do echo "$law,$gamma,$g,$digits" >> "$points"; done
  done
done
start=$(date +%s.%N)
"$viscor" cor --points "$points" --threads "$threads" > "$out"
end=$(date +%s.%N)
python3 - "$out" "$start" "$end" "$threads" <<'PY'
import json, statistics, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
wall = float(sys.argv[3]) - float(sys.argv[2])
solves = [r["seconds"] for r in rows]
total = sum(solves)
print(json.dumps({"points": len(rows), "digits": rows[0]["precision"]["digits"], "threads": int(sys.argv[4]),
                  "wall_s": round(wall, 4), "sum_of_solves_s": round(total, 4),
                  "wall_over_solves": round(wall / total * int(sys.argv[4]), 3),
                  "first_solve_s": round(solves[0], 5), "median_solve_s": round(statistics.median(solves), 5)}))
PY

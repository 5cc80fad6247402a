#!/usr/bin/env bash
# Regenerates every committed table in reference_data/ from the spec beside it.
# Usage: tools/generate_reference_data.sh [path/to/viscor] [threads]
# Interrupted runs resume where they stopped (viscor table --resume); a finished
# table is left as it is, so delete a CSV to regenerate it.
set -euo pipefail
viscor=${1:-build/viscor}
threads=${2:-$(nproc)}
cd "$(dirname "$0")/.."
for spec in reference_data/cor_report_grid.json reference_data/cor_report_g10_*.json \
            reference_data/cor_gamma_sweep.json reference_data/cor_g_sweep.json \
            reference_data/cor_error_map_grid.json; do
  echo "== $spec"
  "$viscor" --update-committed table "$spec" -o "${spec%.json}.csv" --threads "$threads" --resume
done
echo "== reference_data/sticking_hertz.json"
"$viscor" --update-committed table sticking reference_data/sticking_hertz.json -o reference_data/sticking_hertz.csv \
  --threads "$threads" --resume

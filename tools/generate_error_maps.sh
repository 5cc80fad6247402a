#!/usr/bin/env bash
# Rebuilds the error maps reference_data/error_maps/<law>.csv (docs/scenes.md) from the
# committed certified tables: cor_error_map_grid.csv (a tensor grid, 1-2-5 steps)
# supplies the cell corners, the other CoR tables add samples inside the cells.
# Usage: tools/generate_error_maps.sh [path/to/viscor]
# Cells: gamma in 1-2-5 steps from 1e-6 to 1, g = 0, then decades 1e-4..10.
# Safety factor 4 and floor 1e-14: see include/viscor/scenes/error_map_builder.hpp.
set -euo pipefail
viscor=${1:-build/viscor}
cd "$(dirname "$0")/.."
mkdir -p reference_data/error_maps
gamma_edges=1e-6,2e-6,5e-6,1e-5,2e-5,5e-5,1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,0.01,0.02,0.05,0.1,0.2,0.5,1
g_edges=0,1e-4,1e-3,0.01,0.1,1,10
tables=()
for t in reference_data/cor_error_map_grid.csv reference_data/cor_report_grid.csv \
         reference_data/cor_report_g10_*.csv reference_data/cor_gamma_sweep.csv reference_data/cor_g_sweep.csv; do
  tables+=(--table "$t")
done
for law in linear hertz_linear_damping tsuji kuwabara_kono hunt_crossley; do
  "$viscor" --update-committed errormap --model "$law" "${tables[@]}" --gamma-edges "$gamma_edges" --g-edges "$g_edges" \
    --safety-factor 4 --floor 1e-14 -o "reference_data/error_maps/$law.csv"
done

#!/usr/bin/env bash
# A corpus of what the command line prints, for refactorings that must not change it
# (the typed jobs: jobs that return types, front ends that render them): every subcommand,
# its readable text and its JSON, sticks and undecided outcomes, physical inputs, the
# DEM entries of each code, files a command writes, and refusals with their exit code.
# tools/solver_corpus.sh covers the solvers' numbers in depth; this covers the forms.
# Fields that measure time are removed, and the executable, the scratch and source
# directories and the commit are named neutrally (<viscor>, ...), so that two builds compare by
#   tools/cli_corpus.sh build-a/viscor > a.txt; tools/cli_corpus.sh build-b/viscor > b.txt; diff a.txt b.txt
# or against a recorded corpus (tests/data/cli_corpus/corpus.txt, whose README says when it was
# recorded) with --check FILE, which prints the first differences and fails on any.
# Usage: tools/cli_corpus.sh [path to the viscor executable] [--check FILE]
set -u
if [ "${2:-}" = "--check" ]; then
  [ -r "${3:-}" ] || { echo "cli_corpus.sh: --check needs a readable corpus file, got '${3:-}'" >&2; exit 2; }
  now=$(mktemp)
  trap 'rm -f "$now"' EXIT
  "$0" "$1" > "$now" || exit 2
  if ! diff -u "$3" "$now" > "$now.diff"; then
    head -n 60 "$now.diff"
    echo "cli_corpus.sh: the output differs from $3 ($(grep -c '^[-+][^-+]' "$now.diff") lines)" >&2
    rm -f "$now.diff"
    exit 1
  fi
  rm -f "$now.diff"
  echo "cli_corpus.sh: $(grep -c '^== ' "$now") commands print what $3 recorded"
  exit 0
fi
viscor=$(realpath "${1:-build/viscor}")
source_dir=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch" || exit 2
export VISCOR_DATA="$source_dir/reference_data"

# Drops what measures time rather than computes, and names the directories neutrally.
strip_json() {
  python3 -c '
import json, re, sys
timing = re.compile(r"seconds|elapsed|wall|timing|_ms$|_us$|^built$|^created$|^date$|^git_commit$")
def keep(x):
    if isinstance(x, dict):
        return {k: keep(v) for k, v in x.items() if not timing.search(k)}
    return [keep(v) for v in x] if isinstance(x, list) else x
print(json.dumps(keep(json.load(sys.stdin)), indent=2, sort_keys=True))' 2> /dev/null && return 0
  return 1
}
# Names the executable, the scratch and the source directories and the commit neutrally.
neutral_names() {
  sed -E -e "s#$viscor#<viscor>#g" -e "s#$scratch#<scratch>#g" -e "s#$source_dir#<source>#g" \
    -e 's/commit [0-9a-f]{12}(-dirty)?/commit <commit>/g'
}
strip_text() {
  sed -E -e '/seconds|elapsed| wall/d' -e 's/(steps, )[0-9.e+-]+ s$/\1T s/' -e "${extra_text_filter:-}" | neutral_names
}

# The command's standard output and error, then its exit status.
run() {
  echo "== $*"
  "$viscor" "$@" > out.txt 2> err.txt
  local status=$?
  strip_text < out.txt
  [ -s err.txt ] && { echo "-- stderr"; strip_text < err.txt; }
  echo "-- exit $status"
}
# The same command's JSON (the text form first, with run).
run_json() {
  run "$@"
  echo "== $* --json"
  "$viscor" "$@" --json > out.json 2> err.txt
  local status=$?
  if strip_json < out.json > out.stripped; then neutral_names < out.stripped; else strip_text < out.json; fi
  [ -s err.txt ] && { echo "-- stderr"; strip_text < err.txt; }
  echo "-- exit $status"
}
# A file a command wrote, timing fields removed where it is JSON.
show() {
  echo "-- file $1"
  case "$1" in
    *.json) if strip_json < "$1" > out.stripped; then neutral_names < out.stripped; else strip_text < "$1"; fi ;;
    *) strip_text < "$1" ;;
  esac
}

laws="linear hertz_linear_damping tsuji kuwabara_kono hunt_crossley"
for law in $laws; do
  run_json cor --model "$law" --gamma 0.1 --g 1
  run_json exact --model "$law" --gamma 0.1 --g 0
  run_json approx --model "$law" --gamma 0.05 --g 0.5
done
# Precisions, a stick, an undecided creep, the adaptive method, certify and prove.
for digits in 15 18 25 33 50; do run_json cor --model tsuji --gamma 0.2 --g 1 --digits "$digits"; done
run_json cor --model kuwabara_kono --gamma 5 --g 10
run_json cor --model linear --gamma 1.9999 --g 0 --method adaptive
run_json cor --model hunt_crossley --gamma 0.3 --g 2 --certify
run_json cor --model tsuji --gamma 0.2 --g 1 --digits 25 --certify
run_json cor --model kuwabara_kono --gamma 0.2 --g 1 --digits 30 --prove
run_json prove --model linear --gamma 3 --g 0 --digits 20
run_json cor --alpha 2 --beta 3/2 --gamma 0.1 --g 0.5
# Physical inputs: a bead by m and k, by its material, on a wall of its own, a pair.
run_json cor --model kuwabara_kono --m 2.05e-3 --k 6.97e9 --gamma0 1e4 --v0 0.246 --gravity 9.8
run_json cor --model hunt_crossley --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 4e-3 --density 7800 \
  --gamma0 0.3 --v0 0.5 --gravity 9.81 --wall-youngs-modulus 7e10 --wall-poisson-ratio 0.33
run_json scale --model tsuji --m 2.05e-3 --k 6.97e9 --gamma0 1e4 --v0 0.246 --gravity 9.8
run_json scale --model tsuji --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 4e-3 --density 7800 --v0 1 \
  --gravity 0 --contact pair
run_json calibrate --model tsuji --target-e 0.8 --g 0.5
run_json calibrate --model hertz_linear_damping --target-e 0.9 --m 2.05e-3 --k 6.97e9 --v0 0.246 --gravity 9.8
# DEM: each code's entries, the reverse direction, and the files it writes.
for damping in "lammps velocity" "lammps mass_velocity" "lammps viscoelastic" "lammps tsuji" "liggghts hertz" \
  "yade mindlin" "yade viscoelastic"; do
  bead=(--youngs-modulus 2e11 --poisson-ratio 0.3)
  [ "$damping" = "yade viscoelastic" ] && bead=(--k 1e6)  # a linear spring, not a Hertz material
  run_json dem "${damping%% *}" --damping "${damping#* }" "${bead[@]}" --radius 4e-3 --density 7800 \
    --target-e 0.8 --v0 0.5 --gravity 9.81
done
run_json dem lammps --damping tsuji --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 4e-3 --density 7800 \
  --deck-damping 0.5 --v0 0.5 --gravity 9.81
run dem lammps --damping tsuji --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 4e-3 --density 7800 \
  --target-e 0.8 --v0 0.5 --gravity 9.81 --drop-deck drop.lmp --variables vars.lmp
show drop.lmp
show vars.lmp
# Files: a table and its sidecar, a scene, a formula check, the report, a surrogate export.
cat > spec.json << 'EOF'
{"laws": ["tsuji", "linear"], "gamma": [0, 0.05, 2.5], "g": [0, 1], "digits": 20, "method": "auto"}
EOF
run table spec.json -o table.csv --threads 1 --quiet
show table.csv
show table.csv.json
cat > sticking.json << 'EOF'
{"laws": ["tsuji"], "gamma": [0.01, 0.1, 1], "solve_for": "g", "threshold_digits": 12, "digits": 20}
EOF
run table sticking sticking.json -o sticking.csv --threads 1 --quiet
show sticking.csv
cat > scene.json << 'EOF'
{"law": "kuwabara_kono", "bead": {"m": 2.05e-3, "k": 6.9716e9}, "damping": {"measured_e": 0.893, "v0": 0.246, "gravity": 9.8},
 "gravity": 9.8, "velocities": {"from": 0.01, "to": 1, "count": 12, "spacing": "log"}, "tolerance": 1e-4}
EOF
extra_text_filter='s/^([0-9]+,.*,)[0-9.e+-]+$/\1T/' run_json scene scene.json  # the last column: seconds
"$viscor" formula points --model kuwabara_kono > points.csv 2> /dev/null
awk -F, 'NR == 2 { print "gamma,g,e" } NR > 2 { printf "%s,%s,%.17g\n", $1, $2, exp(-1.72 * $1) }' points.csv > mine.csv
run_json formula check --model kuwabara_kono --values mine.csv --tolerance 1e-3 --gamma-max 0.01 --g-max 0.01
run_json formula check --model kuwabara_kono --values mine.csv --tolerance 1e-6
run report
run surrogate export --language c -o export --law tsuji
show export/viscor_surrogate_tsuji.h
# Refusals: the message and the exit code.
run cor --model linear --gamma -1
run cor --model tsuji --gamma 0.1 --g nonsense
run cor --alpha 0.5 --beta 1 --gamma 0.1
run prove --alpha 1000000001/1000000000 --beta 1 --gamma 0.1 --g 0
run dem lammps --damping tsuji --youngs-modulus -1 --poisson-ratio 0.3 --radius 4e-3 --density 7800 \
  --target-e 0.8 --v0 0.5 --gravity 9.81
run formula check --model kuwabara_kono --values mine.csv --tolerance 2
run table missing.json -o x.csv
exit 0

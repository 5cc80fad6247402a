#!/usr/bin/env bash
# A corpus of solver outputs for refactorings that must not change a number: the five
# named laws at double, float128 and 50 digits, both methods, free and loaded impacts,
# sticking, strongly damped creeps (the stiff integrators), certification and proofs.
# Prints every output to stdout with timing fields removed, so two builds compare by
#   tools/solver_corpus.sh build-a/viscor > a.txt; tools/solver_corpus.sh build-b/viscor > b.txt; diff a.txt b.txt
# Usage: tools/solver_corpus.sh [path to the viscor executable] (default build/viscor)
set -u
viscor=${1:-build/viscor}
command -v jq > /dev/null || { echo "solver_corpus.sh needs jq" >&2; exit 2; }

# Drops the fields that measure time rather than compute numbers.
strip_timing() { jq -S -c 'walk(if type == "object" then with_entries(select(.key | test("seconds|elapsed|wall|timing|_ms$|_us$") | not)) else . end)'; }

run() {
  echo "== $*"
  "$viscor" "$@" --json 2>&1 | { strip_timing 2> /dev/null || true; }
}

laws="linear hertz_linear_damping tsuji kuwabara_kono hunt_crossley"
# gamma g: free, loaded, sticking (large gamma and g), strongly damped creeps out (g <= 0).
cases="0.1:0 0.3:2 5:10 1000:0 1e6:-1e-3"
for law in $laws; do
  for digits in 15 30 50; do
    for method in taylor adaptive; do
      for c in $cases; do
        run cor --model "$law" --gamma "${c%%:*}" --g "${c##*:}" --digits "$digits" --method "$method"
      done
    done
  done
done
# Near-critical turns at rest (contact time NaN), spirals, a late turn back, creeps
# that leave with a tiny e, and a creep the GBS solver leaves undecided.
extra="linear:1.9999:0.5 hunt_crossley:0.0063:426 linear:1.99:0 tsuji:1.7:0 linear:1.93:87
kuwabara_kono:1e6:-1e-3 hunt_crossley:1e4:1e-3 tsuji:1e5:1e-9 kuwabara_kono:1e10:0"
for c in $extra; do
  IFS=: read -r law gamma g <<< "$c"
  for digits in 15 50; do
    for method in taylor adaptive; do
      run cor --model "$law" --gamma "$gamma" --g "$g" --digits "$digits" --method "$method"
    done
  done
done
for law in $laws; do
  run cor --model "$law" --gamma 0.2 --g 1 --digits 15 --certify
  run cor --model "$law" --gamma 0.2 --g 0 --digits 30 --certify
done
run cor --model hunt_crossley --gamma 1e4 --g 1e-3 --digits 15 --certify
for law in linear hertz_linear_damping tsuji kuwabara_kono hunt_crossley; do
  run prove --model "$law" --gamma 0.2 --g 1 --digits 30
  run prove --model "$law" --gamma 3 --g 0 --digits 20
done
run prove --model kuwabara_kono --gamma 0.05 --g 1 --digits 50

#!/usr/bin/env bash
# Runs every command of the README's ```sh blocks from the build tree, so the README
# cannot drift. `viscor` is the build tree's tool (a PATH entry), and
# `./build/viscor` too; commands run in a scratch directory that sees the repository's
# docs/, tools/ and reference_data/. The two set-up commands are checked, not run
# (they install and build): .ci/run must hold exactly the two, the main-job command
# first and the test command second (CI walks a newcomer's path), the test command
# configures with -DVISCOR_REQUIRE_ALL_DEPS=ON (CI cannot pass by skipping), the main-job command
# must install with --cli and build only viscor_cli, and what it runs after the build
# is run.
# The README's ```cpp block must be examples/certified_cor.cpp verbatim.
# Usage: readme_test.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
src=$1
build=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/bin"
ln -s "$build/viscor" "$scratch/bin/viscor"
for d in docs tools reference_data examples; do ln -s "$src/$d" "$scratch/$d"; done
ln -s "$build" "$scratch/build"
export PATH="$scratch/bin:$PATH"
unset VISCOR_DATA VISCOR_ERROR_MAPS
cd "$scratch"

failures=0
fail() { echo "README: $*" >&2; failures=$((failures + 1)); }

# What the main jobs must print (extended regular expressions on stdout), from
# independent sources: e from the committed certified tables
# (reference_data/cor_report_grid.csv), the scaled gamma and g from
# tests/data/scaling_reference.csv (tools/scaling_reference.py). A command listed
# here that the README no longer has is reported too.
declare -A expected=(
  ["viscor cor --model kuwabara_kono --gamma 0.05 --g 1 --digits 50 --certify"]='^  e +5\.921461602612392816699384310349'
  ["viscor cor --model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --gamma0 8.49e-7 --v0 0.246 --gravity 9.8"]='^gamma +6\.6027697317069.*|^g +5\.122388420892'
  ["printf 'law,gamma,g,digits\ntsuji,0.1,0.5,50\nhunt_crossley,0.01,1,30\n' | viscor cor --points - --threads 2"]='"e":"8\.503004073684626134172591522430e-01"'
)
# Both alternatives of a pattern with | must match: count the lines that match.
declare -A expected_lines=(
  ["viscor cor --model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --gamma0 8.49e-7 --v0 0.246 --gravity 9.8"]=2
)
declare -A seen=()

setup_prefix='bash tools/install-deps.sh && cmake -S . -B build && cmake --build build -j2'
ci_lines=$(grep -E '^bash tools/install-deps.sh' "$src/.ci/run")
readme_setup=$(grep -E '^bash tools/install-deps.sh' "$src/README.md")
[ "$ci_lines" = "$readme_setup" ] || fail ".ci/run must run the README's two set-up commands, main job first:
  README:
$readme_setup
  .ci/run:
$ci_lines"
ci_line=$(printf '%s\n' "$ci_lines" | tail -n 1)
commands=0
# Every line of every ```sh block, with backslash continuations joined.
while IFS= read -r command; do
  [ -z "$command" ] && continue
  commands=$((commands + 1))
  if [[ $command == "bash tools/install-deps.sh"* ]]; then
    [[ $command == "${setup_prefix/install-deps.sh/install-deps.sh --cli}"* || $command == "$setup_prefix"* ||
       $command == "${setup_prefix/-B build/-B build -DVISCOR_REQUIRE_ALL_DEPS=ON}"* ]] ||
      fail "set-up command not of the form '$setup_prefix ...': $command"
    tail=${command##*&& }
    # The test command runs ctest (then the sanitizer suite, tools/sanitizer_suite.sh).
    test_command=0
    [[ $command == *"&& ctest "* ]] && test_command=1
    if [ "$test_command" = 1 ]; then
      [ "$command" = "$ci_line" ] || fail "the test command differs from .ci/run:
  README: $command
  .ci/run: $ci_line"
      # CI must not pass by skipping: missing dependencies fail (CMakeLists.txt).
      [[ $command == "${setup_prefix/-B build/-B build -DVISCOR_REQUIRE_ALL_DEPS=ON}"* ]] ||
        fail "the test command must configure with -DVISCOR_REQUIRE_ALL_DEPS=ON: $command"
    else
      main_prefix='bash tools/install-deps.sh --cli && cmake -S . -B build && cmake --build build -j2 --target viscor_cli &&'
      [[ $command == "$main_prefix"* ]] || fail "the main-job command must install with --cli and build only viscor_cli: $command"
      command=$tail
    fi
    [ "$test_command" = 1 ] && continue
  fi
  echo "+ $command"
  if ! bash -o pipefail -c "$command" > out.txt 2> err.txt; then
    fail "failed: $command"
    cat err.txt >&2
  elif [ -n "${expected[$command]+set}" ]; then
    seen[$command]=1
    lines=$(grep -cE "${expected[$command]}" out.txt)
    [ "$lines" -ge "${expected_lines[$command]:-1}" ] || {
      fail "wrong output of: $command (expected /${expected[$command]}/)"
      cat out.txt >&2
    }
  fi
done < <(awk '/^```sh$/ {inside = 1; next} /^```/ {inside = 0; next}
              inside { line = $0; sub(/[ \t]+#.*$/, "", line); if (line ~ /^[ \t]*#/ || line ~ /^[ \t]*$/) next;
                       if (line ~ /\\$/) { sub(/\\$/, "", line); pending = pending line; next }
                       print pending line; pending = "" }' "$src/README.md")
[ "$commands" -ge 5 ] || fail "only $commands commands found"
for command in "${!expected[@]}"; do
  [ -n "${seen[$command]+set}" ] || fail "an expected output's command is not in the README (or failed): $command"
done
# The files the scene and report commands write (their contents have their own tests).
[ "$(grep -c . steel.csv 2> /dev/null)" -ge 2 ] || fail "viscor scene wrote no rows to steel.csv"
grep -q "Table 2" report_tables.md 2> /dev/null || fail "viscor report --compare wrote no Table 2 to report_tables.md"

awk '/^```cpp$/ {inside = 1; next} /^```/ {inside = 0} inside' "$src/README.md" > readme_snippet.cpp
diff -u "$src/examples/certified_cor.cpp" readme_snippet.cpp >&2 || fail "the C++ snippet is not examples/certified_cor.cpp"

echo "README: $commands commands, $failures failures"
[ "$failures" -eq 0 ]

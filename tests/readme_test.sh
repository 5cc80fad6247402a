#!/usr/bin/env bash
# Runs every command of the README's ```sh blocks from the build tree, so the README
# cannot drift (issue 13). `viscor` is the build tree's tool (a PATH entry), and
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
    if [[ $tail == ctest* ]]; then
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
    [[ $tail == ctest* ]] && continue
  fi
  echo "+ $command"
  if ! bash -o pipefail -c "$command" > out.txt 2> err.txt; then
    fail "failed: $command"
    cat err.txt >&2
  fi
done < <(awk '/^```sh$/ {inside = 1; next} /^```/ {inside = 0; next}
              inside { line = $0; sub(/[ \t]+#.*$/, "", line); if (line ~ /^[ \t]*#/ || line ~ /^[ \t]*$/) next;
                       if (line ~ /\\$/) { sub(/\\$/, "", line); pending = pending line; next }
                       print pending line; pending = "" }' "$src/README.md")
[ "$commands" -ge 5 ] || fail "only $commands commands found"

awk '/^```cpp$/ {inside = 1; next} /^```/ {inside = 0} inside' "$src/README.md" > readme_snippet.cpp
diff -u "$src/examples/certified_cor.cpp" readme_snippet.cpp >&2 || fail "the C++ snippet is not examples/certified_cor.cpp"

echo "README: $commands commands, $failures failures"
[ "$failures" -eq 0 ]

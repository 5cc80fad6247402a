#!/usr/bin/env bash
# The sanitizer suite (docs/robustness.md), run by the README's test command after
# the normal build and tests:
#   1. build-sanitize: GCC with AddressSanitizer and UndefinedBehaviorSanitizer
#      (-DVISCOR_SANITIZE=ON, halt on the first report); a subset of the test
#      programs covering every folder of the library, the CLI (the tests below run
#      the sanitized viscor), the proofs (Arb), and two fixtures showing that the
#      build stops a heap overflow and a signed overflow. Any sanitizer report,
#      also from a CLI process a test started, fails the suite (log folder below).
#   2. build-fuzz: clang with libFuzzer (-DVISCOR_BUILD_FUZZERS=ON); each fuzz
#      target runs for a fixed time over its committed corpus (tests/fuzz/run_fuzzers.sh).
# Usage: bash tools/sanitizer_suite.sh [--sanitize-only | --fuzz-only] [FUZZ_SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."

mode=all
case "${1:-}" in
  --sanitize-only) mode=sanitize; shift ;;
  --fuzz-only) mode=fuzz; shift ;;
esac
fuzz_seconds=${1:-15}

# One test program per library folder (and the CLI and the proofs), chosen for a
# short build: instrumented, a program costs about 4 times its normal compile time
# (docs/robustness.md, which lists what each covers).
sanitized_tests=(
  exponent_validation_test scaling_test                      # core
  exact_solutions_test                                       # exact
  taylor_series_test                                         # ode
  solve_impact_test                                          # impact
  certification_test                                         # certify
  enclose_test enclose_cli_test enclose_proof_mutation_test  # enclose (Arb), viscor prove
  integrals_test                                             # approx
  surrogate_test corrupt_files_test                          # surrogate; surrogate and table files (tables)
  scene_test                                                 # scenes
  dem_conventions_test                                       # dem
  cli_input_checks_test cli_points_test                      # CLI: options, -o, overflow values, --points
  sanitizer_fixture_heap_overflow sanitizer_fixture_signed_overflow
)
# Tests of the build tree that are not programs of the list (packaging, docs,
# README commands, the examples, which the subset does not build; the CLI corpus, pinned
# to the normal build's optimised code; the calculator page, WebAssembly in a browser):
# they run in the normal build.
not_sanitized='_NOT_BUILT$|^(example_.*|cmake_consumer|check_layers.*|api_docs_.*|installed_cli|readme_commands|doc_examples.*|cli_corpus.*|web_calculator)$'

start=$(date +%s)
seconds() { echo $(($(date +%s) - start)); }

if [ "$mode" != fuzz ]; then
  logs=$PWD/build-sanitize/sanitizer-logs
  cmake -S . -B build-sanitize -DVISCOR_SANITIZE=ON -DVISCOR_BUILD_PYTHON=OFF -DVISCOR_REQUIRE_ALL_DEPS=OFF
  rm -rf "$logs" && mkdir -p "$logs"
  # Every report goes to a file too: a CLI process's stderr is often read by the test that ran it.
  export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:log_path=$logs/asan"
  export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:log_path=$logs/ubsan"
  cmake --build build-sanitize -j2 --target "${sanitized_tests[@]}"
  echo "sanitizer-suite: build-sanitize built in $(seconds) s"
  status=0
  ctest --test-dir build-sanitize -L default -E "$not_sanitized" --output-on-failure -j2 || status=1
  if [ -n "$(ls -A "$logs")" ]; then
    echo "sanitizer-suite: sanitizer reports:" >&2
    for f in "$logs"/*; do echo "== $f" >&2; cat "$f" >&2; done
    status=1
  fi
  echo "sanitizer-suite: sanitized build and tests took $(seconds) s"
  [ "$status" -eq 0 ] || { echo "sanitizer-suite: FAILED" >&2; exit 1; }
fi

if [ "$mode" != sanitize ]; then
  fuzz_start=$(date +%s)
  cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DVISCOR_BUILD_FUZZERS=ON -DVISCOR_WITH_FLOAT128=OFF \
        -DVISCOR_BUILD_TESTS=OFF -DVISCOR_BUILD_CLI=OFF -DVISCOR_BUILD_PYTHON=OFF -DVISCOR_WITH_ARB=OFF
  cmake --build build-fuzz -j2 --target viscor_fuzzers
  echo "sanitizer-suite: build-fuzz built in $(($(date +%s) - fuzz_start)) s"
  bash tests/fuzz/run_fuzzers.sh build-fuzz "$fuzz_seconds"
fi
echo "sanitizer-suite: passed in $(seconds) s"

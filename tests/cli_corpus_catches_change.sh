#!/usr/bin/env bash
# tools/cli_corpus.sh --check must fail on a corpus that differs by one digit of one e.
# Usage: cli_corpus_catches_change.sh VISCOR CORPUS SCRATCH_FILE
set -u
viscor=$1 corpus=$2 changed=$3
sed '0,/"e": "6/s//"e": "7/' "$corpus" > "$changed"
if cmp -s "$corpus" "$changed"; then
  echo "no e starting with 6 in $corpus to change: the check was not tried" >&2
  exit 1
fi
if bash "$(dirname "$0")/../tools/cli_corpus.sh" "$viscor" --check "$changed" > /dev/null 2>&1; then
  echo "cli_corpus.sh --check passed a corpus with a changed digit" >&2
  exit 1
fi
echo "caught: a corpus with one changed digit fails the check"

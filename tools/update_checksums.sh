#!/usr/bin/env bash
# Writes the checksum manifests (SHA256SUMS, the format of sha256sum) of the committed
# data files that viscor reads: the certified and proven tables, the approximation
# baseline, the error maps, the surrogates and their verification tables. viscor
# checks a listed file against its line before reading it (core/checksums.hpp), and
# keeps the line of a file it rewrites; run this after adding a data file, or after
# changing one by other means, and commit the manifests with the files.
#   tools/update_checksums.sh [reference_data]
set -euo pipefail
root="${1:-$(dirname "$0")/../reference_data}"
manifest() {  # directory, glob patterns...
  local dir="$1"; shift
  # shellcheck disable=SC2206  # the patterns are expanded here, in the data directory
  (cd "$dir" && shopt -s nullglob && files=($@) && [ "${#files[@]}" -gt 0 ] &&
   sha256sum -- "${files[@]}" | LC_ALL=C sort -k2 > SHA256SUMS && echo "update_checksums: $dir/SHA256SUMS (${#files[@]} files)")
}
manifest "$root" '*.csv'
manifest "$root/proven" '*.csv'
manifest "$root/proven/digits50" '*.csv'
manifest "$root/dem" '*.csv'
manifest "$root/error_maps" '*.csv'
manifest "$root/surrogates" '*.surrogate' '*.surrogate.verification.csv'

#!/usr/bin/env bash
# Installs viscor's build and test dependencies from Debian 12 packages.
# Idempotent: apt-get update runs once, and only when something is missing.
# Run as root (or with sudo available) on a fresh Debian 12 machine.
set -euo pipefail

# --cli: only what configuring and building the command-line tool needs (the README's
# main-job command); the DEM programs, Python and documentation packages are large
# and only the test suite uses them. Without it: everything (.ci/run).
cli_packages=(
  build-essential cmake pkg-config git python3
  libboost1.81-dev libmpfr-dev libgmp-dev libcli11-dev nlohmann-json3-dev libflint-arb-dev
  libgtest-dev googletest   # the default configure also sets up the tests (not built by the main job)
)

packages=(
  build-essential cmake pkg-config git
  libboost1.81-dev          # Boost.Math tanh-sinh/roots (1.74 is broken for mpfr; see README)
  libmpfr-dev libgmp-dev    # arbitrary precision
  libgtest-dev googletest   # unit tests
  libbenchmark-dev          # Google Benchmark
  libcli11-dev              # command line
  nlohmann-json3-dev        # JSON output and sidecars
  python3-matplotlib        # tools/plot_reference.py figures
  lammps liggghts           # DEM programs run by tests/dem_drop_*test.cpp (docs/dem.md)
  doxygen                   # API reference: cmake --build build --target doc
  libflint-arb-dev          # Arb ball arithmetic: proven enclosures, include/viscor/enclose (docs/proofs.md)
  libqd-dev                 # QD's double-double: include/viscor/core/double_double.hpp (docs/precision.md)
  pybind11-dev python3-dev  # Python module viscor (docs/python.md)
  python3-numpy python3-mpmath  # its vectorised evaluate and tests; Result.mpf
  yade                      # DEM program run by tests/yade_drop_*test.cpp (docs/dem.md, YADE 2023.02a)
  slurm-wlm munge           # a one-node Slurm cluster for the job array of docs/tables.md (tests/slurm_table_test.sh)
  python3-distributed       # viscor.dask: tables, points and evaluate on a Dask cluster (tests/python/test_dask.py)
  python3-tqdm              # progress bars of viscor.table and viscor.dask (docs/python.md)
  libnetcdf-dev             # the NetCDF form of tables: viscor table --format netcdf (docs/tables.md)
  python3-xarray python3-netcdf4  # Table.to_xarray() and reading NetCDF back (docs/python.md)
  clang libclang-rt-14-dev  # libFuzzer and clang's sanitizers: tests/fuzz (docs/robustness.md)
  libc++-14-dev libc++abi-14-dev  # the fuzzers' C++ library (tests/fuzz/CMakeLists.txt says why)
  emscripten                # the calculator page's WebAssembly: web/ (docs/web.md)
  chromium chromium-driver python3-selenium  # its test in a real headless browser (tests/web/)
)

case "${1:-}" in
  --cli) packages=("${cli_packages[@]}") ;;
  "") ;;
  *) echo "install-deps: unknown option '$1' (use --cli, or nothing for everything)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"

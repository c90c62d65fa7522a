#!/usr/bin/env bash
# Installs the Debian packages unidyn needs. Run as root on Debian 12 (bookworm); running it again
# is harmless. Usage: scripts/setup.sh [run|test|fuzz|bench|all]   (default all)
#   run     the `unidyn` command: compilers, CMake, Ninja and the libraries (scripts/run.sh), and
#           Node.js with npm where there is none (the report's web packages come from the npm
#           registry at build time)
#   test    run + GoogleTest, Google Benchmark, the benchmark peers the test build compiles, pdflatex,
#           SymPy, Chromium (the report's browser tests), pybind11 and Python's numpy, pytest,
#           pandas and distributed (the Python module, its tests and its Dask sweeps)
#   fuzz    run + clang with libFuzzer (scripts/fuzz.sh)
#   bench   test (which has Python with SymPy for the side-by-side runs of bench/run.sh)
#   all     every one of these and clang-format
set -euo pipefail

run=(
  build-essential cmake ninja-build pkg-config
  # libraries (DESIGN.md "Dependencies")
  libeigen3-dev libginac-dev libcln-dev libsundials-dev libyaml-cpp-dev
  libcli11-dev libfmt-dev libssl-dev libtinyxml2-dev
)
# tests and micro benchmarks, the peers of bench/ (compiled with them), pdflatex for the LaTeX
# documents `derive --standalone` writes, SymPy to read the JSON `derive` writes, and matplotlib,
# nbclient and ipykernel for the Python module's plots and the example notebooks run as tests,
# PyYAML for models built as dicts
test=(googletest libgtest-dev libgmock-dev libbenchmark-dev libmujoco-dev libsimbody-dev
  liborocos-kdl-dev libdart-utils-urdf-dev
  texlive-latex-base python3 python3-sympy chromium
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pandas python3-distributed
  python3-matplotlib python3-nbclient python3-ipykernel python3-yaml)
# Node.js and npm: Debian's, unless the machine has them already (a newer Node.js, say)
if ! command -v npm >/dev/null 2>&1; then run+=(nodejs npm); fi
# fuzzing: clang with libFuzzer
fuzz=(clang libclang-rt-14-dev)

case "${1:-all}" in
  run) packages=("${run[@]}") ;;
  test) packages=("${run[@]}" "${test[@]}") ;;
  fuzz) packages=("${run[@]}" "${fuzz[@]}") ;;
  bench) packages=("${run[@]}" "${test[@]}") ;;
  all) packages=("${run[@]}" "${test[@]}" "${fuzz[@]}" clang-format) ;;
  *) echo "setup.sh: unknown group '$1' (expected run, test, fuzz, bench or all)" >&2; exit 2 ;;
esac

# Skip apt entirely when everything is already there (fast re-runs, offline re-runs).
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
echo "setup: installing ${missing[*]}"
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
echo "setup: done"

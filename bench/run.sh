#!/usr/bin/env bash
# Builds the benchmarks (Release, with the MuJoCo and Simbody peers) and runs every side-by-side
# comparison; the tables go to standard output and bench/RESULTS.md.
# Usage: bench/run.sh [--quick]
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh bench
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DUNIDYN_BUILD_TESTS=OFF \
  -DUNIDYN_BUILD_BENCH=ON
cmake --build build-bench
python3 bench/run.py build-bench "$@"

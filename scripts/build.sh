#!/usr/bin/env bash
# Configures and builds unidyn. Usage: scripts/build.sh [--sanitize] [--only-cli]
#   default      Release build in build/: the command, the tests and the benchmarks
#   --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer build in build-sanitize/ (-O1 -g1:
#                stacks with files and lines, and long simulations in the tests stay fast enough;
#                -g1 rather than -g: 10 min and 3.5 GB rather than 15 min and 9 GB on 2 cores)
#   --only-cli   only the `unidyn` command and the libraries it needs (the main job)
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
options=(-DCMAKE_BUILD_TYPE=Release -DUNIDYN_BUILD_TESTS=ON -DUNIDYN_BUILD_BENCH=ON)
targets=()
for argument in "$@"; do
  case "$argument" in
    --sanitize)
      build_dir=build-sanitize
      options=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DUNIDYN_SANITIZE=ON
               -DUNIDYN_BUILD_TESTS=ON -DUNIDYN_BUILD_BENCH=OFF)
      ;;
    # without the tests' and benchmarks' packages (scripts/setup.sh run): not configured at all
    --only-cli) targets=(--target unidyn) options+=(-DUNIDYN_BUILD_TESTS=OFF -DUNIDYN_BUILD_BENCH=OFF) ;;
    *) echo "build.sh: unknown option $argument" >&2; exit 2 ;;
  esac
done

cmake -S . -B "$build_dir" -G Ninja "${options[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"

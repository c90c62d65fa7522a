#!/usr/bin/env bash
# Configures and builds unidyn. Usage: scripts/build.sh [--sanitize]
#   default      Release build in build/
#   --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer build in build-sanitize/ (-O1 -g:
#                debuggable stacks, and long simulations in the tests stay fast enough)
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
options=(-DCMAKE_BUILD_TYPE=Release)
if [[ "${1:-}" == "--sanitize" ]]; then
  build_dir=build-sanitize
  options=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g" -DUNIDYN_SANITIZE=ON
           -DUNIDYN_BUILD_BENCH=OFF)
fi

cmake -S . -B "$build_dir" -G Ninja "${options[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"

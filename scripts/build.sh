#!/usr/bin/env bash
# Configures and builds unidyn. Usage: scripts/build.sh [--sanitize]
#   default      Release build in build/
#   --sanitize   Debug build with AddressSanitizer + UndefinedBehaviorSanitizer in build-sanitize/
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
options=(-DCMAKE_BUILD_TYPE=Release)
if [[ "${1:-}" == "--sanitize" ]]; then
  build_dir=build-sanitize
  options=(-DCMAKE_BUILD_TYPE=Debug -DUNIDYN_SANITIZE=ON -DUNIDYN_BUILD_BENCH=OFF)
fi

cmake -S . -B "$build_dir" -G Ninja "${options[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"

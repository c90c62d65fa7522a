#!/usr/bin/env bash
# Installs the dependencies, builds unidyn and runs every test with ctest.
# Usage: scripts/test.sh [--sanitize]   (--sanitize: under AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh test
build_dir=build
if [[ "${1:-}" == "--sanitize" ]]; then build_dir=build-sanitize; fi
bash scripts/build.sh "$@"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"

#!/usr/bin/env bash
# Fuzzes the model-file reader, the expression parser and the URDF/MJCF importers with libFuzzer (clang, AddressSanitizer +
# UndefinedBehaviorSanitizer). Usage: scripts/fuzz.sh [SECONDS]   (each target; default 30)
#
# The corpus kept in the repository (fuzz/corpus/<target>) and the bundled models seed each run;
# new inputs go to build-fuzz/corpus/<target>. A crash, a sanitizer report, an uncaught exception,
# a hang (> 10 s) or more than 2 GB stops the run with the input that caused it (crash-*,
# timeout-*, oom-* in build-fuzz/) and a non-zero exit. A long campaign:
#   bash scripts/fuzz.sh 3600
# and, to keep what it found, merge the new inputs into the repository's corpus:
#   build-fuzz/fuzz/model_file_fuzzer -merge=1 fuzz/corpus/model_file build-fuzz/corpus/model_file
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-30}"
bash scripts/setup.sh fuzz
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DUNIDYN_FUZZ=ON -DUNIDYN_BUILD_TESTS=OFF \
  -DUNIDYN_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target model_file_fuzzer expression_fuzzer robot_file_fuzzer

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in model_file expression robot_file; do
  work="build-fuzz/corpus/$target"
  mkdir -p "$work"
  seeds=("fuzz/corpus/$target")
  if [[ "$target" == model_file ]]; then seeds+=(models); fi
  if [[ "$target" == robot_file ]]; then seeds+=(examples/urdf examples/mjcf tests/formats/models); fi
  echo "fuzz: $target for $seconds s"
  log="build-fuzz/$target.log"
  status=0
  (cd build-fuzz && "./fuzz/${target}_fuzzer" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -max_len=4096 -dict=../fuzz/model.dict -print_final_stats=1 \
    "../$work" "${seeds[@]/#/../}") >"$log" 2>&1 || status=$?
  if ((status != 0)); then
    tail -n 80 "$log"
    echo "fuzz: $target FAILED (status $status); the input is in build-fuzz/ (crash-*, timeout-*, oom-*)"
    exit 1
  fi
  grep -E "^(#[0-9]+.*DONE|Done|stat::number_of_executed_units|stat::peak_rss_mb)" "$log" || true
done
echo "fuzz: no crash"

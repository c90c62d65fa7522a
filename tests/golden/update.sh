#!/usr/bin/env bash
# Rewrites the golden equations of tests/cli/golden_equations.cpp from build/unidyn: every file
# <model>.<method>.<format> here is `unidyn derive <model> --method <method> --format <format>`.
# Run it only when a change of the printed equations is intended, and read the diff before
# committing it.
set -euo pipefail
cd "$(dirname "$0")"
for file in *.text *.latex *.json; do
  IFS=. read -r model method format <<<"$file"
  ../../build/unidyn derive "$model" --method "$method" --format "$format" >"$file"
done

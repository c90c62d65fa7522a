#!/usr/bin/env bash
# Installs the dependencies, builds unidyn and runs the main job on a bundled example: the
# spherical pendulum — its equations of motion by Lagrange and by Newton, the check that they
# agree, and a 100 s simulation (CSV in out/, summary on the terminal).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh run
bash scripts/build.sh --only-cli
mkdir -p out
model=spherical-pendulum
echo
./build/unidyn derive "$model"
echo
./build/unidyn derive "$model" --method newton-euler
echo
./build/unidyn check "$model"
echo
./build/unidyn simulate "$model" --t-end 100 -o "out/$model.csv"

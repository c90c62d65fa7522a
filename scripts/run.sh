#!/usr/bin/env bash
# Installs the dependencies, builds unidyn and runs the main job on a bundled example:
# the rotation of the book's worked example §6.5.1 in every parametrisation.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
bash scripts/build.sh
./build/unidyn rotation show --from matrix \
  0.835959 -0.283542 -0.469869 \
  0.271321 0.957764 -0.0952472 \
  0.47703 -0.0478627 0.877583

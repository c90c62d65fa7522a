#!/usr/bin/env bash
# Installs every build, test and benchmark dependency of unidyn from Debian packages.
# Run as root on Debian 12 (bookworm). Running it again is harmless.
set -euo pipefail

packages=(
  # build tools
  build-essential cmake ninja-build pkg-config clang-format
  # libraries (DESIGN.md "Dependencies")
  libeigen3-dev libginac-dev libcln-dev libsundials-dev libyaml-cpp-dev
  libcli11-dev libfmt-dev libssl-dev
  # tests and micro benchmarks
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  # fuzzing (scripts/fuzz.sh): clang with libFuzzer
  clang libclang-rt-14-dev
  # side-by-side benchmark peers (bench/)
  libmujoco-dev libsimbody-dev python3 python3-sympy
)

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

#!/usr/bin/env bash
# Builds cdref and runs every test, on a fresh Debian 12 machine: install, configure,
# build, ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
start=$(date +%s)
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release -j "$(nproc)"
echo "cdref: build and tests took $(( $(date +%s) - start )) s"

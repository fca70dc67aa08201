#!/usr/bin/env bash
# cdref's main job on a fresh Debian 12 machine: install, configure, build, run.
# Arguments are passed to the cdref command line.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target cdref_tools
exec ./build/release/cdref "$@"

#!/usr/bin/env bash
# Installs what cdref needs from Debian 12's packages, only when something is missing
# (so it is quick on a machine that has them). Runs as root, or through sudo.
set -euo pipefail
# Extra package names may be given as arguments (the fuzz build adds clang's).
pkgs=(cmake ninja-build g++ libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev catch2 libmpfrc++-dev libboost-dev python3
      gnuplot-nox nlohmann-json3-dev libglm-dev libbullet-dev libode-dev libembree-dev libfcl-dev libopen3d-dev libbenchmark-dev libopenmpi-dev openmpi-bin
      pybind11-dev python3-numpy python3-pytest libgtest-dev libgmock-dev libcli11-dev doxygen)
given=$#
[ $# -gt 0 ] && pkgs=("$@")
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  echo "cdref: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# Rapier's WebAssembly build for the gallery (npm's @dimforge/rapier3d-compat, pinned in
# scripts/rapier/package-lock.json), with the machine's node and npm (Debian's nodejs and npm where
# the machine has neither). Optional: where npm cannot reach its registry, the gallery goes without
# Rapier's rows and says so.
if [ "$given" = 0 ]; then
  rapier="$(cd "$(dirname "$0")" && pwd)/rapier"
  if [ ! -f "$rapier/node_modules/@dimforge/rapier3d-compat/package.json" ]; then
    if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
      sudo=""
      [ "$(id -u)" = 0 ] || sudo="sudo"
      export DEBIAN_FRONTEND=noninteractive
      $sudo apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null || true
    fi
    if command -v npm >/dev/null; then
      echo "cdref: installing Rapier's package for the gallery (npm ci in $rapier)" >&2
      (cd "$rapier" && npm ci --no-audit --no-fund --loglevel=error >/dev/null) ||
        echo "cdref: npm could not install Rapier's package: cdref peers goes without Rapier's rows" >&2
    fi
  fi
fi

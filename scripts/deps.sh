#!/usr/bin/env bash
# Installs what cdref needs from Debian 12's packages, only when something is missing
# (so it is quick on a machine that has them). Runs as root, or through sudo.
set -euo pipefail
# Extra package names may be given as arguments (the fuzz build adds clang's).
pkgs=(cmake ninja-build g++ libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev catch2 libmpfrc++-dev libboost-dev python3
      gnuplot-nox nlohmann-json3-dev libglm-dev libbullet-dev libode-dev libembree-dev libfcl-dev libbenchmark-dev libopenmpi-dev openmpi-bin
      pybind11-dev python3-numpy python3-pytest libgtest-dev libgmock-dev libcli11-dev doxygen)
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

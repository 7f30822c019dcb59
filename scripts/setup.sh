#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs every Debian package the project builds, tests or plots with; quiet and quick when
# all are present. Run as root or with sudo available.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ make pkg-config ccache
  verilator libsystemc-dev yosys
  libeigen3-dev libgtest-dev libgmock-dev googletest libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev
  gnuplot-nox
  clang libclang-rt-14-dev python3
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

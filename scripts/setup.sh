#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs every Debian package the project builds, tests or plots with; quick and silent when all
# are present. `--bench` adds the optional benchmark packages. Run as root or with sudo available.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ make pkg-config ccache dpkg-dev
  verilator libsystemc-dev yosys
  libeigen3-dev libgtest-dev libgmock-dev googletest libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libfast-float-dev
  gnuplot-nox
  libsoci-dev libboost-dev libpq-dev libsqlite3-dev libssl-dev postgresql
  clang libclang-rt-14-dev python3
)

# Optional, for benchmarks only (`bash scripts/setup.sh --bench`): bench/sosfilt_peer.sh times
# scipy.signal.sosfilt beside the sample model (docs/benchmarks_core.md). Nothing builds or tests
# with these, so CI does not install them and a failed install only warns.
BENCH_PACKAGES=()
if [ "${1:-}" = "--bench" ]; then
  BENCH_PACKAGES=(python3-scipy)
fi

missing_of() {
  for pkg in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      echo "$pkg"
    fi
  done
}
mapfile -t missing < <(missing_of "${PACKAGES[@]}")
bench_missing=()
if [ "${#BENCH_PACKAGES[@]}" -gt 0 ]; then
  mapfile -t bench_missing < <(missing_of "${BENCH_PACKAGES[@]}")
fi

if [ "${#missing[@]}" -eq 0 ] && [ "${#bench_missing[@]}" -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

export DEBIAN_FRONTEND=noninteractive
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq >/dev/null
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ "${#bench_missing[@]}" -gt 0 ]; then
  { [ "${#missing[@]}" -gt 0 ] || $SUDO apt-get update -qq; } >/dev/null 2>&1 &&
    $SUDO apt-get install -y -qq --no-install-recommends "${bench_missing[@]}" >/dev/null 2>&1 ||
    echo "setup: optional benchmark packages not installed: ${bench_missing[*]}" >&2
fi

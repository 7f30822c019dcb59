#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# An installed flange runs from a copy of its prefix alone. Installs the build folder into a
# temporary prefix, copies the prefix elsewhere, and from a working folder outside the source
# tree runs `flange --version`, design, cosim, synth, run --engine rtl and demo.
#   bash tests/install/install_prefix_test.sh BUILD_DIR SOURCE_DIR
# The source and build folders are out of reach: in a private mount namespace (unshare, when the
# machine permits one) an empty folder is mounted over each; FLANGE_NO_SOURCE_TREE=1 forbids the
# fallback to the source tree in any case. Afterwards every text file the runs wrote (the
# Verilated runners' makefiles and compiler dependency lists, reports, JSON) is searched for the
# two folders' paths. (Binaries are left out: the runner's debug information names the folder
# its archives were compiled in, which nothing reads.)
set -euo pipefail

build="$(cd "$1" && pwd)"
source="$(cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/staged" >/dev/null
cp -a "$work/staged" "$work/prefix"
rm -rf "$work/staged"
mkdir -p "$work/cwd" "$work/xdg" "$work/empty"

# The runs, as a user with only the prefix would type them. Sample counts are the smallest the
# commands take; the Verilated runner of measurement_sos, built by cosim, serves run and demo.
cat > "$work/runs.sh" <<'RUNS'
set -euo pipefail
flange="$PREFIX/bin/flange"
# Runs `flange ARGS...`, echoing it and its time; with LOG set, its output goes there.
step() {
  local start=$SECONDS
  echo "$ flange $*"
  if [ -n "${LOG:-}" ]; then "$flange" "$@" >"$LOG"; else "$flange" "$@"; fi
  echo "  ($((SECONDS - start)) s)"
}
step --version | tee version.txt
grep -qx "data: $PREFIX/share/flange (installed)" version.txt
step design --fs 6 --order 5 --fc 0.5742 --name small --out small
step cosim --coeffs "$PREFIX/share/flange/coeffs/measurement_sos/filter.json" --samples 200
step synth --coeffs coeffs/measurement_sos --out synthesis.md
step simulate --scenario bench --seed 1 --out bench.csv
step calibrate --data bench.csv --out model.json
step run --input bench.csv --calibration model.json --engine rtl --out results.csv \
  --coeffs "$PREFIX/share/flange/coeffs/measurement_sos/filter.json"
LOG=demo.log step demo --out demo
grep -q "demo: everything is in demo/" demo.log
RUNS

export PREFIX="$work/prefix" FLANGE_NO_SOURCE_TREE=1 XDG_CACHE_HOME="$work/xdg"
unset FLANGE_DATA_DIR FLANGE_COSIM_CACHE
hide="mount --bind '$work/empty' '$source'"
case "$build/" in
  "$source"/*) ;;
  *) hide="$hide && mount --bind '$work/empty' '$build'" ;;
esac
run="cd '$work/cwd' && bash '$work/runs.sh'"
if unshare --mount --propagation private true 2>/dev/null; then
  echo "install test: source and build folders hidden in a private mount namespace"
  unshare --mount --propagation private bash -c "$hide && $run"
elif unshare --mount --map-root-user --propagation private true 2>/dev/null; then
  echo "install test: source and build folders hidden in a private user and mount namespace"
  unshare --mount --map-root-user --propagation private bash -c "$hide && $run"
else
  echo "install test: no mount namespace here; FLANGE_NO_SOURCE_TREE=1 and the search below"
  bash -c "$run"
fi

if grep -rlIF -e "$source" -e "$build" "$work/cwd" "$work/xdg" >"$work/leaks.txt"; then
  echo "install test: these files name the source or build folder:" >&2
  cat "$work/leaks.txt" >&2
  exit 1
fi
echo "install test: design, cosim, synth, run --engine rtl and demo ran from $work/prefix alone"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# RTL line and toggle coverage of rtl/ (docs/coverage.md): builds the co-simulation tests of every
# coefficient set and the board tests with Verilator --coverage-line --coverage-toggle in a build
# folder of their own, runs them, merges the coverage files and prints line and toggle coverage
# per RTL file.
#
#   bash scripts/rtl_coverage.sh [build-dir]        (default: build-cov)
#
# Environment: FLANGE_COVERAGE_JOBS (default 2) parallel compile jobs and test binaries;
# FLANGE_COVERAGE_SOAK=1 also runs the million-sample soak test (it adds no coverage, only time).
# Writes into <build-dir>/coverage/: raw/ (one .dat per model instance), merged.dat, annotated/
# (`verilator_coverage --annotate`: every source line with its count, '%' on the ones never
# reached), logs/ (one per test binary) and report.txt (the table). Exit status 1 when a test
# failed (the report is still written) or a step could not run.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(realpath -m "${1:-$root/build-cov}")
jobs=${FLANGE_COVERAGE_JOBS:-2}
out=$build/coverage
start=$SECONDS

# A coverage build of its own: never turn an existing normal build into one.
cache=$build/CMakeCache.txt
if [[ -f $cache ]] && ! grep -q '^FLANGE_RTL_COVERAGE:BOOL=ON$' "$cache"; then
  echo "rtl_coverage: $build is a build without FLANGE_RTL_COVERAGE; name another folder" >&2
  exit 1
fi
if [[ ! -f $cache ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DFLANGE_RTL_COVERAGE=ON >/dev/null
fi

# The test binaries: the co-simulation tests of every coefficient set tb/CMakeLists.txt adds, and
# the board tests (one channel and twelve; the link-budget test adds no coverage, only time).
mapfile -t cosim < <(ninja -C "$build" -t targets all |
                     sed -n 's/^\(iir_core_cosim_[a-z0-9_]*_test\): .*/\1/p' | sort -u)
if [[ ${#cosim[@]} -eq 0 ]]; then
  echo "rtl_coverage: no iir_core_cosim_*_test target in $build (a Ninja build is needed)" >&2
  exit 1
fi
targets=("${cosim[@]}" basys3_top_cosim_test board_stream_test basys3_top_channels_test
         board_channels_stream_test board_ftdi_stream_test)
echo "rtl_coverage: building ${#targets[@]} test binaries in $build (-j$jobs)"
build_log=$build/rtl_coverage_build.log
cmake --build "$build" --parallel "$jobs" --target "${targets[@]}" >"$build_log" ||
  { tail -n 30 "$build_log" >&2; exit 1; }
built=$SECONDS

rm -rf "$out"
mkdir -p "$out/raw" "$out/logs"
export FLANGE_COVERAGE_DIR=$out/raw
# The soak test adds time and no coverage; the link's rate tests time the wall clock, which an
# instrumented model on a shared machine cannot keep to (the protocol model's rate tests reach no
# RTL at all).
filter=-IirCoreSoak.*:BoardFtdiStream.WindowCarries*:BoardFtdiStream.StopAndWait*
[[ ${FLANGE_COVERAGE_SOAK:-0} == 1 ]] && filter=-BoardFtdiStream.WindowCarries*:BoardFtdiStream.StopAndWait*
echo "rtl_coverage: running them (logs in $out/logs)"
failed=0
# Working directory: the build folder, as under CTest.
printf '%s\n' "${targets[@]}" |
  (cd "$build" && xargs -P "$jobs" -I{} sh -c \
     'if tb/{} --gtest_filter="$1" >"$2/{}.log" 2>&1; then echo "  passed: {}";
      else echo "  FAILED: {} (see $2/{}.log)"; exit 1; fi' _ "$filter" "$out/logs") || failed=1
ran=$SECONDS

shopt -s nullglob
dats=("$out"/raw/*.dat)
if [[ ${#dats[@]} -eq 0 ]]; then
  echo "rtl_coverage: no coverage file in $out/raw" >&2
  exit 1
fi
verilator_coverage --write "$out/merged.dat" "${dats[@]}" >/dev/null
verilator_coverage --annotate "$out/annotated" --annotate-min 1 "$out/merged.dat" >/dev/null
echo "rtl_coverage: ${#dats[@]} coverage files merged into $out/merged.dat"
echo
python3 "$root/scripts/rtl_coverage_report.py" --root "$root" "$out/merged.dat" |
  tee "$out/report.txt"
echo
echo "rtl_coverage: build $((built - start)) s, tests $((ran - built)) s," \
     "total $((SECONDS - start)) s"
if [[ $failed -ne 0 ]]; then
  echo "rtl_coverage: a test failed (see above); the coverage is of what ran" >&2
  exit 1
fi

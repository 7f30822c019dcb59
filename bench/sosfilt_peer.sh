#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The sample model (IirSampleModel) against scipy.signal.sosfilt in float64, on the same 1 M
# samples and the same SOS of measurement_sos and vehicle_sos, in one run:
#   bash bench/sosfilt_peer.sh [SAMPLE_MODEL_BENCH] [Google Benchmark flags...]
# (SAMPLE_MODEL_BENCH defaults to build/bench/sample_model_bench; build it with
# `ninja -C build sample_model_bench`.) Prints the bench's table, then sosfilt's rate and the
# ratios sample model / sosfilt and reference / sosfilt (aims: sample model >= 2x sosfilt,
# ReferenceFilter::process >= 1x; ReferenceFilter::step per sample is shown beside).
# Needs a python3 with numpy and scipy: Debian's python3-scipy, one of the optional benchmark
# packages of scripts/setup.sh (`bash scripts/setup.sh --bench`).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bench="$here/../build/bench/sample_model_bench"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  bench="$1"
  shift
fi

python=""
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1 && "$candidate" -c 'import numpy, scipy.signal' 2>/dev/null; then
    python="$candidate"
    break
  fi
done
if [ -z "$python" ]; then
  echo "sosfilt_peer: no python3 with numpy and scipy; install python3-scipy (scripts/setup.sh" \
    "installs it among the optional benchmark packages)" >&2
  exit 2
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$bench" --dump_dir="$work" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_out="$work/bench.json" --benchmark_out_format=json "$@"
"$python" "$here/sosfilt_peer.py" "$work"

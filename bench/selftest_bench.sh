#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The blind check of `flange diagnose` at benchmark size (docs/diagnose.md, "Blind check"):
#   bash bench/selftest_bench.sh [CASES] [SEED] [FLANGE]   (defaults: 50, 1, build/flange)
# Prints the per-case table and the summary against the aims, and leaves selftest.json and
# selftest.md (the per-case table; docs/diagnose_figures.md records its summary) in
# build/selftest_bench/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cases="${1:-50}"
seed="${2:-1}"
flange="${3:-$here/../build/flange}"
out="$here/../build/selftest_bench"
/usr/bin/time -f "wall %e s, max RSS %M kB" \
  "$flange" diagnose --selftest --cases "$cases" --seed "$seed" --out "$out"

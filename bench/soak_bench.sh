#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The soak (docs/benchmarks_core.md, "Soak"): the fast path against the cycle model on 10^8
# samples per checked-in set (half uniform random over the whole input range, half full-scale
# squares), and the Verilated RTL against the cycle model, every pin every cycle, on 10^7 samples
# per set (half random, half full scale) through `flange cosim`.
#   bash bench/soak_bench.sh [MODEL_SAMPLES_PER_STIMULUS] [RTL_SAMPLES_PER_STIMULUS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
model_n="${1:-50000000}"
rtl_n="${2:-5000000}"
cmake --build "$build" --target soak_model flange > /dev/null
echo "== fast path vs cycle model, $model_n samples per stimulus"
"$build/bench/soak_model" "$model_n"
echo "== Verilated RTL vs cycle model, $rtl_n samples per stimulus"
for set in measurement_sos measurement_df1 vehicle_sos; do
  for stimulus in random fullscale; do
    start=$(date +%s.%N)
    line=$("$build/flange" cosim --coeffs "$root/coeffs/$set/filter.json" --samples "$rtl_n" \
             --stimulus "$stimulus" --seed 11)
    end=$(date +%s.%N)
    printf '%-16s %-10s %s (%.1f s)\n' "$set" "$stimulus" "$line" "$(awk "BEGIN { print $end - $start }")"
  done
done

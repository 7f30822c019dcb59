# SPDX-License-Identifier: MIT
# Sourced by bench/wear_coverage.sh and bench/wear_coverage_alt.sh: one fleet's `flange wear
# --truth` run, the same on either reality.
#   wear_truth_check FLANGE STORE_URL TRUTH_JSON DIR SEED
# Writes DIR/wear/ and DIR/wear.log, prints the fleet's verdict line and leaves the per-wheel check
# in DIR/wear/truth_check.json. Exit status 1 of `flange wear` is a failed check against the truth,
# which the coverage table counts; any other failure stops the calling script.
wear_truth_check() {
  local flange="$1" store="$2" truth="$3" dir="$4" seed="$5" status=0
  rm -rf "$dir/wear"
  "$flange" wear --store "$store" --out "$dir/wear" --truth "$truth" > "$dir/wear.log" || status=$?
  if [ "$status" -gt 1 ]; then
    echo "flange wear failed on seed $seed (exit $status): $dir/wear.log" >&2
    exit "$status"
  fi
  echo "seed $seed: $(grep '^verdict' "$dir/wear.log")"
}

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the checked-in coefficient sets under coeffs/ from the thesis's two filters.
#   bash coeffs/regenerate.sh [FLANGE]          rewrite coeffs/<set>/
#   bash coeffs/regenerate.sh --check [FLANGE]  regenerate into a temp folder, compare byte for byte
# FLANGE defaults to build/flange. Keep in step with coeffs/src/thesis_filters.cpp.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
check=0
if [ "${1:-}" = "--check" ]; then
  check=1
  shift
fi
flange="${1:-$here/../build/flange}"

# set name | arguments of `flange design`
SETS=(
  "measurement_sos|--fs 6 --order 5 --fc 0.5742 --structure sos --name measurement"
  "measurement_df1|--fs 6 --order 5 --fc 0.5742 --structure df1 --name measurement"
  "vehicle_sos|--fs 100 --order 7 --fc 0.259 --structure sos --name vehicle"
)
# The thesis's 7th-order direct form does not survive 18-bit quantisation: it must be refused.
REFUSED="--fs 100 --order 7 --fc 0.259 --structure df1 --name vehicle"

out_root="$here"
if [ "$check" -eq 1 ]; then
  out_root="$(mktemp -d)"
  trap 'rm -rf "$out_root"' EXIT
fi

status=0
for entry in "${SETS[@]}"; do
  name="${entry%%|*}"
  args="${entry#*|}"
  # shellcheck disable=SC2086
  "$flange" design $args --out "$out_root/$name" >/dev/null
  if [ "$check" -eq 1 ]; then
    for file in "$here/$name"/*; do
      if ! cmp -s "$file" "$out_root/$name/$(basename "$file")"; then
        echo "regenerate: $name/$(basename "$file") differs from a fresh run of: flange design $args" >&2
        echo "  to update: bash coeffs/regenerate.sh" >&2
        status=1
      fi
    done
    for file in "$out_root/$name"/*; do
      [ -e "$here/$name/$(basename "$file")" ] || { echo "regenerate: $name/$(basename "$file") is missing from coeffs/" >&2; status=1; }
    done
  fi
done

set +e
# shellcheck disable=SC2086
"$flange" design $REFUSED --out "$out_root/vehicle_df1" >/dev/null 2>&1
refused=$?
set -e
if [ "$refused" -ne 3 ] || [ -e "$out_root/vehicle_df1" ]; then
  echo "regenerate: expected the 7th-order direct form to be refused with status 3 and no files (got $refused)" >&2
  status=1
fi
exit "$status"

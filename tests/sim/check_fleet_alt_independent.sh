#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# sim/fleet_alt/ (the second fleet reality) includes only its own headers and standard or
# third-party ones (nothing of sim/src/, host/, model/ or diagnose/: its formulas are its own),
# and only cli/ and the tests include it. Usage: check_fleet_alt_independent.sh SOURCE_DIR
set -euo pipefail
root=${1:?source dir}
alt=$root/sim/fleet_alt
status=0
own=$(cd "$alt" && ls *.h)
while IFS= read -r line; do
  header=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"${line#*:}")
  if ! grep -qx "$header" <<<"$own"; then
    echo "fleet_alt reaches outside itself: $line"
    status=1
  fi
done < <(grep -Hn '#include "' "$alt"/*.h "$alt"/*.cpp)
if grep -rn -E '#include "fleet_alt_' "$root/sim/src" "$root/host" "$root/model" "$root/diagnose"; then
  echo "the twin, the service path or the diagnosis reaches the second fleet reality (above)"
  status=1
fi
[ $status -eq 0 ] && echo "fleet_alt is independent of the twin and the service path"
exit $status

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# diagnose/alt_reality/ includes only its own headers, runtime/'s (the version its files name,
# nothing of the twin or the method) and standard or third-party ones (no sim/, diagnose/, host/
# or model/ header), and the diagnosis's own folders include nothing of the alternative reality
# or its blind check. Usage: check_alt_reality_independent.sh SOURCE_DIR
set -euo pipefail
root=${1:?source dir}
alt=$root/diagnose/alt_reality
status=0
own=$(cd "$alt" && ls *.h; cd "$root/runtime" && ls *.h)
while IFS= read -r line; do
  header=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"${line#*:}")
  if ! grep -qx "$header" <<<"$own"; then
    echo "alt_reality reaches outside itself: $line"
    status=1
  fi
done < <(grep -Hn '#include "' "$alt"/*.h "$alt"/*.cpp)
if grep -rn -E '#include "(alt_|finding_class)' "$root/diagnose/data" "$root/diagnose/hw" "$root/sim" "$root/host"; then
  echo "the method reaches the alternative reality (above)"
  status=1
fi
if grep -n -E 'flange_alt_reality|flange_diagnose_alt_check' "$root/sim/CMakeLists.txt" >/dev/null ||
   sed -n '/add_library(flange_diagnose_data/,/^$/p' "$root/diagnose/CMakeLists.txt" | grep -q alt_; then
  echo "the method links the alternative reality"
  status=1
fi
[ $status -eq 0 ] && echo "alt_reality is independent of the twin and the method"
exit $status

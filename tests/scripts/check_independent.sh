#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Checks that a folder written from formulas of its own stays apart from the code it checks:
#   - the folder's files include only its own headers, those of the folders given with --own,
#     and standard or third-party ones;
#   - no file under the folders given with --not-from includes a header matching --headers;
#   - no CMake file given with --cmake names a library matching --libs.
# Usage:
#   check_independent.sh ROOT FOLDER NAME [--own DIR]... --headers REGEX [--not-from DIR]...
#                        [--libs REGEX --cmake FILE...]
# Folders and files are relative to ROOT. Prints each finding; exit 1 if any, 0 if none.
set -euo pipefail
root=${1:?source dir}; folder=${2:?folder}; name=${3:?name}
shift 3
own_dirs=("$folder"); not_from=(); cmake_files=(); headers=""; libs=""
while [ $# -gt 0 ]; do
  case "$1" in
    --own) own_dirs+=("$2"); shift 2 ;;
    --headers) headers=$2; shift 2 ;;
    --not-from) not_from+=("$2"); shift 2 ;;
    --libs) libs=$2; shift 2 ;;
    --cmake) cmake_files+=("$2"); shift 2 ;;
    *) echo "check_independent.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
status=0
own=$(for d in "${own_dirs[@]}"; do (cd "$root/$d" && ls *.h); done)
while IFS= read -r line; do
  header=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"${line#*:}")
  if ! grep -qx "$header" <<<"$own"; then
    echo "$name reaches outside itself: $line"
    status=1
  fi
done < <(grep -Hn '#include "' "$root/$folder"/*.h "$root/$folder"/*.cpp)
for d in "${not_from[@]}"; do
  if grep -rn -E "#include \"($headers)" "$root/$d"; then
    echo "$d reaches $name (above)"
    status=1
  fi
done
for f in "${cmake_files[@]}"; do
  if grep -n -E "$libs" "$root/$f"; then
    echo "$f links $name (above)"
    status=1
  fi
done
[ $status -eq 0 ] && echo "$name is independent of what it checks"
exit $status

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The long fuzzing run (docs/reliability.md): every libFuzzer harness for SECONDS (default 300)
# on a copy of its kept corpus, in the sanitized clang build of scripts/reliability.sh.
#   bash bench/fuzz_bench.sh [SECONDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exec bash "$root/scripts/reliability.sh" --fuzz-seconds "${1:-300}"

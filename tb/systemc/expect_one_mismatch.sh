#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the SystemC bench given as arguments with a planted fault and succeeds only when the bench
# caught it: exit status 1 and exactly one mismatch in its summary line.
out="$("$@")"
status=$?
printf '%s\n' "$out"
if [ "$status" -ne 1 ]; then
  echo "expect_one_mismatch: exit status $status, expected 1: $*" >&2
  exit 1
fi
if [[ "$out" != *", 1 mismatches,"* ]]; then
  echo "expect_one_mismatch: the summary does not report exactly one mismatch: $*" >&2
  exit 1
fi

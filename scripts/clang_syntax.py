#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every translation unit of the project through clang's front end (-fsyntax-only), with the
flags of the g++ build (its compile_commands.json), so that the tree keeps building with clang as
well as g++ (docs/reliability.md, "Compilers"). Generated code (Verilator's, in the build folder)
and third-party sources are left out. CTest runs it as ClangSyntax.EveryTranslationUnit.

    python3 scripts/clang_syntax.py BUILD_DIR [--clang clang++] [--jobs 2] [--only SUBSTRING]

Exit status 0 when every unit passes, 1 when one fails (its command and clang's message are
printed), 2 for a bad argument.
"""
import argparse
import concurrent.futures
import json
import os
import shlex
import subprocess
import sys

# g++ options clang does not take; the value after an option in TAKES_VALUE goes with it.
DROP = {"-fno-fat-lto-objects", "-fconcepts-diagnostics-depth=3"}
DROP_PREFIXES = ("-fdiagnostics-color",)
TAKES_VALUE = {"-o", "-MF", "-MT", "-MQ"}


def clang_command(entry, clang):
    args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    out = [clang]
    skip = False
    for arg in args[1:]:
        if skip:
            skip = False
            continue
        if arg in TAKES_VALUE:
            skip = True
            continue
        if arg in ("-c", "-MD", "-MMD") or arg in DROP or arg.startswith(DROP_PREFIXES):
            continue
        out.append(arg)
    return out + ["-fsyntax-only", "-Wno-unknown-warning-option"]


def project_units(build_dir, only):
    source_dir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    build_dir = os.path.abspath(build_dir)
    with open(os.path.join(build_dir, "compile_commands.json")) as f:
        entries = json.load(f)
    seen = {}
    for entry in entries:
        path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
        if not path.startswith(source_dir + os.sep) or path.startswith(build_dir + os.sep):
            continue
        if only and only not in path:
            continue
        seen.setdefault(path, entry)  # one flag set per file is enough for the front end
    return seen


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("--clang", default="clang++")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", default="")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.build_dir, "compile_commands.json")):
        print(f"clang_syntax: {args.build_dir}/compile_commands.json not found (configure the "
              "build first)", file=sys.stderr)
        return 2
    units = project_units(args.build_dir, args.only)

    def check(item):
        path, entry = item
        command = clang_command(entry, args.clang)
        done = subprocess.run(command, cwd=entry["directory"], capture_output=True, text=True)
        return path, command, done.returncode, done.stderr

    failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for path, command, status, stderr in pool.map(check, sorted(units.items())):
            if status != 0:
                failed += 1
                print(f"clang_syntax: {path} fails with clang:\n{stderr}\n  reproduce: "
                      f"{shlex.join(command)}", file=sys.stderr)
    print(f"clang_syntax: {len(units) - failed} of {len(units)} translation units pass "
          f"{args.clang} -fsyntax-only")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

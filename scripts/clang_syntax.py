#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every translation unit of the project through clang's front end (-fsyntax-only), with the
flags of the g++ build (its compile_commands.json), so that the tree keeps building with clang as
well as g++ (docs/reliability.md, "Compilers"). Generated code (Verilator's, in the build folder)
and third-party sources are left out. CTest runs it as ClangSyntax.EveryTranslationUnit.

    python3 scripts/clang_syntax.py BUILD_DIR [--clang clang++] [--jobs 2] [--only SUBSTRING]

A unit that passed is remembered (like ccache does for objects) under a key made of its clang
command, the clang version and the text of every file it includes (the g++ build's dependency
list, `ninja -t deps`; without one, every header of the project), in
${XDG_CACHE_HOME:-~/.cache}/flange/clang_syntax; a later run checks only the units whose key
changed, so CI pays the whole front-end pass (about 12 CPU minutes on this machine) once, then
only for what a change touches. FLANGE_CLANG_SYNTAX_CACHE overrides the folder (empty: none).

Exit status 0 when every unit passes, 1 when one fails (its command and clang's message are
printed), 2 for a bad argument.
"""
import argparse
import concurrent.futures
import hashlib
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


def cache_dir():
    if "FLANGE_CLANG_SYNTAX_CACHE" in os.environ:
        return os.environ["FLANGE_CLANG_SYNTAX_CACHE"] or None
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "flange", "clang_syntax")


def headers_digest(source_dir, build_dir, clang):
    """The clang version and every project header's text, in one digest."""
    digest = hashlib.sha256()
    digest.update(subprocess.run([clang, "--version"], capture_output=True, text=True).stdout.encode())
    for top, dirs, files in os.walk(source_dir):
        dirs[:] = sorted(d for d in dirs if os.path.join(top, d) != build_dir and d != ".git")
        for name in sorted(files):
            if name.endswith((".h", ".hpp", ".inc")):
                path = os.path.join(top, name)
                digest.update(path.encode())
                with open(path, "rb") as f:
                    digest.update(f.read())
    return digest.hexdigest()


def ninja_deps(build_dir):
    """Object file -> the files its g++ compile read, from ninja's dependency log."""
    done = subprocess.run(["ninja", "-C", build_dir, "-t", "deps"], capture_output=True, text=True)
    deps, current = {}, None
    for line in done.stdout.splitlines():
        if line and not line.startswith(" "):
            current = line.split(":")[0]
            deps[current] = []
        elif line.strip() and current is not None:
            deps[current].append(line.strip())
    return deps


FILE_DIGESTS = {}


def file_digest(path):
    if path not in FILE_DIGESTS:
        try:
            with open(path, "rb") as f:
                FILE_DIGESTS[path] = hashlib.sha256(f.read()).hexdigest()
        except OSError:
            FILE_DIGESTS[path] = "missing"
    return FILE_DIGESTS[path]


def unit_key(path, command, headers, included):
    """`included`: the files the unit reads (paths relative to its build folder), or None."""
    digest = hashlib.sha256((headers + "\0" + shlex.join(command)).encode())
    digest.update(file_digest(path).encode())
    for f in included or []:
        digest.update(f.encode() + file_digest(f).encode())
    return digest.hexdigest()


def object_of(entry):
    args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    return args[args.index("-o") + 1] if "-o" in args else None


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
    cache = cache_dir()
    source_dir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    build_dir = os.path.abspath(args.build_dir)
    deps = ninja_deps(build_dir) if cache else {}
    clang_version = subprocess.run([args.clang, "--version"], capture_output=True,
                                   text=True).stdout
    all_headers = None  # computed only when a unit has no dependency list
    cached = 0

    def check(item):
        nonlocal cached
        path, entry = item
        command = clang_command(entry, args.clang)
        stamp = None
        if cache:
            included = deps.get(object_of(entry) or "")
            if included:
                included = [os.path.normpath(os.path.join(entry["directory"], f)) for f in included]
                headers = clang_version
            else:
                nonlocal all_headers
                if all_headers is None:
                    all_headers = headers_digest(source_dir, build_dir, args.clang)
                headers = all_headers
            stamp = os.path.join(cache, unit_key(path, command, headers, included))
        if stamp and os.path.exists(stamp):
            cached += 1
            return path, command, 0, ""
        done = subprocess.run(command, cwd=entry["directory"], capture_output=True, text=True)
        if stamp and done.returncode == 0:
            os.makedirs(cache, exist_ok=True)
            open(stamp, "w").close()
        return path, command, done.returncode, done.stderr

    failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for path, command, status, stderr in pool.map(check, sorted(units.items())):
            if status != 0:
                failed += 1
                print(f"clang_syntax: {path} fails with clang:\n{stderr}\n  reproduce: "
                      f"{shlex.join(command)}", file=sys.stderr)
    print(f"clang_syntax: {len(units) - failed} of {len(units)} translation units pass "
          f"{args.clang} -fsyntax-only ({cached} unchanged since they last passed)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

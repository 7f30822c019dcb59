#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that the diagnosis's data layer keeps its stage order (diagnose/data/README.md).

  python3 scripts/diagnose_layers.py [--root DIR]

The order is read from diagnose/CMakeLists.txt, where each stage is a
`flange_diagnose_stage(NAME "BELOW" SOURCES ... DIRS ...)` library linking only the stage below
it. A file belongs to the stage whose folder holds it. The check fails when

  - a file includes a header of a later stage (the build would fail too, since that header is not
    on its include path; this names the line),
  - the files include each other in a cycle (headers included by name, within or across stages),
  - a .cpp under diagnose/data is in no stage's SOURCES, or a stage's folder does not exist.

Each finding is one line, `path:line: what`; the exit status is 1 when there is any, 2 when the
CMake file cannot be read, 0 otherwise.
"""

import argparse
import os
import re
import sys

STAGE_CALL = re.compile(r'flange_diagnose_stage\((\w+)\s+"(\w*)"(.*?)\)', re.S)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def read_stages(cmake_text):
    """[(name, below, sources, dirs)] in the order the CMake file defines them."""
    stages = []
    for name, below, body in STAGE_CALL.findall(cmake_text):
        words = body.split()
        sources, dirs, into = [], [], None
        for word in words:
            if word in ("SOURCES", "DIRS"):
                into = sources if word == "SOURCES" else dirs
            elif into is not None:
                into.append(word)
        stages.append((name, below, sources, dirs))
    return stages


def stage_order_problems(stages):
    """Each stage must link the one defined just before it (the first links none)."""
    problems = []
    for i, (name, below, _, _) in enumerate(stages):
        expected = stages[i - 1][0] if i > 0 else ""
        if below != expected:
            problems.append(f"diagnose/CMakeLists.txt: stage {name} links '{below}', "
                            f"expected '{expected}' (the stage defined before it)")
    return problems


def files_by_stage(root, stages):
    """{relative path: stage index} for every .h/.cpp in the stages' folders (deepest folder
    wins), and the problems found on the way."""
    owner, problems = {}, []
    folders = []
    for index, (name, _, _, dirs) in enumerate(stages):
        for d in dirs:
            path = os.path.join(root, "diagnose", d)
            if not os.path.isdir(path):
                problems.append(f"diagnose/{d}: folder of stage {name} does not exist")
            folders.append((d, index))
    folders.sort(key=lambda f: -len(f[0]))
    data = os.path.join(root, "diagnose", "data")
    for dirpath, _, names in os.walk(data):
        for n in names:
            if not n.endswith((".h", ".cpp")):
                continue
            rel = os.path.relpath(os.path.join(dirpath, n), os.path.join(root, "diagnose"))
            for d, index in folders:
                if os.path.dirname(rel) == d:
                    owner[rel] = index
                    break
            else:
                problems.append(f"diagnose/{rel}: in no stage's folder")
    listed = {s for _, _, sources, _ in stages for s in sources}
    for rel in sorted(owner):
        if rel.endswith(".cpp") and rel not in listed:
            problems.append(f"diagnose/{rel}: in no stage's SOURCES")
    return owner, problems


def includes_of(root, rel, by_name):
    """[(line number, included file's relative path)] of the data layer's files `rel` includes."""
    found = []
    with open(os.path.join(root, "diagnose", rel), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m and os.path.basename(m.group(1)) in by_name:
                found.append((number, by_name[os.path.basename(m.group(1))]))
    return found


def cycle_problems(graph):
    """One line per include cycle found by a depth-first walk (each cycle reported once)."""
    problems, state, stack = [], {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in graph.get(node, []):
            if state.get(nxt) == "open":
                cycle = stack[stack.index(nxt):] + [nxt]
                problems.append(f"diagnose/{node}: include cycle " + " -> ".join(cycle))
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = "done"

    for node in sorted(graph):
        if node not in state:
            visit(node)
    return problems


def check(root):
    with open(os.path.join(root, "diagnose", "CMakeLists.txt"), encoding="utf-8") as f:
        stages = read_stages(f.read())
    problems = stage_order_problems(stages)
    owner, found = files_by_stage(root, stages)
    problems += found
    by_name = {os.path.basename(rel): rel for rel in owner}
    graph = {}
    for rel in sorted(owner):
        for number, target in includes_of(root, rel, by_name):
            graph.setdefault(rel, []).append(target)
            if owner[target] > owner[rel]:
                problems.append(
                    f"diagnose/{rel}:{number}: includes {os.path.basename(target)} of stage "
                    f"{stages[owner[target]][0]}, above its own stage {stages[owner[rel]][0]}")
    problems += cycle_problems(graph)
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    args = parser.parse_args()
    try:
        problems = check(os.path.abspath(args.root))
    except OSError as e:
        print(f"diagnose_layers.py: {e}", file=sys.stderr)
        return 2
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

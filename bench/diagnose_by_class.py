#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The blind self-test's figures by effect class (docs/diagnose_figures.md).

    python3 bench/diagnose_by_class.py DIR/selftest.json...

Reads the selftest.json that `flange diagnose --selftest --reality third|alt` wrote (for example
build/confidence_reliability/third*/selftest.json after bench/confidence_reliability.sh) and prints
two Markdown tables: each kind of pair (singles, two or three classes, null and outside) with the
aims' figures, and each true class: alone, right class first (and first or named alike it); with
others, the pair's first class a true one, and the class itself named.
"""
import json
import sys
from collections import defaultdict


def pairs_of(paths):
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        for pair in data.get("pairs", []):
            yield data.get("seed"), pair


def share(hits, total):
    return f"{hits}/{total} ({100.0 * hits / total:.0f} %)" if total else "-"


def main(paths):
    if not paths:
        sys.exit("diagnose_by_class: give the selftest.json files of a blind self-test")
    kinds = defaultdict(lambda: defaultdict(int))
    alone = defaultdict(lambda: [0, 0, 0])  # pairs, right first, right first or alike
    together = defaultdict(lambda: [0, 0, 0])  # pairs, a true class first, the class named
    seeds = set()
    for seed, pair in pairs_of(paths):
        seeds.add(seed)
        truth = [t["class"] for t in pair.get("truth", [])]
        claimed = {c["class"] for c in pair.get("claims", []) if c.get("right")}
        kind = "control" if not truth or pair["kind"] == "outside" else (
            "single" if len(truth) == 1 else "several")
        k = kinds[kind]
        k["pairs"] += 1
        if kind == "control":
            k["quiet"] += 0 if pair.get("claims") else 1
            continue
        k["first"] += bool(pair.get("top_correct"))
        k["first or alike"] += bool(pair.get("top_among_indistinguishable"))
        k["all named"] += bool(pair.get("all_found"))
        for name in truth:
            if kind == "single":
                row = alone[name]
                row[0] += 1
                row[1] += bool(pair.get("top_correct"))
                row[2] += bool(pair.get("top_among_indistinguishable"))
            else:
                row = together[name]
                row[0] += 1
                row[1] += bool(pair.get("top_correct"))
                row[2] += name in claimed
    print(f"{len(paths)} self-test(s), seeds {', '.join(str(s) for s in sorted(seeds))}\n")
    print("| pairs | right class first | first or named alike it | every class named |"
          " nothing claimed |")
    print("|---|---:|---:|---:|---:|")
    for kind, label in (("single", "one class"), ("several", "two or three classes")):
        k = kinds[kind]
        print(f"| {label} | {share(k['first'], k['pairs'])} |"
              f" {share(k['first or alike'], k['pairs'])} |"
              f" {share(k['all named'], k['pairs']) if kind == 'several' else '-'} | - |")
    c = kinds["control"]
    print(f"| null and outside | - | - | - | {share(c['quiet'], c['pairs'])} |\n")
    print("| class | alone: right first | alone: first or alike | with others: a true class first"
          " | with others: named |")
    print("|---|---:|---:|---:|---:|")
    for name in sorted(set(alone) | set(together)):
        a, t = alone[name], together[name]
        print(f"| {name} | {a[1]}/{a[0]} | {a[2]}/{a[0]} | {t[1]}/{t[0]} | {t[2]}/{t[0]} |")


if __name__ == "__main__":
    main(sys.argv[1:])

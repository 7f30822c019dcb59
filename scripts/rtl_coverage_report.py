#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-file line and toggle coverage of rtl/ from Verilator coverage files (docs/coverage.md).

Reads one or more .dat files (SystemC::Coverage-3, as VerilatedCovContext::write and
`verilator_coverage --write` make them), adds up the counts of equal points, and prints one row per
RTL file:

- line: the source lines that Verilator's line coverage (--coverage-line: the v_line blocks and
  the v_branch if/else/case arms) names in each point's S field; a line is covered when every point
  that names it was reached at least once (as `verilator_coverage --annotate-min 1` marks it).
- toggle: the bits of every signal that --coverage-toggle instruments; a bit is covered when it
  changed at least once.

A point counts once per source location, whatever instance or coefficient set reached it: the core
is the top of the per-set tests and u_core of the board top, and widths differ between sets (a bit
that exists in one set only is one point).

Points no test can reach are waived in tb/rtl_coverage_waivers.txt, each with its reason: the table
gives the coverage without them and, as "raw", with them. The uncovered points that are not waived
follow the table, then the waived ones with their reasons, then any waiver that matched nothing.

  python3 scripts/rtl_coverage_report.py merged.dat [--root DIR] [--waivers FILE]
                                         [--min-line P] [--min-toggle P]

Exit status 1 when a --min-* aim (percent over all files, waivers applied) is missed, a waiver line
cannot be read, or no point was read.
"""

import argparse
import collections
import fnmatch
import os
import re
import sys

LINE_PAGES = ("v_line", "v_branch")
TOGGLE_PAGES = ("v_toggle",)


def parse_dat(paths):
    """Sums the counts of equal keys over `paths`; returns {key fields (tuple of pairs): count}."""
    counts = collections.Counter()
    for path in paths:
        with open(path, encoding="utf-8", errors="surrogateescape") as f:
            for number, text in enumerate(f, 1):
                if not text.startswith("C '"):
                    continue
                m = re.match(r"C '(.*)' (\d+)\s*$", text)
                if not m:
                    raise ValueError(f"{path}:{number}: not a coverage point")
                fields = {}
                for item in m.group(1).split("\x01")[1:]:
                    name, _, value = item.partition("\x02")
                    fields[name] = value
                counts[tuple(sorted(fields.items()))] += int(m.group(2))
    return counts


def line_set(spec, fallback):
    """'117,119-120' -> {117, 119, 120}."""
    lines = set()
    for part in (spec or "").split(","):
        if not part:
            continue
        lo, _, hi = part.partition("-")
        lines.update(range(int(lo), int(hi or lo) + 1))
    return lines or {int(fallback)}


def split_bit(name):
    """'btc_q[3]' -> ('btc_q', 3); 'rom[1][2]' -> ('rom[1]', 2); 'flag' -> ('flag', None)."""
    m = re.match(r"^(.*)\[(\d+)\]$", name)
    return (m.group(1), int(m.group(2))) if m else (name, None)


def split_indices(name):
    """'rom[1][2]' -> ('rom', ['1', '2']); 'flag' -> ('flag', [])."""
    m = re.match(r"^([^\[]*)((?:\[[^\]]*\])*)$", name)
    if not m:
        return name, []
    return m.group(1), re.findall(r"\[([^\]]*)\]", m.group(2))


def index_matches(spec, index):
    """Whether bit or word `index` (a string) is in `spec`: '*', or e.g. '15:5' or '3,1:0'."""
    if spec == "*":
        return True
    if not index.isdigit():
        return False
    for part in spec.split(","):
        hi, _, lo = part.partition(":")
        hi, lo = int(hi), int(lo or hi)
        if min(hi, lo) <= int(index) <= max(hi, lo):
            return True
    return False


class Waiver:
    def __init__(self, kind, path, pattern, reason, where):
        self.kind, self.path, self.pattern = kind, path, pattern
        self.reason, self.where = reason, where
        self.used = 0
        if kind == "toggle":
            self.name, self.indices = split_indices(pattern)

    def matches_toggle(self, path, signal):
        if self.kind != "toggle" or path != self.path:
            return False
        name, indices = split_indices(signal)
        return (fnmatch.fnmatchcase(name, self.name) and len(indices) == len(self.indices) and
                all(index_matches(s, i) for s, i in zip(self.indices, indices)))

    def matches_line(self, path, text):
        return self.kind == "line" and path == self.path and self.pattern in text


def read_waivers(path):
    waivers = []
    if not path:
        return waivers
    with open(path, encoding="utf-8") as f:
        for number, text in enumerate(f, 1):
            text = text.strip()
            if not text or text.startswith("#"):
                continue
            fields = [x.strip() for x in text.split("|", 3)]
            if len(fields) != 4 or fields[0] not in ("toggle", "line") or not all(fields):
                raise ValueError(
                    f"{path}:{number}: expected 'toggle|line | file | pattern | reason'")
            waivers.append(Waiver(*fields, where=f"{os.path.basename(path)}:{number}"))
    return waivers


def bit_ranges(bits):
    """[0, 1, 2, 5] -> '[2:0], [5]' (descending within a range, as in a declaration)."""
    bits = sorted(b for b in bits if b is not None)
    out, start = [], None
    for i, b in enumerate(bits):
        if start is None:
            start = b
        if i + 1 == len(bits) or bits[i + 1] != b + 1:
            out.append(f"[{b}:{start}]" if b != start else f"[{b}]")
            start = None
    return ", ".join(out)


class FileCoverage:
    def __init__(self):
        self.line_points = collections.defaultdict(int)   # (l, n, o, S) -> count
        self.toggle_points = collections.defaultdict(int)  # signal[bit] -> count

    def lines(self):
        """{source line: [(count, what) for every point naming it]}."""
        per_line = collections.defaultdict(list)
        for (l, _n, o, s), count in self.line_points.items():
            for line in line_set(s, l):
                per_line[line].append((count, o))
        return per_line


def collect(counts, root):
    files = collections.defaultdict(FileCoverage)
    for key, count in counts.items():
        f = dict(key)
        page = f.get("page", "").split("/")[0]
        path = f.get("f", "")
        if root and os.path.isabs(path):
            path = os.path.relpath(path, root)
        if page in LINE_PAGES:
            key = (f["l"], f.get("n", ""), f.get("o", ""), f.get("S", ""))
            files[path].line_points[key] += count
        elif page in TOGGLE_PAGES:
            # One module per file, so the signal names the point (the page names Verilator's
            # parameterised copy of the module, iir_core__Rz1 in the board top).
            files[path].toggle_points[f.get("o", "")] += count
    return files


def source_lines(root, path):
    try:
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            return f.read().split("\n")
    except OSError:
        return []


def percent(hit, total):
    return 100.0 * hit / total if total else 100.0


def report(files, waivers, waiver_file, root, out):
    rows, uncovered_lines, uncovered_toggles = [], [], []
    waived = collections.defaultdict(list)  # waiver -> what it waived
    totals = collections.defaultdict(lambda: [0] * 8)
    for path in sorted(files):
        cov = files[path]
        text = source_lines(root, path)
        # Lines: hit, total, then the same without the waived ones.
        per_line = cov.lines()
        lh = sum(1 for pts in per_line.values() if all(c > 0 for c, _ in pts))
        lt = len(per_line)
        nlh, nlt = lh, lt
        for line in sorted(per_line):
            missed = sorted({o for c, o in per_line[line] if c == 0})
            if not missed:
                continue
            source = text[line - 1].strip() if 0 < line <= len(text) else ""
            what = f"{path}:{line} ({', '.join(missed)})"
            waiver = next((w for w in waivers if w.matches_line(path, source)), None)
            if waiver:
                waiver.used += 1
                waived[waiver].append(f"{line}")
                nlt -= 1
            else:
                uncovered_lines.append(f"{what}  {source}")
        # Toggle bits, likewise.
        th = sum(1 for c in cov.toggle_points.values() if c > 0)
        tt = len(cov.toggle_points)
        nth, ntt = th, tt
        by_signal = collections.defaultdict(list)
        for signal, c in cov.toggle_points.items():
            if c > 0:
                continue
            waiver = next((w for w in waivers if w.matches_toggle(path, signal)), None)
            if waiver:
                waiver.used += 1
                waived[waiver].append(signal)
                ntt -= 1
            else:
                by_signal[split_bit(signal)[0]].append(split_bit(signal)[1])
        for signal in sorted(by_signal):
            uncovered_toggles.append(f"{path}: {signal}{bit_ranges(by_signal[signal])}")
        counts = (nlh, nlt, lh, lt, nth, ntt, th, tt)
        rows.append((path,) + counts)
        group = os.path.dirname(path) or "."
        for g in {group, "all"}:
            totals[g] = [a + b for a, b in zip(totals[g], counts)]

    width = max([len(r[0]) for r in rows] + [len("rtl/board (all files)")])
    out.write(f"{'file':<{width}}  {'lines':>9}  {'line %':>6}  {'raw %':>6}  {'toggle bits':>11}  "
              f"{'toggle %':>8}  {'raw %':>6}\n")

    def row(name, nlh, nlt, lh, lt, nth, ntt, th, tt):
        out.write(f"{name:<{width}}  {f'{nlh}/{nlt}':>9}  {percent(nlh, nlt):6.1f}  "
                  f"{percent(lh, lt):6.1f}  {f'{nth}/{ntt}':>11}  {percent(nth, ntt):8.1f}  "
                  f"{percent(th, tt):6.1f}\n")

    for r in rows:
        row(*r)
    for g in sorted(k for k in totals if k != "all"):
        if sum(1 for r in rows if (os.path.dirname(r[0]) or ".") == g) > 1:
            row(f"{g} (all files)", *totals[g])
    row("total", *totals["all"])
    out.write("(line %, toggle %: without the waived points; raw %: with them)\n")

    out.write("\nuncovered lines" + (":\n" if uncovered_lines else ": none\n"))
    for u in uncovered_lines:
        out.write(f"  {u}\n")
    out.write("uncovered toggle bits" + (":\n" if uncovered_toggles else ": none\n"))
    for u in uncovered_toggles:
        out.write(f"  {u}\n")
    if waived:
        out.write(f"waived ({os.path.relpath(waiver_file, root)}):\n")
        for w in waivers:
            if w.used:
                n = len(waived[w])
                unit = ("line" if w.kind == "line" else "bit") + ("s" if n > 1 else "")
                out.write(f"  {w.path}: {w.pattern} ({n} {unit}): {w.reason}\n")
    stale = [w for w in waivers if not w.used]
    if stale:
        out.write("waivers that matched no uncovered point "
                  "(remove them, or the run was partial):\n")
        for w in stale:
            out.write(f"  {w.where}: {w.kind} {w.path} {w.pattern}\n")
    return totals["all"]


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dat", nargs="+", help="coverage files (merged or not)")
    parser.add_argument("--root", default=repo,
                        help="paths are shown relative to this folder, and sources read from it "
                             "(default: the repository)")
    parser.add_argument("--waivers", default=os.path.join(repo, "tb", "rtl_coverage_waivers.txt"),
                        help="waiver file; '' for none (default: tb/rtl_coverage_waivers.txt)")
    parser.add_argument("--min-line", type=float, help="aim for line %% over all files")
    parser.add_argument("--min-toggle", type=float, help="aim for toggle %% over all files")
    args = parser.parse_args()
    try:
        waivers = read_waivers(args.waivers)
        files = collect(parse_dat(args.dat), args.root)
    except (OSError, ValueError) as e:
        print(f"rtl_coverage_report: {e}", file=sys.stderr)
        return 1
    if not files:
        print("rtl_coverage_report: no line or toggle point in " + " ".join(args.dat),
              file=sys.stderr)
        return 1
    nlh, nlt, _, _, nth, ntt, _, _ = report(files, waivers, args.waivers, args.root, sys.stdout)
    status = 0
    if args.min_line is not None and percent(nlh, nlt) < args.min_line:
        print(f"line coverage {percent(nlh, nlt):.1f} % is below the aim of {args.min_line} %",
              file=sys.stderr)
        status = 1
    if args.min_toggle is not None and percent(nth, ntt) < args.min_toggle:
        print(f"toggle coverage {percent(nth, ntt):.1f} % is below the aim of {args.min_toggle} %",
              file=sys.stderr)
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Tests of scripts/diagnose_layers.py: the tree as it is passes; a copy of diagnose/ with an
include planted against the stage order, an include cycle, a source in no stage or a stage
linking the wrong one below fails, naming the file and line."""

import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import diagnose_layers  # noqa: E402


class Layers(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="diagnose_layers_")
        shutil.copytree(os.path.join(ROOT, "diagnose", "data"),
                        os.path.join(self.tmp, "diagnose", "data"))
        shutil.copy(os.path.join(ROOT, "diagnose", "CMakeLists.txt"),
                    os.path.join(self.tmp, "diagnose", "CMakeLists.txt"))

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def path(self, rel):
        return os.path.join(self.tmp, "diagnose", "data", rel)

    def plant(self, rel, line):
        """Adds `line` after the file's first include; returns that line's number."""
        with open(self.path(rel), encoding="utf-8") as f:
            lines = f.read().split("\n")
        at = next(i for i, l in enumerate(lines) if l.startswith("#include")) + 1
        lines.insert(at, line)
        with open(self.path(rel), "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        return at + 1

    def test_the_tree_passes(self):
        self.assertEqual(diagnose_layers.check(ROOT), [])

    def test_an_upward_include_is_named_with_its_line(self):
        line = self.plant("input/protocol.cpp", '#include "verdict.h"')
        problems = diagnose_layers.check(self.tmp)
        self.assertEqual(problems, [
            f"diagnose/data/input/protocol.cpp:{line}: includes verdict.h of stage verdict, "
            "above its own stage input"])

    def test_an_include_of_a_lower_stage_passes(self):
        self.plant("verdict/verdict.cpp", '#include "protocol.h"')
        self.assertEqual(diagnose_layers.check(self.tmp), [])

    def test_a_cycle_within_a_stage_fails(self):
        self.plant("selection/scoring.h", '#include "selection.h"')
        self.plant("selection/selection.h", '#include "scoring.h"')
        problems = diagnose_layers.check(self.tmp)
        self.assertTrue(any("include cycle" in p and "scoring.h" in p for p in problems),
                        problems)

    def test_a_source_in_no_stage_fails(self):
        with open(self.path("noise/stray.cpp"), "w", encoding="utf-8") as f:
            f.write("// not built\n")
        self.assertEqual(diagnose_layers.check(self.tmp),
                         ["diagnose/data/noise/stray.cpp: in no stage's SOURCES"])

    def test_a_stage_linking_past_the_one_below_fails(self):
        cmake = os.path.join(self.tmp, "diagnose", "CMakeLists.txt")
        with open(cmake, encoding="utf-8") as f:
            text = f.read()
        with open(cmake, "w", encoding="utf-8") as f:
            f.write(text.replace('flange_diagnose_stage(verdict "signatures"',
                                 'flange_diagnose_stage(verdict "identify"'))
        problems = diagnose_layers.check(self.tmp)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("stage verdict links 'identify', expected 'signatures'", problems[0])


if __name__ == "__main__":
    unittest.main()

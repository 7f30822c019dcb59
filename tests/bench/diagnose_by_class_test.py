#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""bench/diagnose_by_class.py counts each kind of pair and each class as a self-test wrote them:
a made-up selftest.json with every case the tables count, and the rows they must show."""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(sys.argv[1])


def pair(kind, truth, claims, top, alike, found):
    return {"kind": kind, "truth": [{"class": c} for c in truth],
            "claims": [{"class": c, "right": r, "confidence": 0.5} for c, r in claims],
            "top_correct": top, "top_among_indistinguishable": alike, "all_found": found}


pairs = [
    pair("single", ["ageing"], [("ageing", True)], True, True, True),
    pair("single", ["range_compression"], [("static_nonlinearity", False)], False, True, False),
    pair("single", ["range_compression"], [], False, False, False),
    pair("multiple", ["ageing", "mains_pickup"], [("ageing", True)], True, True, False),
    pair("multiple", ["ageing", "channel_skew"], [("channel_skew", True), ("ageing", True)],
         True, True, True),
    pair("multiple", ["mains_pickup", "channel_skew"], [("ageing", False)], False, False, False),
    pair("null", [], [], False, False, False),
    pair("outside", ["outside"], [("ageing", False)], False, False, False),
]
with tempfile.TemporaryDirectory() as tmp:
    path = Path(tmp) / "selftest.json"
    path.write_text(json.dumps({"seed": 7, "pairs": pairs}))
    out = subprocess.run([sys.executable, str(ROOT / "bench/diagnose_by_class.py"), str(path)],
                         check=True, capture_output=True, text=True).stdout
expected = [
    "| one class | 1/3 (33 %) | 2/3 (67 %) | - | - |",
    "| two or three classes | 2/3 (67 %) | 2/3 (67 %) | 1/3 (33 %) | - |",
    "| null and outside | - | - | - | 1/2 (50 %) |",
    "| ageing | 1/1 | 1/1 | 2/2 | 2/2 |",
    "| channel_skew | 0/0 | 0/0 | 1/2 | 1/2 |",
    "| mains_pickup | 0/0 | 0/0 | 1/2 | 0/2 |",
    "| range_compression | 0/2 | 1/2 | 0/0 | 0/0 |",
]
missing = [row for row in expected if row not in out.splitlines()]
if missing:
    sys.exit("diagnose_by_class_test: rows missing:\n" + "\n".join(missing) + "\n--- got:\n" + out)
empty = subprocess.run([sys.executable, str(ROOT / "bench/diagnose_by_class.py")],
                       capture_output=True, text=True)
if empty.returncode == 0:
    sys.exit("diagnose_by_class_test: no files given, yet exit status 0")
print("diagnose_by_class_test: passed")

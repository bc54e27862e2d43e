#!/usr/bin/env python3
"""Tests of check_layering.py: small temporary trees with their own layer table, and one
copy of the real repository with a bad include planted in it.

    python3 -m unittest discover -s tests/layering -v      (or run this file)
"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "check_layering.py")
REPO = os.path.dirname(os.path.dirname(HERE))

# low (0) < mid (1) < left = right (2, siblings) < app (3); 'fuzz' has no folder.
TABLE = {
    "layers": [
        {"name": "low", "rank": 0, "root": "src/semslam/low", "owns": "bottom"},
        {"name": "mid", "rank": 1, "root": "src/semslam/mid", "owns": "middle"},
        {"name": "left", "rank": 2, "root": "src/semslam/left", "owns": "one sibling"},
        {"name": "right", "rank": 2, "root": "src/semslam/right", "owns": "the other sibling"},
        {"name": "app", "rank": 3, "root": "apps", "owns": "the tool"},
        {"name": "fuzz", "rank": 3, "root": "fuzz", "owns": "missing folder"},
    ],
    "every_file_layered_under": ["src/semslam"],
    "allowed": [],
    "forbidden": [{"from": "right", "to": ["low"], "why": "test rule"}],
}

# A clean tree: every include runs down or stays in its layer.
CLEAN = {
    "src/semslam/low/Low.h": "#pragma once\n#include <vector>\n",
    "src/semslam/low/Low.cpp": '#include "semslam/low/Low.h"\n',
    "src/semslam/mid/Mid.h": '#pragma once\n#include "semslam/low/Low.h"\n',
    "src/semslam/left/Left.h": '#pragma once\n#include "semslam/mid/Mid.h"\n#include "Detail.h"\n',
    "src/semslam/left/Detail.h": "#pragma once\n",
    "src/semslam/right/Right.h": '#pragma once\n#include "semslam/mid/Mid.h"\n',
    "apps/tool/Commands.h": '#pragma once\n#include "semslam/left/Left.h"\n',
    "apps/tool/main.cpp": '#include "Commands.h"\n#include "semslam/right/Right.h"\n',
    "apps/tool/sub/Extra.cpp": '#include "tool/Commands.h"\n#include "third_party/lib.h"\n',
}


def run_checker(root, *extra):
    completed = subprocess.run([sys.executable, SCRIPT, "--root", root, *extra],
                               capture_output=True, text=True, timeout=300)
    return completed.returncode, completed.stdout, completed.stderr


class TreeCase(unittest.TestCase):
    """A temporary repository built from CLEAN, edited per test."""

    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="layering-test-")
        self.addCleanup(shutil.rmtree, self.root)
        self.table = json.loads(json.dumps(TABLE))
        self.files = dict(CLEAN)

    def write(self):
        for path, text in self.files.items():
            full = os.path.join(self.root, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as stream:
                stream.write(text)
        os.makedirs(os.path.join(self.root, "docs"), exist_ok=True)
        with open(os.path.join(self.root, "docs", "layers.json"), "w", encoding="utf-8") as stream:
            json.dump(self.table, stream)

    def check(self):
        self.write()
        return run_checker(self.root)

    def assertReports(self, location, pattern):
        """The checker exits 1 and prints 'location: ...pattern...' on a line of its own."""
        code, out, err = self.check()
        self.assertEqual(code, 1, out + err)
        regex = re.compile("^" + re.escape(location) + ": .*" + pattern, re.MULTILINE)
        self.assertRegex(out, regex)
        self.assertRegex(out, r"layering: \d+ files, \d+ includes checked, [1-9]\d* problems\n$")
        return out


class CleanTree(TreeCase):
    def test_clean_tree_passes(self):
        code, out, err = self.check()
        self.assertEqual(code, 0, out + err)
        self.assertEqual(out, "layering: 9 files, 10 includes checked, 0 problems\n")

    def test_allowed_sibling_pair_passes(self):
        self.table["allowed"] = [{"from": "left", "to": "right"}]
        self.files["src/semslam/left/Left.h"] += '#include "semslam/right/Right.h"\n'
        code, out, err = self.check()
        self.assertEqual(code, 0, out + err)

    def test_include_in_block_comment_is_ignored(self):
        self.files["src/semslam/low/Low.h"] += '/* old:\n#include "semslam/app/Nope.h"\n*/\n'
        code, out, err = self.check()
        self.assertEqual(code, 0, out + err)

    def test_include_through_layer_root_resolves(self):
        # apps/tool/sub/Extra.h includes "tool/Commands.h": neither src/ nor its own folder holds it,
        # the layer root apps/ does. The circle shows it was resolved and not taken for third-party.
        self.files["apps/tool/sub/Extra.h"] = '#pragma once\n#include "tool/Commands.h"\n'
        self.files["apps/tool/Commands.h"] += '#include "sub/Extra.h"\n'
        self.assertReports("apps/tool/Commands.h:3",
                           "include circle: apps/tool/Commands.h -> apps/tool/sub/Extra.h -> apps/tool/Commands.h")


class Violations(TreeCase):
    def test_upward_include(self):
        self.files["src/semslam/mid/Mid.h"] += '#include "semslam/left/Left.h"\n'
        self.assertReports("src/semslam/mid/Mid.h:3",
                           r'upward include "semslam/left/Left.h": mid \(rank 1\) includes left \(rank 2\)')

    def test_sibling_include(self):
        self.files["src/semslam/left/Left.h"] += '#include "semslam/right/Right.h"\n'
        self.assertReports("src/semslam/left/Left.h:4", r"sibling include .*left .* right")

    def test_allowed_is_one_direction(self):
        self.table["allowed"] = [{"from": "left", "to": "right"}]
        self.files["src/semslam/right/Right.h"] += '#include "semslam/left/Left.h"\n'
        self.assertReports("src/semslam/right/Right.h:3", "sibling include")

    def test_forbidden_include(self):
        # Down the ranks (2 -> 0), so only the forbidden rule catches it.
        self.files["src/semslam/right/Right.cpp"] = '#include "semslam/right/Right.h"\n\n#include "semslam/low/Low.h"\n'
        out = self.assertReports("src/semslam/right/Right.cpp:3",
                                 r"forbidden include .*right may not include low \(test rule\)")
        self.assertNotIn("upward", out)
        self.assertIn(", 1 problems", out)

    def test_circle_of_two_headers(self):
        self.files["src/semslam/mid/A.h"] = '#pragma once\n#include "B.h"\n'
        self.files["src/semslam/mid/B.h"] = '#pragma once\n#include "semslam/low/Low.h"\n#include "A.h"\n'
        self.assertReports("src/semslam/mid/A.h:2",
                           "include circle: src/semslam/mid/A.h -> src/semslam/mid/B.h -> src/semslam/mid/A.h")

    def test_file_including_itself(self):
        self.files["src/semslam/low/Low.h"] += '#include "Low.h"\n'
        self.assertReports("src/semslam/low/Low.h:3",
                           "include circle: src/semslam/low/Low.h -> src/semslam/low/Low.h")

    def test_layer_circle(self):
        # Both directions allowed and no file circle: only the layer circle is left to report.
        self.table["allowed"] = [{"from": "left", "to": "right"}, {"from": "right", "to": "left"}]
        self.files["src/semslam/left/Left.h"] += '#include "semslam/right/Right.h"\n'
        self.files["src/semslam/right/Other.h"] = '#include "semslam/left/Detail.h"\n'
        out = self.assertReports("src/semslam/left/Left.h:4", "layer circle: left -> right -> left")
        self.assertIn("right -> left at src/semslam/right/Other.h:1", out)
        self.assertNotIn("include circle", out)

    def test_unknown_semslam_include(self):
        self.files["src/semslam/mid/Mid.cpp"] = '#include "semslam/mid/Mid.h"\n#include "semslam/mid/Gone.h"\n'
        self.assertReports("src/semslam/mid/Mid.cpp:2", '"semslam/mid/Gone.h" names no file')

    def test_file_in_no_layer(self):
        self.files["src/semslam/stray/Stray.h"] = "#pragma once\n"
        self.files["src/semslam/Top.cpp"] = '#include "semslam/low/Low.h"\n'
        out = self.assertReports("src/semslam/stray/Stray.h:1", "belongs to no layer")
        self.assertRegex(out, r"(?m)^src/semslam/Top.cpp:1: file belongs to no layer")

    def test_include_landing_in_no_layer(self):
        self.files["src/semslam/stray/Stray.h"] = "#pragma once\n"
        self.files["src/semslam/low/Low.cpp"] += '#include "semslam/stray/Stray.h"\n'
        self.assertReports("src/semslam/low/Low.cpp:2", "lands in no layer")


class BadTable(TreeCase):
    def assertBadTable(self, message):
        code, out, err = self.check()
        self.assertEqual(code, 2, out + err)
        self.assertIn("bad layer table", err)
        self.assertIn(message, err)

    def test_unknown_layer_in_forbidden(self):
        self.table["forbidden"].append({"from": "left", "to": "nowhere"})
        self.assertBadTable("unknown layer 'nowhere'")

    def test_missing_rank(self):
        del self.table["layers"][1]["rank"]
        self.assertBadTable("'mid'")

    def test_duplicate_name(self):
        self.table["layers"][1]["name"] = "low"
        self.assertBadTable("used twice")

    def test_allowed_pair_not_siblings(self):
        self.table["allowed"] = [{"from": "mid", "to": "left"}]
        self.assertBadTable("not a pair of sibling layers")

    def test_invalid_json(self):
        self.write()
        with open(os.path.join(self.root, "docs", "layers.json"), "w", encoding="utf-8") as stream:
            stream.write("{ not json")
        code, out, err = run_checker(self.root)
        self.assertEqual(code, 2, out + err)
        self.assertIn("not valid JSON", err)

    def test_missing_table(self):
        self.write()
        code, out, err = run_checker(self.root, "--table", os.path.join(self.root, "nope.json"))
        self.assertEqual(code, 2, out + err)
        self.assertIn("cannot read", err)


class RealRepository(unittest.TestCase):
    """The repository's own src/, apps/ and layer table, with one bad include planted."""

    def test_planted_include_is_reported(self):
        for needed in ("src/semslam/slam", "src/semslam/eval/RunEvaluation.h", "docs/layers.json"):
            if not os.path.exists(os.path.join(REPO, needed)):
                self.skipTest(f"{needed} is not in this checkout")
        root = tempfile.mkdtemp(prefix="layering-real-")
        self.addCleanup(shutil.rmtree, root)
        for folder in ("src", "apps"):
            if os.path.isdir(os.path.join(REPO, folder)):
                shutil.copytree(os.path.join(REPO, folder), os.path.join(root, folder))
        os.makedirs(os.path.join(root, "docs"))
        shutil.copy(os.path.join(REPO, "docs", "layers.json"), os.path.join(root, "docs"))

        victim = "src/semslam/slam/" + sorted(
            name for name in os.listdir(os.path.join(root, "src/semslam/slam")) if name.endswith(".h"))[0]
        with open(os.path.join(root, victim), encoding="utf-8") as stream:
            text = stream.read()
        if text and not text.endswith("\n"):
            text += "\n"
        line = text.count("\n") + 1
        with open(os.path.join(root, victim), "w", encoding="utf-8") as stream:
            stream.write(text + '#include "semslam/eval/RunEvaluation.h"\n')

        code, out, err = run_checker(root)
        self.assertEqual(code, 1, out + err)
        location = re.escape(f"{victim}:{line}: ")
        self.assertRegex(out, re.compile("^" + location + "upward include .*slam .* eval", re.MULTILINE))
        self.assertRegex(out, re.compile("^" + location + "forbidden include .*slam may not include eval",
                                         re.MULTILINE))


if __name__ == "__main__":
    unittest.main()

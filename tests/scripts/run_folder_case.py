"""A unittest.TestCase with hand-made run folders (metrics.json, and branches.csv where given) in a scratch
directory, for the tests of the results sections that read them.
"""
import json
import os
import tempfile
import unittest

BRANCHES_HEADER = "opened_at,closed_after,score_as_is,score_apart,score_next_best,kept\n"


class RunFolderCase(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.scratch.cleanup()

    def folder(self, name, metrics, branches=None):
        """A run folder `name` whose metrics.json holds `metrics` (time_s 1 unless given) and, where `branches` is
        given, a branches.csv of those rows."""
        path = os.path.join(self.scratch.name, name)
        os.makedirs(path)
        with open(os.path.join(path, "metrics.json"), "w") as f:
            json.dump(dict({"time_s": 1.0}, **metrics), f)
        if branches is not None:
            with open(os.path.join(path, "branches.csv"), "w") as f:
                f.write(BRANCHES_HEADER + "".join(row + "\n" for row in branches))
        return path

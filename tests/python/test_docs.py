"""docs/python.md's example runs as written, from the repository root (as the page says)."""

import os
import re
import subprocess
import sys

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def test_the_example_of_docs_python_md_runs_as_written(cli, tmp_path):
    with open(os.path.join(REPOSITORY, "docs", "python.md"), encoding="utf-8") as stream:
        blocks = re.findall(r"```python\n(.*?)```", stream.read(), flags=re.S)
    assert blocks, "docs/python.md has no python block"
    # The page runs the tool as build/bin/semslam from the repository root; the test's tool may be elsewhere.
    (tmp_path / "build" / "bin").mkdir(parents=True)
    os.symlink(os.environ["SEMSLAM_CLI"], tmp_path / "build" / "bin" / "semslam")
    for block in blocks:
        environment = dict(os.environ)
        environment["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in
                                                    environment.get("PYTHONPATH", "").split(os.pathsep) if p)
        completed = subprocess.run([sys.executable, "-c", block], cwd=tmp_path, capture_output=True, text=True,
                                   env=environment, timeout=300)
        assert completed.returncode == 0, completed.stderr
        assert "refused: /nonexistent.jsonl: file does not exist" in completed.stdout

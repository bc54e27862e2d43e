"""What every docs/results.md section module (make_results.py) needs to run the tool: a command that must
succeed, and a run folder's metrics."""
import json
import os
import subprocess
import sys


def run_checked(command):
    """Runs a command of a results section and returns its standard output; exits with its output when it
    fails (a results section is written completely or not at all)."""
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"make_results.py: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def read_metrics(folder):
    """The metrics.json of a `semslam run` folder."""
    with open(os.path.join(folder, "metrics.json")) as f:
        return json.load(f)

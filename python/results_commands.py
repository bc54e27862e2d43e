"""What every docs/results.md section module (make_results.py) needs to run the tool: a command that must
succeed, a run folder's metrics, and table cells."""
import json
import math
import os
import statistics
import subprocess
import sys


def run_checked(command):
    """Runs a command of a results section and returns its standard output; exits with its output when it
    fails (a results section is written completely or not at all)."""
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"make_results.py: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def cell(value, digits=3):
    """A table cell: a float to `digits` places, `–` for a missing (None) or NaN figure, anything else as text."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "–"
    return f"{value:.{digits}f}" if isinstance(value, float) else str(value)


def mean_cell(values, digits=3):
    """The mean of a table cell's numbers, `–` when none is a number, with the count in brackets when some are
    missing (a metric undefined on some logs)."""
    present = [v for v in values if isinstance(v, (int, float))]
    if not present:
        return "–"
    cell = f"{statistics.fmean(present):.{digits}f}"
    return cell if len(present) == len(values) else f"{cell} ({len(present)})"


def read_metrics(folder):
    """The metrics.json of a `semslam run` folder."""
    with open(os.path.join(folder, "metrics.json")) as f:
        return json.load(f)


def peak_memory_run(command):
    """Runs `command` as the only child of a fresh interpreter and returns (its stderr, its peak resident set in
    MiB, its wall seconds): the peak of that interpreter's children is the command's own."""
    probe = ("import resource, subprocess, sys, time\n"
             "start = time.monotonic()\n"
             "done = subprocess.run(sys.argv[1:], capture_output=True, text=True)\n"
             "wall = time.monotonic() - start\n"
             "sys.stdout.write(done.stderr)\n"
             "print('PEAK', resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, wall, done.returncode)\n")
    output = run_checked([sys.executable, "-c", probe] + command)
    stderr, _, last = output.rstrip("\n").rpartition("\n")
    _, peak_kib, wall, code = last.split()
    if code != "0":
        sys.exit(f"make_results.py: {' '.join(command)} failed:\n{stderr}")
    return stderr, int(peak_kib) / 1024.0, float(wall)

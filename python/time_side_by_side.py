#!/usr/bin/env python3
"""Time two commands side by side: the ratio of their costs, measured so that a drifting machine does not move it.

    python/time_side_by_side.py [-n RUNS] [--warmup K] --vs 'BASELINE COMMAND' -- COMMAND [ARG ...]

COMMAND (the candidate) and BASELINE run in turn, candidate first, RUNS times each, after K warm-up pairs that are
not counted. Each run is timed from outside, as a whole process (start-up and set-up included):

- wall seconds: a monotonic clock read just before the start and just after the child is reaped;
- CPU seconds: the operating system's user + system accounting of the finished child and of everything it waited for
  (`os.wait4`'s resource usage).

The figure to quote is the MEDIAN OF THE PAIRED RATIOS candidate / baseline (wall and CPU), taken pair by pair, so
that a machine whose speed drifts during the call (another job starting, a thermal change) moves both members of a
pair alike. The minimum and maximum of the ratios are printed beside it: a wide range says the machine was noisy.
The medians of each command's own times are printed too, but compare absolute times only within one call.

Both commands are split into words as a shell would (`shlex`), run without a shell, with empty standard input and
their output discarded. A command that needs a pipe or a redirection is written `sh -c '...'`. A run that exits
non-zero stops the call with exit status 1 and the command's exit code, since a failing run's time means nothing.

This is how docs/ measures the cost of a change ("median of the paired ratios"): docs/benchmarks.md explains why
speed is never asserted by a timed test.
"""

import argparse
import os
import shlex
import statistics
import subprocess
import sys
import time


def time_one_run(command):
    """Runs `command` once; returns (wall seconds, CPU seconds). Exits the script if the command fails."""
    start = time.monotonic()
    try:
        child = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL)
    except OSError as error:
        sys.exit(f"time_side_by_side: cannot start {command[0]!r}: {error.strerror}")
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        print(f"time_side_by_side: {shlex.join(command)} exited with {child.returncode}; no figure is printed",
              file=sys.stderr)
        sys.exit(1)
    return wall, usage.ru_utime + usage.ru_stime


def spread(values):
    """'median (min-max)' of a list of positive numbers."""
    return f"{statistics.median(values):.4g} (range {min(values):.4g}-{max(values):.4g})"


def main():
    parser = argparse.ArgumentParser(
        description="Time COMMAND against a baseline, alternated run by run; print the median of the paired "
                    "ratios COMMAND / BASELINE of wall and CPU time.")
    parser.add_argument("-n", "--runs", type=int, default=5, help="timed runs of each command (default 5)")
    parser.add_argument("--warmup", type=int, default=1, help="untimed pairs run first (default 1)")
    parser.add_argument("--vs", required=True, metavar="BASELINE",
                        help="the baseline command, one string split as a shell splits words")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- COMMAND [ARG ...]: the candidate")
    arguments = parser.parse_args()

    candidate = arguments.command[1:] if arguments.command[:1] == ["--"] else arguments.command
    baseline = shlex.split(arguments.vs)
    if not candidate or not baseline:
        parser.error("both a candidate (after --) and a baseline (--vs) command are needed")
    if arguments.runs < 1 or arguments.warmup < 0:
        parser.error("--runs must be at least 1 and --warmup at least 0")

    for _ in range(arguments.warmup):
        time_one_run(candidate)
        time_one_run(baseline)
    candidate_times, baseline_times = [], []
    for _ in range(arguments.runs):
        candidate_times.append(time_one_run(candidate))
        baseline_times.append(time_one_run(baseline))

    wall_ratios = [c[0] / b[0] for c, b in zip(candidate_times, baseline_times)]
    cpu_ratios = [c[1] / b[1] for c, b in zip(candidate_times, baseline_times) if b[1] > 0]
    print(f"candidate: {shlex.join(candidate)}")
    print(f"baseline:  {shlex.join(baseline)}")
    print(f"runs: {arguments.runs} pairs after {arguments.warmup} warm-up pair(s)")
    print(f"candidate wall s: {spread([t[0] for t in candidate_times])}   "
          f"CPU s: {spread([t[1] for t in candidate_times])}")
    print(f"baseline  wall s: {spread([t[0] for t in baseline_times])}   "
          f"CPU s: {spread([t[1] for t in baseline_times])}")
    print(f"ratio candidate/baseline, wall: {spread(wall_ratios)}")
    if cpu_ratios:
        print(f"ratio candidate/baseline, CPU:  {spread(cpu_ratios)}")
    else:
        print("ratio candidate/baseline, CPU:  not defined (the baseline used no measurable CPU time)")


if __name__ == "__main__":
    main()

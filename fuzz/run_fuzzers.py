#!/usr/bin/env python3
"""Runs every libFuzzer harness (fuzz_<harness> in --bin) for --seconds each (or until --runs executions, whichever
comes first) and prints, per harness, the executions, executions per second, corpus size and findings; exits 1 when
any harness has a finding.

Each harness starts from a copy of fuzz/corpus/<harness>/ and fuzz/findings/<harness>/ (the source tree is never
written) under --work; its findings (crash-*, leak-*, timeout-*, oom-* files; slow units are reported only past the
20 s limit, where they are timeouts) go to
--work/<harness>/findings/: copy each into fuzz/findings/<harness>/ once fixed, where `make test` replays it. Limits
per input: 20 s, 4096 MB. --parallel N runs N harnesses side by side (one process each); the rows are printed in
harness order whatever the order they finish in. The scratch input a harness writes per execution goes to a private
folder under --scratch (a tmpfs such as /dev/shm where there is one: the harnesses read files, and a file on tmpfs
costs no disk write), removed when the harness ends."""

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def default_scratch():
    shm = "/dev/shm"
    return shm if os.path.isdir(shm) and os.access(shm, os.W_OK) else None


def run_harness(harness, arguments):
    """Runs one harness from a fresh copy of its corpus; returns (row, failure text or None)."""
    work = os.path.join(arguments.work, harness)
    corpus, findings = os.path.join(work, "corpus"), os.path.join(work, "findings")
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "corpus", harness), corpus)
    old_findings = os.path.join(HERE, "findings", harness)
    if os.path.isdir(old_findings):
        shutil.copytree(old_findings, corpus, dirs_exist_ok=True)
    os.makedirs(findings)
    # -report_slow_units at the per-input time limit: an input under 20 s is within the contract, not a finding.
    command = [os.path.join(arguments.bin, f"fuzz_{harness}"), f"-max_total_time={arguments.seconds}",
               "-timeout=20", "-report_slow_units=20", "-rss_limit_mb=4096", "-print_final_stats=1",
               f"-artifact_prefix={findings}{os.sep}", corpus]
    if arguments.runs > 0:
        command.insert(1, f"-runs={arguments.runs}")
    # A private scratch folder per harness, removed afterwards (a crash leaves its input file and unpacked folder).
    scratch = tempfile.mkdtemp(prefix=f"semslam-fuzz-{harness}-", dir=arguments.scratch)
    environment = dict(os.environ, TMPDIR=scratch)
    started = time.monotonic()
    try:
        result = subprocess.run(command, capture_output=True, text=True, env=environment)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    elapsed = time.monotonic() - started
    # libFuzzer's final statistics: "stat::number_of_executed_units: N" (-print_final_stats=1); "Done N runs in S
    # second(s)" when it stops at -max_total_time or -runs.
    executed = re.search(r"stat::number_of_executed_units:\s*(\d+)", result.stderr)
    done = re.search(r"Done (\d+) runs in (\d+) second", result.stderr)
    executions = int(executed.group(1)) if executed else (int(done.group(1)) if done else 0)
    seconds = max(1.0, elapsed)
    new = sorted(os.listdir(findings))
    failed = result.returncode != 0 and not new
    row = (harness, executions, int(executions / seconds), int(round(elapsed)), len(os.listdir(corpus)),
           len(new) + (1 if failed else 0))
    failure = f"{harness}: exit {result.returncode}\n{result.stderr[-3000:]}" if result.returncode != 0 else None
    return row, failure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--seconds", type=int, default=60, help="time limit per harness")
    parser.add_argument("--runs", type=int, default=0, help="stop a harness after this many executions (0: no limit)")
    parser.add_argument("--work", required=True)
    parser.add_argument("--only", default="", help="comma-separated harnesses to run (default: every one)")
    parser.add_argument("--parallel", type=int, default=1, help="harnesses run side by side")
    parser.add_argument("--scratch", default=default_scratch(),
                        help="folder for each execution's input file (default: /dev/shm where writable)")
    arguments = parser.parse_args()
    harnesses = sorted(os.listdir(os.path.join(HERE, "corpus")))
    if arguments.only:
        wanted = arguments.only.split(",")
        unknown = sorted(set(wanted) - set(harnesses))
        if unknown:
            parser.error(f"no harness named {', '.join(unknown)} (fuzz/corpus/ has {', '.join(harnesses)})")
        harnesses = [h for h in harnesses if h in wanted]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, arguments.parallel)) as pool:
        results = list(pool.map(lambda h: run_harness(h, arguments), harnesses))
    found = 0
    print(f"{'harness':22} {'executions':>12} {'exec/s':>8} {'seconds':>8} {'corpus':>7} {'findings':>9}")
    for (harness, executions, rate, seconds, corpus_size, findings_count), failure in results:
        print(f"{harness:22} {executions:12d} {rate:8d} {seconds:8d} {corpus_size:7d} {findings_count:9d}")
        found += findings_count
        if failure:
            print(failure, file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

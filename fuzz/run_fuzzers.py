#!/usr/bin/env python3
"""Runs every libFuzzer harness (fuzz_<harness> in --bin) for --seconds each and prints, per harness, the
executions, executions per second, corpus size and findings; exits 1 when any harness has a finding.

Each harness starts from a copy of fuzz/corpus/<harness>/ and fuzz/findings/<harness>/ (the source tree is never
written) under --work; its findings (crash-*, leak-*, timeout-*, oom-* files) go to --work/<harness>/findings/: copy
each into fuzz/findings/<harness>/ once fixed, where `make test` replays it. Limits per input: 20 s, 4096 MB."""

import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--seconds", type=int, default=60)
    parser.add_argument("--work", required=True)
    parser.add_argument("--only", default="", help="comma-separated harnesses to run (default: every one)")
    arguments = parser.parse_args()
    harnesses = sorted(os.listdir(os.path.join(HERE, "corpus")))
    if arguments.only:
        harnesses = [h for h in harnesses if h in arguments.only.split(",")]
    rows, found = [], 0
    for harness in harnesses:
        work = os.path.join(arguments.work, harness)
        corpus, findings = os.path.join(work, "corpus"), os.path.join(work, "findings")
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(os.path.join(HERE, "corpus", harness), corpus)
        old_findings = os.path.join(HERE, "findings", harness)
        if os.path.isdir(old_findings):
            shutil.copytree(old_findings, corpus, dirs_exist_ok=True)
        os.makedirs(findings)
        command = [os.path.join(arguments.bin, f"fuzz_{harness}"), f"-max_total_time={arguments.seconds}",
                   "-timeout=20", "-rss_limit_mb=4096", "-print_final_stats=1",
                   f"-artifact_prefix={findings}{os.sep}", corpus]
        result = subprocess.run(command, capture_output=True, text=True)
        done = re.search(r"Done (\d+) runs in (\d+) second", result.stderr)
        executions = int(done.group(1)) if done else 0
        seconds = max(1, int(done.group(2))) if done else arguments.seconds
        new = sorted(os.listdir(findings))
        found += len(new) + (0 if result.returncode == 0 or new else 1)
        rows.append((harness, executions, executions // seconds, len(os.listdir(corpus)), len(new)))
        if result.returncode != 0:
            print(f"{harness}: exit {result.returncode}\n{result.stderr[-3000:]}", file=sys.stderr)
    print(f"{'harness':22} {'executions':>12} {'exec/s':>8} {'corpus':>7} {'findings':>9}")
    for harness, executions, rate, corpus_size, findings_count in rows:
        print(f"{harness:22} {executions:12d} {rate:8d} {corpus_size:7d} {findings_count:9d}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Runs every shell command block of README.md verbatim, so the README cannot rot.

The blocks (```sh fences) are run in order, one command at a time (a line, with its backslash continuations), by
bash in a scratch folder laid out like a checkout:

    SCRATCH/shared         -> the shared datasets' folder (the parent of SEMSLAM_SHARED_DATA)
    SCRATCH/repo           the working directory of every command: README.md and python/ copied, build/bin linked
                           to the build's bin/ (also first on PATH, as `semslam` is for an installed user)

so `../shared/data/...` resolves as it does from a real checkout. A command is changed in one way only: the flags
of APPENDED_FLAGS below are appended to it (to keep long commands short; a flag the command already has makes it
fail, which is wanted: the table must stay an addition). A command is not run when it is listed in NOT_RUN (with
the reason), when a ../shared/data path it names is absent (it is skipped with a message, as every data test
does), or when it names a file or folder that a skipped command would have made. Every other command must exit 0
and print something at least every MAX_SILENCE_S seconds (progress lines count).

Usage: run_readme_commands.py --readme README.md --bin BUILD/bin --shared-data ../shared/data --source REPO_ROOT
"""

import argparse
import os
import re
import selectors
import shutil
import subprocess
import sys
import tempfile
import time

# Flags appended to a command whose text (continuation lines joined by one space) starts with the key.
APPENDED_FLAGS = {
    # The first 300 poses (of 908 at stride 5) of KITTI 00: the same kind of log, made in a third of the time.
    "semslam simulate semantic --dimension 3 --trajectory ../shared/data/kitti-odometry-poses/00.txt": "--steps 300",
}

# Commands the test does not run: the prefix and why.
NOT_RUN = {
    "make demo": "builds; `make demo` is what the README's commands start after",
    "make test": "runs this test",
    "make install": "installs outside the scratch folder; tests/packaging/install_and_consume.sh covers it",
}

# The longest a command may stay silent (seconds): progress lines must come at least this often.
MAX_SILENCE_S = 30.0


def shell_blocks(readme_text):
    """The ```sh blocks of the README, in order, each as its list of commands (continuations joined)."""
    blocks = re.findall(r"^```sh\n(.*?)^```", readme_text, flags=re.M | re.S)
    result = []
    for block in blocks:
        commands, current = [], ""
        for line in block.splitlines():
            if not current and (not line.strip() or line.lstrip().startswith("#")):
                continue
            if line.rstrip().endswith("\\"):
                current += line.rstrip()[:-1].rstrip() + " "
                continue
            current += line.strip() if current else line.rstrip()
            commands.append(current)
            current = ""
        if current:
            commands.append(current)
        result.append(commands)
    return result


def split_comment(command):
    """(code, comment): the command without a trailing `# ...` comment outside quotes, and that comment."""
    quote = None
    for i, c in enumerate(command):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or command[i - 1].isspace()):
            return command[:i].rstrip(), command[i:]
    return command.rstrip(), ""


def run_one(code, cwd, env):
    """Runs `code` with bash; returns (exit code, output, seconds, longest silence in seconds)."""
    start = time.monotonic()
    process = subprocess.Popen(["bash", "-o", "pipefail", "-c", code], cwd=cwd, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    selector = selectors.DefaultSelector()
    selector.register(process.stdout, selectors.EVENT_READ)
    output, last, silence = [], start, 0.0
    while True:
        ready = selector.select(timeout=1.0)
        now = time.monotonic()
        if ready:
            chunk = os.read(process.stdout.fileno(), 65536)
            if not chunk:
                break
            output.append(chunk.decode(errors="replace"))
            last = now
        silence = max(silence, now - last)
    process.wait()
    end = time.monotonic()
    silence = max(silence, end - last)
    return process.returncode, "".join(output), end - start, silence


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--readme", required=True)
    parser.add_argument("--bin", required=True, help="the build's bin folder (semslam, the examples)")
    parser.add_argument("--shared-data", required=True, help="the shared datasets (../shared/data of a checkout)")
    parser.add_argument("--source", required=True, help="the repository root (python/ is copied from it)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder and print where it is")
    arguments = parser.parse_args()

    with open(arguments.readme, encoding="utf-8") as f:
        blocks = shell_blocks(f.read())
    if not blocks:
        print("README.md has no ```sh block")
        return 1

    scratch = tempfile.mkdtemp(prefix="semslam-readme-")
    repo = os.path.join(scratch, "repo")
    os.makedirs(os.path.join(repo, "build"))
    shutil.copy(arguments.readme, os.path.join(repo, "README.md"))
    shutil.copytree(os.path.join(arguments.source, "python"), os.path.join(repo, "python"),
                    ignore=shutil.ignore_patterns("__pycache__"))
    os.symlink(os.path.abspath(arguments.bin), os.path.join(repo, "build", "bin"))
    shared_data = os.path.abspath(arguments.shared_data)
    os.symlink(os.path.dirname(shared_data), os.path.join(scratch, "shared"))

    env = dict(os.environ)
    env["PATH"] = os.path.join(repo, "build", "bin") + os.pathsep + env.get("PATH", "")
    env["MPLBACKEND"] = "Agg"
    env["PYTHONDONTWRITEBYTECODE"] = "1"

    failures, ran, skipped, unmade = [], 0, 0, set()
    total_start = time.monotonic()
    for number, commands in enumerate(blocks, start=1):
        for command in commands:
            code, _ = split_comment(command)
            if not code:
                continue
            reason = next((why for prefix, why in NOT_RUN.items() if code.startswith(prefix)), None)
            missing = [p for p in re.findall(r"\.\./shared/data/[^\s'\"]*", code)
                       if not os.path.exists(os.path.join(repo, p))]
            if missing:
                reason = f"data absent: {', '.join(missing)}"
            words = set(re.split(r"[\s=]+", code))
            needs = sorted(w for w in words if w.rstrip("/") in unmade)
            if reason is None and needs:
                reason = f"needs {', '.join(needs)}, made by a skipped command"
            if reason is not None:
                print(f"[block {number}] SKIP {code}\n    ({reason})")
                skipped += 1
                if not code.startswith("make "):
                    for flag in ("--out", "--report", "--step-times"):
                        for made in re.findall(re.escape(flag) + r"[\s=]+(\S+)", code):
                            unmade.add(made.rstrip("/"))
                continue
            extra = next((flags for prefix, flags in APPENDED_FLAGS.items() if code.startswith(prefix)), "")
            to_run = f"{code} {extra}" if extra else code
            status, output, seconds, silence = run_one(to_run, repo, env)
            ran += 1
            print(f"[block {number}] {to_run}\n    exit {status}, {seconds:.1f} s, longest silence {silence:.1f} s")
            if status != 0:
                failures.append(f"{to_run}: exit {status}\n{output[-4000:]}")
            elif silence > MAX_SILENCE_S:
                failures.append(f"{to_run}: silent for {silence:.0f} s (> {MAX_SILENCE_S:.0f} s without output)")
    print(f"{ran} commands run, {skipped} skipped, {len(failures)} failed, {time.monotonic() - total_start:.1f} s")
    if arguments.keep:
        print(f"scratch folder kept: {scratch}")
    else:
        shutil.rmtree(scratch, ignore_errors=True)
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

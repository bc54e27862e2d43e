"""python/plot_methods.py draws from run folders and, through the module, straight from a log."""

import os
import subprocess
import sys

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(REPOSITORY, "python", "plot_methods.py")


def plot(*arguments):
    return subprocess.run([sys.executable, "-B", SCRIPT, *map(str, arguments)], capture_output=True, text=True,
                          timeout=300)


def test_plot_methods_from_a_log_and_from_run_folders(cli, tmp_path):
    cli("simulate", "semantic", "--out", tmp_path / "log.jsonl", "--seed", 5, "--steps", 30, "--classes", 2)
    completed = plot("--log", tmp_path / "log.jsonl", "--methods", "known,mm-nh", "--option", "no_covariances=True",
                     "--option", "birth=threshold", "--out", tmp_path / "from_log.png")
    assert completed.returncode == 0, completed.stderr
    assert (tmp_path / "from_log.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(os.listdir(tmp_path)) == ["from_log.png", "log.jsonl"]  # nothing else written: no run folder

    cli("run", "--method", "mm-nh", "--in", tmp_path / "log.jsonl", "--out", tmp_path / "mm-nh", "--quiet")
    completed = plot(tmp_path / "mm-nh", "--out", tmp_path / "from_folder.png")
    assert completed.returncode == 0, completed.stderr
    assert (tmp_path / "from_folder.png").exists()


def test_plot_methods_reports_a_bad_option(cli, tmp_path):
    cli("simulate", "semantic", "--out", tmp_path / "log.jsonl", "--seed", 5, "--steps", 10)
    completed = plot("--log", tmp_path / "log.jsonl", "--methods", "mm-nh", "--option", "gate=7",
                     "--out", tmp_path / "x.png")
    assert completed.returncode != 0 and "--gate" in completed.stderr
    assert not (tmp_path / "x.png").exists()

"""docs/results.md section of issue 17: paper B's robustness study under mpirun on this machine; used by
make_results.py.

The same study in several layouts (one process with 2 threads; mpirun with 1, 2 or 4 ranks), run in turn,
round after round, so that a drift of the shared machine's speed hits every layout alike; the wall time of each
whole command, median over the rounds. Every layout's folder must equal the first's file for file, timings.csv
aside (docs/studies.md); the section says so or stops.
"""
import filecmp
import os
import shutil
import statistics
import subprocess
import sys
import time

from results_commands import run_checked

ROUNDS = 3
# Lost in the Woods as in the robustness section, cut shorter: about half a minute of 2-core work per study.
LOG = ("utias-lost-in-the-woods", ["--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1"])
STUDY = ["--max-steps", "100", "--methods", "known,ml,gpda,mm,mm-nh", "--odom-noise-scale", "0,5,20",
         "--misclassification", "0.1,0.5", "--seeds", "2", "--smoother", "batch", "--quiet"]
# (label, ranks (0: no mpirun), threads per process, environment)
LAYOUTS = [
    ("1 process × 2 threads", 0, 2, {}),
    ("1 process × 2 threads, OMP_NUM_THREADS=1", 0, 2, {"OMP_NUM_THREADS": "1"}),
    ("mpirun -np 2 × 1 thread (work queue)", 2, 1, {}),
    ("mpirun -np 2 × 1 thread (static partition)", 2, 1, {"SEMSLAM_MPI_SCHEDULE": "static"}),
    ("mpirun -np 1 × 1 thread", 1, 1, {}),
]
IDENTITY_ONLY = [("mpirun -np 4 × 1 thread (oversubscribed)", 4, 1, {})]


def _mpirun(ranks):
    """mpirun on this machine only: as root if need be, more ranks than cores allowed, loopback."""
    return ["mpirun", "-np", str(ranks), "--oversubscribe", "--mca", "btl", "self,vader", "--mca",
            "btl_vader_single_copy_mechanism", "none", "--mca", "oob_tcp_if_include", "lo"]


def _environment(extra):
    env = dict(os.environ, **extra)
    if os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def _command(semslam, log, out, ranks, threads):
    return (_mpirun(ranks) if ranks else []) + [semslam, "study", "robustness", "--log", log] + STUDY + [
        "--threads", str(threads), "--out", out, "--overwrite"]


def _timed(command, extra):
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, env=_environment(extra))
    if result.returncode != 0:
        sys.exit(f"make_results.py: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return time.monotonic() - start


def _same_folder(reference, other):
    names = sorted(set(os.listdir(reference)) - {"timings.csv"})
    if names != sorted(set(os.listdir(other)) - {"timings.csv"}):
        return False
    return all(filecmp.cmp(os.path.join(reference, n), os.path.join(other, n), shallow=False) for n in names)


def studies_mpi_section(semslam, data, scratch, shown):
    lines = ["## Studies under MPI (issue 17)", "",
             "docs/studies.md. Paper B's robustness study (50 runs: 5 methods × 5 levels × 2 seeds, first 100 "
             "keyframes of Lost in the Woods) in each layout on this 2-core machine, shared with other work; the "
             "layouts run in turn, " + str(ROUNDS) + " rounds; wall time of the whole command, median (min–max).",
             ""]
    path = os.path.join(data, LOG[0])
    if not os.path.exists(path):
        return lines + ["dataset absent", ""]
    if shutil.which("mpirun") is None:
        return lines + ["mpirun absent (make deps installs openmpi-bin)", ""]
    log = os.path.join(scratch, "studies-mpi-litw.jsonl")
    convert = [semslam, "convert", LOG[0], path, "--out", log] + LOG[1]
    run_checked(convert)
    times = {label: [] for label, _, _, _ in LAYOUTS}
    folders = {}
    for label, _, _, _ in LAYOUTS:
        folders[label] = os.path.join(scratch, f"studies-mpi-{len(folders)}")
    for _ in range(ROUNDS):
        for label, ranks, threads, extra in LAYOUTS:
            times[label].append(_timed(_command(semslam, log, folders[label], ranks, threads), extra))
    for label, ranks, threads, extra in IDENTITY_ONLY:
        folders[label] = os.path.join(scratch, f"studies-mpi-{len(folders)}")
        _timed(_command(semslam, log, folders[label], ranks, threads), extra)
    reference = folders[LAYOUTS[0][0]]
    different = [label for label, out in folders.items() if not _same_folder(reference, out)]
    if different:
        sys.exit(f"make_results.py: studies under MPI: {', '.join(different)} differ from one process "
                 "(timings.csv aside)")
    median = {label: statistics.median(values) for label, values in times.items()}
    base = median[LAYOUTS[0][0]]
    lines += ["| layout | wall [s] | speed against 1 process × 2 threads |", "|---|---|---|"]
    for label, values in times.items():
        lines.append(f"| {label} | {median[label]:.1f} ({min(values):.1f}–{max(values):.1f}) | "
                     f"{base / median[label]:.2f}× |")
    one_rank, two_ranks = median["mpirun -np 1 × 1 thread"], median["mpirun -np 2 × 1 thread (work queue)"]
    lines += ["", f"- 1 → 2 ranks (1 thread each): {one_rank / two_ranks:.2f}× faster.",
              "- Debian's CHOLMOD runs its own OpenMP threads (docs/benchmarks.md): in one process with 2 worker "
              "threads they oversubscribe the 2 cores; mpirun binds each rank to a core, so each rank's OpenMP "
              "runs one thread. `OMP_NUM_THREADS=1` gives the single process the same footing.",
              "- Every folder above, and that of `mpirun -np 4` (oversubscribed), equals the first file for file, "
              "`timings.csv` aside.", "", "```sh", shown(convert).replace(log, "litw.jsonl")]
    for label, ranks, threads, extra in LAYOUTS + IDENTITY_ONLY:
        prefix = "".join(f"{key}={value} " for key, value in extra.items())
        lines.append(prefix + shown(_command(semslam, log, "DIR", ranks, threads)).replace(log, "litw.jsonl"))
    return lines + ["```", ""]

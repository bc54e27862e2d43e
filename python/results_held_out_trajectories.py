"""docs/results.md section `held-out-trajectories`: the issue's KITTI target (mm-nh ATE ≤ 2 × known association's and
≤ ml's, default options) on semantic simulations over trajectories no default was chosen on: KITTI 00 and 07 driven
backwards, three parts of 00 (python/edit_trajectory.py), and 00 and 07 stepped at other strides than every
project's fifth frame (a step every 3 or 8 camera frames: more or fewer steps, and sightings, per metre), simulated
as the KITTI simulations of the association section are (results_max_mixtures.kitti_simulation) with seeds of
their own. Every cell comes from the runs' metrics.json (results_association.kitti_target_table). Used by
make_results.py.
"""
import os

import edit_trajectory
from results_association import kitti_target_table
from results_max_mixtures import KITTI_STRIDE, kitti_simulation

# (label, KITTI sequence, frames kept, reversed, stride, simulator seeds). 07 reversed has 8 seeds (its runs take
# seconds); the others three each (a run of a whole 00 takes up to a minute, at stride 3 nearly two).
EDITS = [
    ("00 reversed", "00", slice(None), True, KITTI_STRIDE, range(1, 4)),
    ("07 reversed", "07", slice(None), True, KITTI_STRIDE, range(1, 9)),
    ("00 frames 0-2299", "00", slice(None, 2300), False, KITTI_STRIDE, range(1, 4)),
    ("00 frames 2270-4540", "00", slice(2270, None), False, KITTI_STRIDE, range(1, 4)),
    ("00 frames 2270-4540 reversed", "00", slice(2270, None), True, KITTI_STRIDE, range(1, 4)),
    ("00 frames 1000-3499", "00", slice(1000, 3500), False, KITTI_STRIDE, range(1, 4)),
    ("00 at stride 3", "00", slice(None), False, 3, range(1, 4)),
    ("00 at stride 8", "00", slice(None), False, 8, range(1, 4)),
    ("07 at stride 3", "07", slice(None), False, 3, range(1, 4)),
    ("07 at stride 8", "07", slice(None), False, 8, range(1, 4)),
]


def edit_arguments(selection, reverse):
    """The options of python/edit_trajectory.py that make an edit."""
    arguments = []
    if selection != slice(None):
        arguments += ["--frames", edit_trajectory.frames_text(selection)]
    return arguments + (["--reverse"] if reverse else [])


def held_out_trajectories_section(semslam, data, scratch, shown):
    lines = ["## KITTI simulations on held-out trajectories (issue 10)", ""]
    os.makedirs(scratch, exist_ok=True)
    logs = []
    for index, (label, sequence, selection, reverse, stride, seeds) in enumerate(EDITS):
        source = os.path.join(data, "kitti-odometry-poses", f"{sequence}.txt")
        if not os.path.exists(source):
            continue
        trajectory = source  # the strides simulate the sequence as it is: nothing to edit
        if selection != slice(None) or reverse:
            trajectory = os.path.join(scratch, f"edit{index}.txt")
            edit_trajectory.write_frames(trajectory, edit_trajectory.edit(edit_trajectory.read_frames(source),
                                                                          selection, reverse))
        logs += [(label, seed, trajectory, os.path.join(scratch, f"edit{index}-seed{seed}"), stride)
                 for seed in seeds]
    table = kitti_target_table(semslam, logs, "trajectory") if logs else None
    if table is None:
        return lines + ["KITTI odometry poses are absent: section skipped.", ""]
    lines += ["The KITTI target of the association section on trajectories that no default of the project was "
              "chosen on: KITTI 00 and 07 driven backwards (the frames in the opposite order, each pose as it was: "
              "the vehicle backs along its path, and the camera sees each place as it leaves it) and parts of 00 "
              "(frames 0-2299, 2270-4540 forwards and backwards, 1000-3499), made by python/edit_trajectory.py and "
              "simulated with the association section's KITTI command; and 00 and 07 as they are, simulated with a "
              "step every 3 or 8 camera frames (`--stride 3`, `--stride 8`) instead of every 5th: the same roads "
              "with more or fewer steps, and sightings, per metre. Columns as there.", ""]
    lines += table
    example_edit = ["/usr/bin/python3", "python/edit_trajectory.py", "../shared/data/kitti-odometry-poses/00.txt",
                    "--out", "00-part.txt"] + edit_arguments(slice(2270, None), True)
    lines += ["", "```sh", " ".join(example_edit),
              shown([str(a) for a in kitti_simulation(semslam, "00-part.txt", "k.jsonl", "S")]) +
              "   # the strides: --trajectory ../shared/data/kitti-odometry-poses/SEQ.txt --stride 3 or 8",
              "for m in known ml mm-nh; do build/bin/semslam run --method $m --in k.jsonl --out k/$m "
              "--no-covariances; done", "```", ""]
    return lines

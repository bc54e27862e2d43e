"""semslam.run against `semslam run`: the same metrics.json, the same run folder contents, the same errors."""

import csv
import json

import numpy as np
import pytest

import semslam

WALL_TIMES = {"time_s"}  # the only metrics a second run may change (docs/metrics.md)


@pytest.fixture(scope="module")
def logs(cli, tmp_path_factory):
    folder = tmp_path_factory.mktemp("logs")
    cli("simulate", "semantic", "--out", folder / "planar.jsonl", "--seed", 3, "--steps", 60, "--classes", 3)
    cli("simulate", "semantic", "--out", folder / "spatial.jsonl", "--seed", 4, "--steps", 40, "--classes", 3,
        "--dimension", 3)
    cli("simulate", "aliased2d", "--out", folder / "aliased.jsonl", "--steps", 8)
    return folder


def cli_run(cli, log, folder, method, *flags):
    cli("run", "--method", method, "--in", log, "--out", folder, "--quiet", "--overwrite", *flags)
    return json.loads((folder / "metrics.json").read_text())


@pytest.mark.parametrize("log_name, method, flags, keywords", [
    ("planar.jsonl", "mm-nh", [], {}),
    ("planar.jsonl", "known", ["--no-covariances"], {"no_covariances": True}),
    ("planar.jsonl", "gpda", ["--gate", "0.95", "--em-window", "3"], {"gate": 0.95, "em_window": 3}),
    ("planar.jsonl", "ml", ["--birth", "threshold", "--no-warm-start"], {"birth": "threshold", "no_warm_start": True}),
    ("spatial.jsonl", "mm", ["--smoother", "batch"], {"smoother": "batch"}),
    ("aliased.jsonl", "hybrid", ["--seed", "4"], {"seed": 4}),
    ("aliased.jsonl", "hybrid-geometric", ["--max-components", "4"], {"max_components": 4}),
])
def test_run_equals_the_command_line_tool(cli, logs, tmp_path, log_name, method, flags, keywords):
    log = logs / log_name
    expected = cli_run(cli, log, tmp_path / "cli", method, *flags)
    result = semslam.run(method, str(log), **keywords)
    assert set(result.metrics) == set(expected)
    differing = {key for key in expected if result.metrics[key] != expected[key]}
    assert differing <= WALL_TIMES, f"differ: {sorted(differing - WALL_TIMES)}"
    # The settings the run was made with: the folder's settings.json but its schema and release.
    settings = json.loads((tmp_path / "cli" / "settings.json").read_text())
    assert {settings.pop("schema"), settings.pop("version")} == {"semslam.settings/1", semslam.__version__}
    assert result.settings == settings

    # The arrays hold what the run folder holds.
    with open(tmp_path / "cli" / "trajectory.tum") as stream:
        rows = np.array([[float(x) for x in line.split()] for line in stream if line.strip()])
    assert result.trajectory.shape[0] == rows.shape[0] == len(result.timestamps)
    np.testing.assert_allclose(result.timestamps, rows[:, 0], rtol=1e-15)
    if log_name == "spatial.jsonl":  # N x 7 rows x, y, z, qx, qy, qz, qw as TUM writes them (q up to sign)
        assert result.trajectory.shape[1] == 7
        np.testing.assert_allclose(result.trajectory[:, :3], rows[:, 1:4], rtol=1e-12, atol=1e-12)
        signs = np.sign(np.sum(result.trajectory[:, 3:] * rows[:, 4:], axis=1))[:, None]
        np.testing.assert_allclose(signs * result.trajectory[:, 3:], rows[:, 4:], atol=1e-12)
    else:  # N x 3 rows x, y, theta; TUM holds theta as a yaw quaternion (0, 0, sin θ/2, cos θ/2)
        assert result.trajectory.shape[1] == 3
        np.testing.assert_allclose(result.trajectory[:, :2], rows[:, 1:3], rtol=1e-12, atol=1e-12)
        yaw = 2 * np.arctan2(rows[:, 6], rows[:, 7])
        np.testing.assert_allclose(np.angle(np.exp(1j * (result.trajectory[:, 2] - yaw))), 0, atol=1e-12)
    with open(tmp_path / "cli" / "associations.csv") as stream:
        associations = list(csv.DictReader(stream))
    assert len(associations) == len(result.associations["landmark"])
    for row, landmark in zip(associations, result.associations["landmark"]):
        assert int(row["landmark"]) == landmark if row["landmark"] != "null" else landmark == semslam.NULL_HYPOTHESIS
    assert (result.hypotheses is not None) == method.startswith("hybrid")
    if result.hypotheses is not None:
        assert len(result.hypotheses) == len(result.timestamps)


def test_run_takes_a_loaded_log_and_is_deterministic(logs):
    log = semslam.read_log(str(logs / "planar.jsonl"))
    assert len(log) == 61 and log.dimension == 2 and log.classes == 3
    first = semslam.run("mm-nh", log)
    second = semslam.run("mm-nh", str(logs / "planar.jsonl"))
    np.testing.assert_array_equal(first.trajectory, second.trajectory)
    np.testing.assert_array_equal(first.associations["landmark"], second.associations["landmark"])


def test_bad_options_raise_with_the_command_line_tools_message(logs):
    log = str(logs / "planar.jsonl")
    with pytest.raises(TypeError, match="unexpected keyword argument 'gates'.*gate"):
        semslam.run("mm-nh", log, gates=0.9)
    with pytest.raises(ValueError, match="--gate"):
        semslam.run("mm-nh", log, gate=2.0)
    with pytest.raises(ValueError, match="--method"):
        semslam.run("mm-nhh", log)
    with pytest.raises(TypeError, match="True or False"):
        semslam.run("mm-nh", log, no_covariances=1)
    with pytest.raises(ValueError, match="--seed"):
        semslam.run("hybrid", log, seed=-1)
    with pytest.raises(TypeError, match="one value"):  # a list cannot smuggle in another flag
        semslam.run("known", log, birth=["threshold", "--smoother", "batch"])
    with pytest.raises(TypeError, match="unexpected keyword argument 'help'"):
        semslam.run("known", log, help=True)
    with pytest.raises(ValueError, match="--confirmations"):  # the tool's range check (1..) on a decimal integer
        semslam.run("mm-nh", log, confirmations="0x10")


def test_integer_options_read_decimal_as_on_the_command_line(cli, logs, tmp_path):
    """"0467" is 467 (CLI11 alone reads it as octal 311): the tool's rule (fuzz/findings/options), in Python too."""
    log = logs / "aliased.jsonl"
    expected = cli_run(cli, log, tmp_path / "cli", "hybrid", "--seed", "467")
    result = semslam.run("hybrid", str(log), seed="0467")
    assert {key for key in expected if result.metrics[key] != expected[key]} <= WALL_TIMES


def test_run_takes_a_bytes_or_pathlike_path(logs):
    from_text = semslam.run("known", str(logs / "planar.jsonl"))
    for path in (logs / "planar.jsonl", bytes(logs / "planar.jsonl")):
        np.testing.assert_array_equal(semslam.run("known", path).trajectory, from_text.trajectory)


def test_a_malformed_log_raises_with_its_line_number(logs, tmp_path):
    lines = (logs / "planar.jsonl").read_text().splitlines()
    lines[2] = lines[2].replace('"time"', '"tiem"', 1)
    (tmp_path / "bad.jsonl").write_text("\n".join(lines) + "\n")
    for call in (lambda: semslam.read_log(str(tmp_path / "bad.jsonl")),
                 lambda: semslam.run("mm-nh", str(tmp_path / "bad.jsonl"))):
        with pytest.raises(semslam.InputError) as error:
            call()
        assert error.value.line == 3
        assert str(error.value).startswith(str(tmp_path / "bad.jsonl") + ":3: ")
    with pytest.raises(semslam.InputError, match="does not exist"):
        semslam.run("mm-nh", str(tmp_path / "missing.jsonl"))


def test_a_log_written_from_python_reads_back_the_same(logs, tmp_path):
    log = semslam.read_log(str(logs / "spatial.jsonl"))
    semslam.write_log(str(tmp_path / "copy.jsonl"), log)
    assert (tmp_path / "copy.jsonl").read_bytes() == (logs / "spatial.jsonl").read_bytes()


def test_ate_and_rpe_equal_the_command_line_tool(cli, logs, tmp_path):
    cli_run(cli, logs / "planar.jsonl", tmp_path / "run", "mm-nh")
    estimate = semslam.read_trajectory(str(tmp_path / "run" / "trajectory.tum"))
    reference = semslam.read_trajectory(str(tmp_path / "run" / "truth.tum"))
    for kind, function, flags in (("ape", semslam.ate, {"align": "se3"}),
                                  ("rpe", semslam.rpe, {"delta": 2, "relation": "angle_deg"})):
        arguments = ["eval", kind, "--est", tmp_path / "run" / "trajectory.tum", "--ref",
                     tmp_path / "run" / "truth.tum", "--json"]
        arguments += ["--align", "se3"] if kind == "ape" else ["--delta", "2", "--relation", "angle_deg"]
        expected = json.loads(cli(*arguments).stdout)
        statistics = function(estimate, reference, **flags)
        for key in ("max", "mean", "median", "min", "rmse", "sse", "std"):
            assert statistics[key] == pytest.approx(expected[key], rel=1e-12, abs=1e-15)
    # From the arrays of a run, without files.
    result = semslam.run("mm-nh", str(logs / "planar.jsonl"))
    from_arrays = semslam.ate(semslam.Trajectory(result.timestamps, result.trajectory), reference, align="se3")
    assert from_arrays["rmse"] == pytest.approx(semslam.ate(estimate, reference, align="se3")["rmse"], rel=1e-9)


def test_progress_is_reported_every_step_and_can_stop_the_run(logs):
    log = str(logs / "planar.jsonl")
    calls = []
    semslam.run("mm-nh", log, progress=lambda done, total: calls.append((done, total)))
    assert calls == [(k, 61) for k in range(1, 62)]

    def stop_at_ten(done, total):
        calls.append(done)
        if done == 10:
            raise RuntimeError("enough")

    calls.clear()
    with pytest.raises(RuntimeError, match="enough"):
        semslam.run("mm-nh", log, progress=stop_at_ten)
    assert calls == list(range(1, 11))  # the run stopped at the step that raised
    with pytest.raises(TypeError, match="callable"):
        semslam.run("mm-nh", log, progress=3)


def test_ctrl_c_stops_a_run_at_the_end_of_a_step(logs):
    """A pending KeyboardInterrupt is checked after every step (the GIL is released while a step runs)."""
    import _thread

    calls = []

    def interrupt_at_five(done, total):
        calls.append(done)
        if done == 5:
            _thread.interrupt_main()  # as Ctrl-C: Python's signal flag, seen at the next check

    for method, log in (("mm-nh", logs / "planar.jsonl"), ("hybrid", logs / "aliased.jsonl")):
        calls.clear()
        with pytest.raises(KeyboardInterrupt):
            semslam.run(method, str(log), progress=interrupt_at_five)
        assert calls == [1, 2, 3, 4, 5]

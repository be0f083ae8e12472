"""What `tide run` writes, read from Python: its frames, probes.csv and checkpoint.h5 hold the
state the same scene reaches when tidesph steps it to the same step, bit for bit."""

import json
import os
import subprocess

import numpy as np
import pytest

import tidesph
from conftest import small_dam_break

TIDE = os.environ.get("TIDE_COMMAND")


@pytest.fixture(scope="module")
def tide_run(tmp_path_factory):
    if not TIDE:
        pytest.skip("TIDE_COMMAND is not set: ctest sets it where the tide command is built (TIDE_BUILD_APPS)")
    directory = tmp_path_factory.mktemp("tide_run")
    scene_file = directory / "dam.json"
    scene = small_dam_break()
    scene["output"] = {"fields": ["position", "velocity", "density", "pressure", "id"]}
    scene_file.write_text(json.dumps(scene))
    out = directory / "run"
    subprocess.run([TIDE, "run", str(scene_file), "--out", str(out), "--until", "0.03", "--quiet",
                    "--checkpoint-every", "0.01"], check=True, stdout=subprocess.DEVNULL)
    return scene_file, out


def by_id(ids, values):
    return values[np.argsort(ids)]


def stepped_to(scene_file, step):
    sim = tidesph.Simulation(scene_file)
    while sim.step_count < step:
        sim.step()
    return sim


def test_frames_hold_the_state_of_the_same_step(tide_run):
    scene_file, out = tide_run
    files = tidesph.frame_files(out)
    assert [os.path.basename(f) for f in files[:2]] == ["frames_000000.h5", "frames_000001.h5"]
    frame = tidesph.read_frame(files[-1])
    assert frame["time"] >= 0.03
    assert frame["fields"]["position"].shape == (800, 2)
    sim = stepped_to(scene_file, frame["step"])
    assert sim.time == frame["time"]
    ids = frame["fields"]["id"]
    x, y = sim.field("position")
    np.testing.assert_array_equal(by_id(ids, frame["fields"]["position"]),
                                  by_id(sim.field("id"), np.stack([x, y], axis=1)))
    np.testing.assert_array_equal(by_id(ids, frame["fields"]["pressure"]), by_id(sim.field("id"), sim.field("pressure")))


def test_probes_csv_holds_the_readings_of_the_same_times(tide_run):
    scene_file, out = tide_run
    series = tidesph.read_series(out / "probes.csv")
    assert list(series) == ["time", "p_floor", "h_wall"]
    assert len(series["time"]) >= 4  # t = 0, 0.01, 0.02, 0.03
    sim = tidesph.Simulation(scene_file)
    for row, time in enumerate(series["time"]):
        while sim.time < time:
            sim.step()
        assert sim.time == time
        readings = sim.probes()
        assert readings["p_floor"] == series["p_floor"][row]
        assert readings["h_wall"] == series["h_wall"][row]


def test_restore_the_runs_checkpoint(tide_run):
    scene_file, out = tide_run
    sim = tidesph.Simulation(scene_file)
    sim.restore_checkpoint(out / "checkpoint.h5")
    assert sim.time >= 0.03
    straight = stepped_to(scene_file, sim.step_count)
    for name in ("density", "pressure"):
        np.testing.assert_array_equal(sim.field(name), straight.field(name), err_msg=name)


def test_a_directory_without_frames(tmp_path):
    with pytest.raises(ValueError, match="no frame files"):
        tidesph.frame_files(tmp_path)


def test_a_series_that_is_not_one(tmp_path):
    bad = tmp_path / "probes.csv"
    bad.write_text("time,a\n0,1\n0.5,x\n")
    with pytest.raises(RuntimeError, match=r"probes.csv: line 3: expected a number, got \"x\""):
        tidesph.read_series(bad)

"""Checkpoints from Python, through the C++ checkpoint code (Simulation::save/restore and
io::write_checkpoint/read_checkpoint): a resumed run continues with the same bits."""

import numpy as np
import pytest

import tidesph
from conftest import small_dam_break


def fields(sim):
    return {name: np.array(sim.field(name), copy=True) for name in sim.field_names}


def test_resume_gives_the_same_bits(dam_break, tmp_path):
    straight = tidesph.Simulation(dam_break)
    for _ in range(40):
        straight.step()

    first = tidesph.Simulation(dam_break)
    for _ in range(20):
        first.step()
    first.write_checkpoint(tmp_path / "run.h5")
    resumed = tidesph.Simulation(small_dam_break())  # an equal dict: the same scene
    resumed.restore_checkpoint(tmp_path / "run.h5")
    assert resumed.step_count == 20 and resumed.time == first.time
    for _ in range(20):
        resumed.step()

    assert resumed.time == straight.time
    a, b = fields(straight), fields(resumed)
    assert a.keys() == b.keys()
    for name in a:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)


def test_checkpoint_of_another_scene_is_refused(dam_break, tmp_path):
    tidesph.Simulation(dam_break).write_checkpoint(tmp_path / "run.h5")
    dam_break["particle_spacing"] = 0.02
    other = tidesph.Simulation(dam_break)
    with pytest.raises(tidesph.CheckpointError, match="run.h5"):
        other.restore_checkpoint(tmp_path / "run.h5")
    assert other.step_count == 0


def test_missing_checkpoint_names_the_file(dam_break, tmp_path):
    with pytest.raises(RuntimeError, match="absent.h5"):
        tidesph.Simulation(dam_break).restore_checkpoint(tmp_path / "absent.h5")

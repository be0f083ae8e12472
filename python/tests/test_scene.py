"""Scenes from files and dicts, and the errors a bad one raises: the scene reader's own messages,
naming the file (or the dict's name) and the JSON key path."""

import numpy as np
import pytest

import tidesph
from conftest import small_dam_break


def test_scene_file(scenes_dir):
    scene = tidesph.load_scene(scenes_dir / "dam_break_2d.json")
    assert scene.dimension == 2
    assert scene.scheme == "wcsph"
    assert scene.source.endswith("dam_break_2d.json")


def test_scene_dict():
    scene = tidesph.scene_from_dict(small_dam_break(), name="dam")
    assert (scene.dimension, scene.particle_spacing, scene.end_time) == (2, 0.01, 0.05)
    assert scene.probe_names == ["p_floor", "h_wall"]


def test_numpy_values_in_a_dict():
    d = small_dam_break()
    d["fluid"][0]["box"]["max"] = np.array([0.2, 0.4])
    d["particle_spacing"] = np.float32(0.01).item()
    assert tidesph.scene_from_dict(d).dimension == 2


@pytest.mark.parametrize("change, path, expected", [
    (lambda d: d["solver"].update(cfl="fast") if "solver" in d else d.update(solver={"cfl": "fast"}),
     "/solver/cfl", "expected a number"),
    (lambda d: d["fluid"][0]["box"].update(max=[0.2]), "/fluid/0/box/max", "expected"),
    (lambda d: d["materials"][0].update(rest_density=-1), "/materials/0/rest_density", "expected"),
    (lambda d: d.update(colour="blue"), "/colour", "unknown key"),
])
def test_bad_dict_names_the_key_path(change, path, expected):
    d = small_dam_break()
    change(d)
    with pytest.raises(tidesph.SceneError) as error:
        tidesph.scene_from_dict(d, name="my scene")
    message = str(error.value)
    assert message.startswith("my scene: " + path + ":"), message
    assert expected in message
    assert isinstance(error.value, ValueError)


def test_bad_dict_in_the_simulation_constructor():
    d = small_dam_break()
    d["time"]["end"] = "soon"
    with pytest.raises(tidesph.SceneError, match="^scene dict: /time/end: "):
        tidesph.Simulation(d)


def test_missing_file_names_it(tmp_path):
    with pytest.raises(tidesph.SceneError, match="nowhere.json"):
        tidesph.load_scene(tmp_path / "nowhere.json")


def test_value_that_is_not_json():
    d = small_dam_break()
    d["gravity"] = {0, -9.81}
    with pytest.raises(TypeError, match="set"):
        tidesph.scene_from_dict(d)

"""Steps and runs from Python: the reports, the run statistics, thread-count independence, and
two Python threads stepping one simulation (the GIL is released while it steps)."""

import threading

import numpy as np
import pytest

import tidesph

LIMITS = {"acoustic", "velocity", "viscous", "force", "capillary"}


def test_step_reports_the_time_step(dam_break):
    sim = tidesph.Simulation(dam_break)
    report = sim.step()
    assert report["limit"] in LIMITS
    assert report["dt"] > 0
    assert sim.time == pytest.approx(report["dt"])
    assert sim.step_count == 1
    assert report["density_solve"] is None  # WCSPH solves no pressure equation


def test_run_until_and_its_statistics(dam_break):
    sim = tidesph.Simulation(dam_break)
    steps = sim.run(0.02)
    stats = sim.statistics
    assert steps == sim.step_count == stats["steps"] > 0
    assert 0.02 <= sim.time < 0.02 + stats["last_step"]["dt"]
    assert sum(stats["limits"].values()) == steps
    assert stats["particle_steps"] == steps * sim.particle_count  # nothing left the tank
    assert stats["neighbor_builds"] >= 1
    assert "kick_drift" in stats["stage_seconds"]
    assert sim.run(0.01) == 0  # already past


def test_run_defaults_to_the_scene_end(dam_break):
    sim = tidesph.Simulation(dam_break)
    sim.run()
    assert sim.time >= dam_break["time"]["end"]


def test_incompressible_solves_are_counted(dam_break):
    dam_break["solver"] = {"scheme": "dfsph"}
    sim = tidesph.Simulation(dam_break)
    report = sim.step()
    assert report["density_solve"]["iterations"] >= 1
    assert report["limit"] in LIMITS
    stats = sim.statistics
    assert stats["density_solves"]["solves"] == 1
    assert stats["divergence_solves"]["solves"] == 1


def final_state(scene, steps):
    sim = tidesph.Simulation(scene)
    for _ in range(steps):
        sim.step()
    return {name: np.array(sim.field(name), copy=True) for name in ("position", "velocity", "density", "id")}


def test_same_bits_for_one_and_two_threads(dam_break):
    try:
        tidesph.set_threads(1)
        assert tidesph.thread_count() == 1
        one = final_state(dam_break, 30)
        tidesph.set_threads(2)
        two = final_state(dam_break, 30)
    finally:
        tidesph.set_threads(0)
    for name in one:
        np.testing.assert_array_equal(one[name], two[name], err_msg=name)


def test_two_python_threads_step_one_simulation(dam_break):
    # The lock serialises the steps: 2 x 15 steps from two threads are 30 steps, with the bits of
    # 30 steps taken one after the other.
    sim = tidesph.Simulation(dam_break)
    workers = [threading.Thread(target=lambda: [sim.step() for _ in range(15)]) for _ in range(2)]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join()
    assert sim.step_count == 30
    serial = final_state(dam_break, 30)
    np.testing.assert_array_equal(np.array(sim.field("position")), serial["position"])


def test_probes_read_now(dam_break):
    sim = tidesph.Simulation(dam_break)
    sim.run(0.02)
    readings = sim.probes()
    assert list(readings) == ["p_floor", "h_wall"]
    assert readings["p_floor"] > 0
    # The front has not reached x = 0.55 m (5.5 a) by t = 0.02 s (T = 0.28; Ritter: Z < 1.6).
    assert readings["h_wall"] == 0


def test_an_unstable_run_raises(dam_break):
    # As tests/wcsph_test.cpp (SpeedBandIsAConfigurableMultipleOfTheSoundSpeed): a speed band of
    # 1e-4 c0 (3 mm/s) that the falling column passes at once stops the run with a diagnosis.
    dam_break["solver"] = {"max_mach_number": 1e-4}
    sim = tidesph.Simulation(dam_break)
    with pytest.raises(tidesph.InstabilityError, match=r"particle \d+ has speed = .*max_mach_number.* at step \d+") as error:
        sim.run(0.05)
    assert isinstance(error.value, RuntimeError)
    assert sim.step_count < 100

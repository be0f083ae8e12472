"""Fields as NumPy views: no copy, read-only, alive as long as a view is, live until the next step
re-sorts; and the starting fields set from Python before the first step."""

import gc

import numpy as np
import pytest

import tidesph
from conftest import EPS, REAL


def test_views_share_the_simulations_memory(dam_break):
    sim = tidesph.Simulation(dam_break)
    density = sim.field("density")
    assert density.shape == (sim.particle_count,)
    assert density.dtype == REAL
    assert not density.flags.owndata
    assert np.shares_memory(density, sim.field("density"))
    x, y = sim.field("position")
    assert x.shape == y.shape == (sim.particle_count,)
    assert sim.field("id").dtype == np.uint32
    assert set(sim.fields) == set(sim.field_names)
    assert {"position", "velocity", "density", "pressure", "mass", "id"} <= set(sim.field_names)


def test_views_are_read_only(dam_break):
    sim = tidesph.Simulation(dam_break)
    with pytest.raises(ValueError):
        sim.field("pressure")[0] = 1.0


def test_unknown_field_names_the_fields_there_are(dam_break):
    sim = tidesph.Simulation(dam_break)
    with pytest.raises(KeyError, match="no field 'temperature'.*pressure"):
        sim.field("temperature")


def test_a_view_shows_the_arrays_as_they_are_now(dam_break):
    # No particle leaves this tank, so the arrays keep their place: a view fetched before the
    # steps shows what a fresh one shows after them, in the particle order of now.
    sim = tidesph.Simulation(dam_break)
    before = sim.field("velocity")[0]
    ids_before = sim.field("id")
    sim.run(0.02)
    assert sim.statistics["removed_total"] == 0
    np.testing.assert_array_equal(before, sim.field("velocity")[0])
    np.testing.assert_array_equal(ids_before, sim.field("id"))
    assert np.abs(before).max() > 0


def test_a_view_keeps_its_simulation_alive(dam_break):
    sim = tidesph.Simulation(dam_break)
    pressure = sim.field("pressure")
    copy = pressure.copy()
    del sim
    gc.collect()
    np.testing.assert_array_equal(pressure, copy)


def test_a_restore_leaves_older_views_on_the_old_state(dam_break, tmp_path):
    sim = tidesph.Simulation(dam_break)
    sim.write_checkpoint(tmp_path / "start.h5")
    sim.run(0.01)
    old = sim.field("pressure")
    old_copy = old.copy()
    sim.restore_checkpoint(tmp_path / "start.h5")
    assert sim.step_count == 0
    np.testing.assert_array_equal(old, old_copy)
    assert not np.shares_memory(old, sim.field("pressure"))


def by_id(sim, name):
    order = np.argsort(sim.field("id"))
    value = sim.field(name)
    return tuple(v[order] for v in value) if isinstance(value, tuple) else value[order]


def test_set_fields_recomputes_the_pressure_from_the_density(dam_break):
    # Continuity density keeps the density it is given; the start computes the pressure from it by
    # the Tait equation p = ρ0 c0² / γ ((ρ/ρ0)^γ − 1), γ = 7, c0 = 10 max_speed (docs/scenes.md).
    dam_break["solver"] = {"density": "continuity"}
    sim = tidesph.Simulation(dam_break)
    rho0, c0, gamma = 1000.0, 30.0, 7.0
    ids = sim.field("id").copy()
    y = sim.field("position")[1].copy()
    density = rho0 * (1 + 0.01 * y / 0.4)  # up to 1% denser at the top
    sim.set_fields(density=density)
    np.testing.assert_array_equal(by_id(sim, "density"), density[np.argsort(ids)])
    p = sim.field("pressure")
    expected = rho0 * c0**2 / gamma * ((sim.field("density") / rho0) ** gamma - 1)
    # x^7 − 1 with x ≈ 1 in the build's precision: rounding of a few ulp of 1, times ρ0 c0² / γ.
    np.testing.assert_allclose(p, expected, rtol=0, atol=100 * EPS * rho0 * c0**2 / gamma)
    assert p.max() > 0.9 * rho0 * c0**2 / gamma * (1.01**gamma - 1)


@pytest.mark.parametrize("scheme", ["wcsph", "dfsph", "iisph"])
def test_set_velocity_moves_the_fluid(dam_break, scheme):
    dam_break["gravity"] = [0, 0]
    dam_break["solver"] = {"scheme": scheme}
    sim = tidesph.Simulation(dam_break)
    n = sim.particle_count
    sim.set_fields(velocity=np.stack([np.full(n, 0.5), np.zeros(n)]))
    u, v = by_id(sim, "velocity")
    np.testing.assert_array_equal(u, 0.5)
    x0 = by_id(sim, "position")[0]
    sim.step()
    dt = sim.statistics["last_step"]["dt"]
    # A uniform velocity in a fluid at rest density, no gravity: the first step carries the column
    # 0.5 dt to the right; the wall beside it slows only the particles near it.
    shift = by_id(sim, "position")[0] - x0
    # Within 1e-6 (the interior's acceleration is round-off), or in float two ulp of the positions
    # (up to 0.6 m) the shift is the difference of.
    assert np.median(shift) == pytest.approx(0.5 * dt, rel=1e-6, abs=2 * float(np.spacing(REAL(0.6))))


def test_set_fields_checks_before_it_sets(dam_break):
    sim = tidesph.Simulation(dam_break)
    n = sim.particle_count
    with pytest.raises(ValueError, match=r"'velocity': expected \(2, 800\) or \(800, 2\) values for 800 particles"):
        sim.set_fields(density=np.full(n, 1000.0), velocity=np.zeros(n))
    with pytest.raises(KeyError, match="temperature"):
        sim.set_fields(temperature=np.zeros(n))
    with pytest.raises(ValueError, match="index field"):
        sim.set_fields(id=np.zeros(n))
    assert np.all(sim.field("density") != 0)


def test_set_fields_only_before_the_first_step(dam_break):
    sim = tidesph.Simulation(dam_break)
    sim.step()
    with pytest.raises(RuntimeError, match="before the first step"):
        sim.set_fields(density=np.full(sim.particle_count, 1000.0))


@pytest.mark.parametrize("scene", ["wcsph", "dfsph", "crowd"])
def test_setting_the_fields_a_run_starts_with_changes_nothing(dam_break, scenes_dir, scene):
    # The start run again from the same fields is the start of the scene: the same bits after 20 steps.
    def make():
        if scene == "crowd":
            return tidesph.Simulation(scenes_dir / "crowd_room_evacuation.json")
        dam_break["solver"] = {"scheme": scene}
        return tidesph.Simulation(dam_break)

    plain, edited = make(), make()
    names = [name for name in edited.field_names if name not in ("id", "phase")]
    edited.set_fields(**{name: np.array(edited.field(name)) for name in names})
    for sim in (plain, edited):
        for _ in range(20):
            sim.step()
    for name in plain.field_names:
        np.testing.assert_array_equal(np.array(plain.field(name)), np.array(edited.field(name)), err_msg=name)

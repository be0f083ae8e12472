"""The hydrostatic tank from Python: after settling, the pressure equals ρ0 g (H − y) within the
C++ test's bound (tests/wcsph_test.cpp, check_hydrostatic): in 5 horizontal bands, the band mean
within 2% of ρ0 g (H − ȳ) for every band lying entirely more than a kernel support below the free
surface, and |ρ/ρ0 − 1| < 1% everywhere. The probes read the same water (tests/probes_test.cpp): a pressure
probe ρ0 g depth within 2%, a water-height probe the surface within half a particle spacing."""

import numpy as np

import tidesph
from conftest import GRAVITY, hydrostatic_tank

HEIGHT = 0.5
REST_DENSITY = 1000.0


def test_tank_settles_to_hydrostatic_pressure():
    scene = hydrostatic_tank(height=HEIGHT, rows=25)
    scene["probes"] = [{"name": "p_bulk", "type": "pressure", "position": [0.25, 0.1]},
                       {"name": "height", "type": "water_height", "position": [0.25, 0]}]
    sim = tidesph.Simulation(scene)
    sim.run(7.0)  # the C++ test's settling time
    y = sim.field("position")[1]
    p = sim.field("pressure")
    rho = sim.field("density")

    bands = 5
    band = np.clip((y / HEIGHT * bands).astype(int), 0, bands - 1)
    support = 2.0 * sim.smoothing_length  # Wendland C2: support 2h
    checked = 0
    for k in range(bands):
        if (k + 1) * HEIGHT / bands > HEIGHT - support:
            break
        inside = band == k
        assert inside.any(), f"band {k} is empty"
        expected = REST_DENSITY * GRAVITY * (HEIGHT - y[inside].mean())
        assert abs(p[inside].mean() - expected) < 0.02 * expected, f"band {k}"
        checked += 1
    assert checked == 4  # 25 rows, h = 0.034 m: every band but the top one
    assert np.max(np.abs(rho / REST_DENSITY - 1)) < 0.01

    probes = sim.probes()
    expected = REST_DENSITY * GRAVITY * (HEIGHT - 0.1)
    assert abs(probes["p_bulk"] - expected) < 0.02 * expected
    assert abs(probes["height"] - HEIGHT) < 0.5 * scene["particle_spacing"]

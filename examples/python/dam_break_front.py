"""A dam break set up and run from Python (docs/python.md): a water column a wide and 2a high
collapses in a tank; its front position is recorded as it runs and plotted against Martin &
Moyce's (1952) dimensionless time, with matplotlib where it is installed.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dam_break_front.py
"""

import math
import sys

import numpy as np

import tidesph

GRAVITY = 9.81  # m/s²


def dam_break(a=0.1, columns=40):
    """The scene as a dict, with the keys of a scene file (docs/scenes.md)."""
    return {
        "dimension": 2,
        "particle_spacing": a / columns,
        "kernel": {"type": "wendland_c2", "smoothing_ratio": 1.7},
        "materials": [{"name": "water", "rest_density": 1000, "kinematic_viscosity": 1e-6,
                       "max_speed": math.sqrt(2 * GRAVITY * 2 * a)}],
        "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [a, 2 * a]}}],
        "walls": {"container": {"min": [0, 0], "max": [6 * a, 3 * a], "open_top": True}},
        "gravity": [0, -GRAVITY],
        "time": {"end": 1.0, "output_interval": 0.01},
    }


def front_history(a=0.1, columns=40, until_T=3.0, samples=30):
    """(T, Z): T = t sqrt(2g/a), Z = front / a, the front being the largest x of the water."""
    sim = tidesph.Simulation(dam_break(a, columns))
    time_scale = math.sqrt(a / (2 * GRAVITY))
    history = []
    for T in np.linspace(0, until_T, samples + 1):
        sim.run(T * time_scale)
        x = sim.field("position")[0]  # a view of the fluid's x array: no copy
        history.append((sim.time / time_scale, x.max() / a))
    return np.array(history), sim.statistics


def main():
    history, stats = front_history()
    for T, Z in history[::5]:
        print(f"T = {T:5.2f}   Z = {Z:5.2f}")
    print(f"{stats['steps']} steps, {stats['particle_steps_per_second']:.3g} particle-steps/s, "
          f"time step bound by {max(stats['limits'], key=stats['limits'].get)}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (apt-get install python3-matplotlib): no plot", file=sys.stderr)
        return
    figure, axes = plt.subplots(figsize=(5, 3.5))
    axes.plot(history[:, 0], history[:, 1], "o-", markersize=3, label="TideSPH")
    axes.set_xlabel(r"$T = t\,\sqrt{2g/a}$")
    axes.set_ylabel(r"$Z = x_\mathrm{front}/a$")
    axes.legend()
    figure.tight_layout()
    figure.savefig("dam_break_front.png", dpi=120)
    print("wrote dam_break_front.png")


if __name__ == "__main__":
    main()

"""Scenes the tidesph tests share. The module is found through PYTHONPATH (ctest sets it to the
build's python/ folder); TIDE_SCENES_DIR and TIDE_COMMAND (ctest sets them) name the shipped
scenes and the tide command."""

import copy
import math
import os
import pathlib

import numpy as np
import pytest

import tidesph

GRAVITY = 9.81  # m/s²
REAL = np.float64 if tidesph.precision == "double" else np.float32  # the build's tide::Real
EPS = float(np.finfo(REAL).eps)


def hydrostatic_tank(height=0.5, width=0.5, rows=25):
    """The 2D tank of the C++ hydrostatic test (tests/hydrostatic_scene.hpp): water H deep in a tank
    W wide, n rows over H, Wendland C2 with h = 1.7 Δx, summation density, α = 0.1, c0 = 10 sqrt(2 g H)."""
    spacing = height / rows
    return {
        "dimension": 2,
        "particle_spacing": spacing,
        "kernel": {"type": "wendland_c2", "smoothing_ratio": 1.7},
        "materials": [{"name": "water", "rest_density": 1000, "kinematic_viscosity": 1e-6,
                       "max_speed": math.sqrt(2 * GRAVITY * height)}],
        "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [width, height]}}],
        "walls": {"layers": 4, "slip": "no_slip",
                  "container": {"min": [0, 0], "max": [width, 1.5 * height], "open_top": True}},
        "gravity": [0, -GRAVITY],
        "solver": {"scheme": "wcsph", "alpha": 0.1},
        "time": {"end": 7.0, "output_interval": 0.1},
    }


def small_dam_break():
    """A 0.2 x 0.4 m water column in a 0.6 x 0.5 m tank, 1 cm spacing: 800 particles."""
    return {
        "dimension": 2,
        "particle_spacing": 0.01,
        "kernel": {"type": "wendland_c2", "smoothing_ratio": 1.7},
        "materials": [{"name": "water", "rest_density": 1000, "kinematic_viscosity": 1e-6, "max_speed": 3.0}],
        "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [0.2, 0.4]}}],
        "walls": {"container": {"min": [0, 0], "max": [0.6, 0.5], "open_top": True}},
        "gravity": [0, -GRAVITY],
        "time": {"end": 0.05, "output_interval": 0.01},
        "probes": [{"name": "p_floor", "type": "pressure", "position": [0.1, 0.02]},
                   {"name": "h_wall", "type": "water_height", "position": [0.55, 0]}],
    }


@pytest.fixture
def dam_break():
    return copy.deepcopy(small_dam_break())


@pytest.fixture
def scenes_dir():
    return pathlib.Path(os.environ.get("TIDE_SCENES_DIR", pathlib.Path(__file__).resolve().parents[2] / "scenes"))

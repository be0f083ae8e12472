#!/usr/bin/env python3
"""Writes the oil-displacement scenes after Zhou et al. 2010 (docs/multiphase.md, "Oil
displacement"): a square cavity joined by fractures, water injected through the fractures of a
pseudo-periodic channel (domain.inflow with phase "water"), the oil recovery of the cavity written
to recovery.csv (output.recovery).

The walls are the solid that is left when the open region (cavity and fractures, a union of
rectangles) is cut out of the domain: the solid is split into boxes on the grid of the
rectangles' edges, one wall obstacle per box. Lengths below are in millimetres, on the 1 mm
particle lattice; the scenes are in SI units.

The paper's set-up numbers were not at hand; every number here is this project's choice
(docs/multiphase.md, "Oil displacement"): a 20 mm cavity, 4 mm fractures, water (1000 kg/m3) and
a light oil (800 kg/m3) of equal dynamic viscosity 0.01 Pa s (ten times water's: the low-Reynolds
regime the paper's Morris viscosity is for; with water's own viscosity the weakly compressible
flow's pressure noise grew until the run failed), interfacial tension 0.01 N/m (capillary length
sqrt(sigma / (drho g)) = 2.3 mm), contact angle 45 degrees (water-wet) or 135 (oil-wet) through the
water, injection at 0.05 m/s.

The wetting family (oil_wetting_*) asks the wetting question where capillarity competes with
gravity: the middle-fractured cavity at h = 8 mm, horizontal, with thirty times the tension (0.3
N/m: capillary length 12.4 mm, cavity Bond number 2.6 instead of 78), 30 against 150 degrees
through the water, and unlike_attraction false, the pairwise strengths whose contact lines move
(docs/multiphase.md, "Open problems"). The kernel stays the study's (quintic, support 4.2
spacings): with the 5-spacing support of the contact-line test (h = 5/3 spacings) the pressure
noise of these runs grew from +-200 to +-2500 Pa after 1.2-1.5 s. docs/multiphase.md also has the
pair at 0.01 and 0.1 N/m, without gravity and with the 5-spacing support.

The capillary family (oil_capillary_*) asks the orientation question where the interface holds:
the nine middle-fractured cavities (heights 4, 8, 12 mm; horizontal, rising, falling) with water-wet
walls at the wetting pair's Bond 7.8 settings (0.1 N/m: capillary length 7.1 mm; 30 degrees through
the water, unlike_attraction false, 3 s) and three times the background pressure (7500 Pa). At the
study's 0.01 N/m the jets of the stepped fractures break the interface up and carry oil from above
the fracture's roof out (docs/multiphase.md, finding 1).

Run from the repository root: python3 scripts/oil_scenes.py (rewrites scenes/oil_*.json).
"""

import json
import pathlib

SPACING = 1.0  # mm
LAYERS = 5  # ceil(support / spacing): quintic spline, support 3 h, h = 1.4 spacings
CAVITY = (20.0, 40.0, 0.0, 20.0)  # x0, x1, y0, y1
LENGTH = 56.0  # the channel's period along x
FRACTURE = 4.0  # width of the fractures that carry the injected water
STEP_STUB = 4.0  # a stepped fracture runs this far at the cavity's height before it turns
STEP = 6.0  # and rises or falls this much
INJECTION = 0.05  # m/s in the inflow buffer
BUFFER = 9.0  # mm, two kernel supports
END_TIME = {"middle": 2.0, "upper": 2.0, "wetting": 3.0, "capillary": 3.0}
SOUND_SPEED = 8.0  # m/s: the gravity-driven flow in the cavity reaches 0.4 m/s
BACKGROUND_PRESSURE = 2500.0  # Pa: well above the pressure noise rho c |dv| of that flow
WATER_WET, OIL_WET = 45.0, 135.0  # static contact angle through the water, degrees
TENSION = 0.01  # N/m
SMOOTHING_RATIO = 1.4  # support 4.2 spacings, the pairwise model's least (at least 4)


class Wetting:
    """The wetting family's settings (module docstring)."""
    TENSION = 0.3  # N/m: cavity Bond number 200 * 9.81 * 0.02**2 / 0.3 = 2.6
    WATER_WET, OIL_WET = 30.0, 150.0


class Capillary:
    """The capillary family's settings (module docstring)."""
    TENSION = 0.1  # N/m: cavity Bond number 200 * 9.81 * 0.02**2 / 0.1 = 7.8
    WATER_WET = 30.0
    # Pa: the tension-driven flow reaches ~1 m/s, so rho c |dv| is ~8000 Pa; at the study's 2500 Pa
    # the pressure went negative (-5700 Pa by 0.3 s) and the falling 8 mm cavity's interface came
    # apart after 2 s (docs/multiphase.md, finding 1)
    BACKGROUND_PRESSURE = 7500.0


def solid_boxes(open_rects, domain):
    """Boxes that tile the domain minus the union of the open rectangles (x0, x1, y0, y1)."""
    x0, x1, y0, y1 = domain
    xs = sorted({x0, x1, *(v for r in open_rects for v in r[:2])})
    ys = sorted({y0, y1, *(v for r in open_rects for v in r[2:])})
    def is_open(cx, cy):
        return any(r[0] < cx < r[1] and r[2] < cy < r[3] for r in open_rects)
    rows = []  # per y interval: the x runs of solid cells
    for j in range(len(ys) - 1):
        cy = (ys[j] + ys[j + 1]) / 2
        runs, start = [], None
        for i in range(len(xs) - 1):
            solid = not is_open((xs[i] + xs[i + 1]) / 2, cy)
            if solid and start is None:
                start = xs[i]
            if not solid and start is not None:
                runs.append((start, xs[i]))
                start = None
        if start is not None:
            runs.append((start, xs[-1]))
        rows.append(runs)
    boxes, open_boxes = [], {}
    for j, runs in enumerate(rows):
        still = {}
        for run in runs:
            bottom = open_boxes.pop(run, ys[j])
            still[run] = bottom
        for run, bottom in open_boxes.items():
            boxes.append((run[0], run[1], bottom, ys[j]))
        open_boxes = still
    for run, bottom in open_boxes.items():
        boxes.append((run[0], run[1], bottom, ys[-1]))
    return sorted(boxes, key=lambda b: (b[2], b[0]))


def stepped_fracture(y, width, step):
    """A fracture from x = 0 to the cavity and from the cavity to x = LENGTH at height y (its
    floor) where it meets the cavity; with a step, STEP_STUB from the cavity it turns and runs
    `step` higher (or lower) to the channel's ends."""
    cx0, cx1 = CAVITY[:2]
    if step == 0:
        return [(0.0, cx0, y, y + width), (cx1, LENGTH, y, y + width)]
    outer = y + step
    low, high = min(y, outer), max(y, outer) + width
    return [
        (0.0, cx0 - STEP_STUB, outer, outer + width),
        (cx0 - STEP_STUB - width, cx0 - STEP_STUB, low, high),
        (cx0 - STEP_STUB, cx0, y, y + width),
        (cx1, cx1 + STEP_STUB, y, y + width),
        (cx1 + STEP_STUB, cx1 + STEP_STUB + width, low, high),
        (cx1 + STEP_STUB, LENGTH, outer, outer + width),
    ]


def mm(values):
    return [round(v / 1000, 6) for v in values]


def scene(name, open_rects, oil_rects, contact_angle, end_time, description, tension=TENSION, unlike_attraction=None,
          background_pressure=BACKGROUND_PRESSURE):
    """A scene; unlike_attraction None leaves the key to its default (true)."""
    surface_tension = {"model": "pairwise", "coefficient": tension, "contact_angle": contact_angle}
    if unlike_attraction is not None:
        surface_tension["unlike_attraction"] = unlike_attraction
    y_low = min(r[2] for r in open_rects) - LAYERS * SPACING
    y_high = max(r[3] for r in open_rects) + LAYERS * SPACING
    domain = (0.0, LENGTH, y_low, y_high)
    obstacles = [{"box": {"min": mm([b[0], b[2]]), "max": mm([b[1], b[3]])}} for b in solid_boxes(open_rects, domain)]
    fluid = [{"material": "water", "box": {"min": mm([0, y_low]), "max": mm([LENGTH, y_high])},
              "velocity": [INJECTION, 0]}]
    fluid += [{"material": "oil", "box": {"min": mm([r[0], r[2]]), "max": mm([r[1], r[3]])}} for r in oil_rects]
    cx0, cx1, cy0, cy1 = CAVITY
    return name, description, {
        "dimension": 2,
        "particle_spacing": SPACING / 1000,
        "kernel": {"type": "quintic_spline", "smoothing_ratio": SMOOTHING_RATIO},
        "domain": {"min": mm([0, y_low]), "max": mm([LENGTH, y_high]), "periodic": [True, False],
                   "inflow": {"velocity": INJECTION, "length": BUFFER / 1000, "phase": "water"}},
        "materials": [
            {"name": "water", "rest_density": 1000, "kinematic_viscosity": 1e-5, "sound_speed": SOUND_SPEED},
            {"name": "oil", "rest_density": 800, "kinematic_viscosity": 1.25e-5, "sound_speed": SOUND_SPEED},
        ],
        "fluid": fluid,
        "walls": {"layers": LAYERS, "slip": "no_slip", "obstacles": obstacles},
        "gravity": [0, -9.81],
        "solver": {"scheme": "wcsph", "equation_of_state": "linear", "density": "summation",
                   "viscosity": "laminar", "clamp_negative_pressure": False, "background_pressure": background_pressure,
                   "gravity_ramp_time": 0.1,
                   "surface_tension": surface_tension},
        "time": {"end": end_time, "output_interval": 0.1},
        "output": {"fields": ["position", "velocity", "pressure", "phase"], "probe_interval": 0.01,
                   "recovery": {"material": "oil", "region": {"min": mm([cx0, cy0]), "max": mm([cx1, cy1])}}},
    }


def middle_fractured(height, step, contact_angle):
    orientation = {0: "horizontal", STEP: "rising", -STEP: "falling"}[step]
    wetting = "water-wet" if contact_angle < 90 else "oil-wet"
    description = (f"Zhou et al. 2010 middle-fractured cavity (scripts/oil_scenes.py): a 20 mm oil-filled cavity, "
                   f"{FRACTURE:g} mm fractures meeting it {height:g} mm above its floor, {orientation}, "
                   f"{wetting} walls ({contact_angle:g} degrees through the water); water injected at "
                   f"{INJECTION:g} m/s")
    open_rects = [CAVITY] + stepped_fracture(height, FRACTURE, step)
    return scene(f"oil_middle_h{height:g}_{orientation}_{wetting.replace('-', '_')}", open_rects, [CAVITY],
                 contact_angle, END_TIME["middle"], description)


BOND = (1000 - 800) * 9.81 * ((CAVITY[3] - CAVITY[2]) / 1000) ** 2 / Wetting.TENSION


def wetting_pair(height):
    """The middle-fractured cavity at `height`, horizontal, water-wet and oil-wet, with the wetting
    family's tension and contact-line settings (module docstring)."""
    open_rects = [CAVITY] + stepped_fracture(height, FRACTURE, 0.0)
    scenes = []
    for contact_angle in (Wetting.WATER_WET, Wetting.OIL_WET):
        wetting = "water-wet" if contact_angle < 90 else "oil-wet"
        description = (f"Zhou et al. 2010 wetting comparison (scripts/oil_scenes.py): a 20 mm oil-filled cavity, "
                       f"{FRACTURE:g} mm fractures meeting it {height:g} mm above its floor, horizontal, {wetting} walls "
                       f"({contact_angle:g} degrees through the water), interfacial tension {Wetting.TENSION:g} N/m "
                       f"(cavity Bond number {BOND:.2g}), pairwise unlike_attraction false; water "
                       f"injected at {INJECTION:g} m/s")
        scenes.append(scene(f"oil_wetting_h{height:g}_horizontal_{wetting.replace('-', '_')}", open_rects, [CAVITY],
                            contact_angle, END_TIME["wetting"], description, Wetting.TENSION, False))
    return scenes


def capillary_family():
    """The middle-fractured cavities of every height and orientation, water-wet, at the capillary
    family's tension and contact-line settings (module docstring)."""
    bond = (1000 - 800) * 9.81 * ((CAVITY[3] - CAVITY[2]) / 1000) ** 2 / Capillary.TENSION
    scenes = []
    for height in (4.0, 8.0, 12.0):
        for step in (0.0, STEP, -STEP):
            orientation = {0: "horizontal", STEP: "rising", -STEP: "falling"}[step]
            description = (f"Zhou et al. 2010 orientation comparison where capillarity holds the interface "
                           f"(scripts/oil_scenes.py): a 20 mm oil-filled cavity, {FRACTURE:g} mm fractures meeting "
                           f"it {height:g} mm above its floor, {orientation}, water-wet walls "
                           f"({Capillary.WATER_WET:g} degrees through the water), interfacial tension "
                           f"{Capillary.TENSION:g} N/m (cavity Bond number {bond:.2g}), pairwise unlike_attraction "
                           f"false, background pressure {Capillary.BACKGROUND_PRESSURE:g} Pa; water injected at {INJECTION:g} m/s")
            open_rects = [CAVITY] + stepped_fracture(height, FRACTURE, step)
            scenes.append(scene(f"oil_capillary_h{height:g}_{orientation}_water_wet", open_rects, [CAVITY],
                                Capillary.WATER_WET, END_TIME["capillary"], description, Capillary.TENSION, False,
                                Capillary.BACKGROUND_PRESSURE))
    return scenes


def upper_fractured(width, contact_angle):
    """The water flows in a fracture above the cavity, joined to the cavity's ceiling by a vertical
    fracture of `width`, centred on it: the oil can leave only by gravity drainage through it."""
    cx0, cx1, cy0, cy1 = CAVITY
    centre = (cx0 + cx1) / 2
    throat = (centre - width / 2, centre + width / 2, cy1, cy1 + FRACTURE)
    channel = (0.0, LENGTH, cy1 + FRACTURE, cy1 + 2 * FRACTURE)
    wetting = "water-wet" if contact_angle < 90 else "oil-wet"
    description = (f"Zhou et al. 2010 upper-fractured cavity (scripts/oil_scenes.py): a 20 mm oil-filled cavity "
                   f"joined by a vertical fracture {width:g} mm wide and {FRACTURE:g} mm long to a {FRACTURE:g} mm "
                   f"fracture above it that carries water at {INJECTION:g} m/s; {wetting} walls")
    return scene(f"oil_upper_w{width:g}_{wetting.replace('-', '_')}", [CAVITY, throat, channel], [CAVITY, throat],
                 contact_angle, END_TIME["upper"], description)


def all_scenes():
    scenes = []
    for height in (4.0, 8.0, 12.0):
        for step in (0.0, STEP, -STEP):
            scenes.append(middle_fractured(height, step, WATER_WET))
    scenes.append(middle_fractured(8.0, 0.0, OIL_WET))
    for width in (2.0, 4.0, 6.0, 8.0, 10.0, 12.0):
        scenes.append(upper_fractured(width, WATER_WET))
    scenes += wetting_pair(8.0)
    scenes += capillary_family()
    return scenes


def main():
    directory = pathlib.Path(__file__).resolve().parent.parent / "scenes"
    for name, description, document in all_scenes():
        (directory / f"{name}.json").write_text(f"// {description}\n" + json.dumps(document, indent=1) + "\n")
        print(directory / f"{name}.json")


if __name__ == "__main__":
    main()

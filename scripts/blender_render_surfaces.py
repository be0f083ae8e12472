"""Renders the surface meshes of `tide surface` in Blender: water material, camera, sun, floor.

    blender -b --python scripts/blender_render_surfaces.py -- SURFACE_DIR OUT_DIR \
        [--frames A:B] [--size WxH] [--samples N]

SURFACE_DIR holds surface_NNNNNN.ply (tide surface RUN writes them to RUN/surface); each frame is
rendered with Cycles on the CPU (headless: no display or GPU needed) to OUT_DIR/blender_NNNNNN.png.
All meshes are imported first, so that the camera frames the fluid over the whole sequence, and
each is shown in its own frame only. The scene is z-up, as TideSPH's 3D scenes are. docs/rendering.md
says more.
"""

import argparse
import math
import os
import re
import sys

import bpy
from mathutils import Vector


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender -b --python blender_render_surfaces.py --")
    parser.add_argument("surface_dir")
    parser.add_argument("out_dir")
    parser.add_argument("--frames", default="", help="A:B, A:, :B or A (default: all)")
    parser.add_argument("--size", default="1280x720", help="WxH in pixels")
    parser.add_argument("--samples", type=int, default=32, help="Cycles samples per pixel")
    return parser.parse_args(argv)


def frame_files(surface_dir, frames):
    found = {}
    for name in os.listdir(surface_dir):
        match = re.fullmatch(r"surface_(\d{6,})\.ply", name)
        if match:
            found[int(match.group(1))] = os.path.join(surface_dir, name)
    first, _, last = frames.partition(":")
    low = int(first) if first else 0
    high = int(last) if last else (low if frames and ":" not in frames else math.inf)
    selected = sorted((n, path) for n, path in found.items() if low <= n <= high)
    if not selected:
        sys.exit(f"blender_render_surfaces: no surface_NNNNNN.ply in {surface_dir} within --frames '{frames}'")
    return selected


def import_ply(path):
    # From Blender 3.6 on the C++ importer wm.ply_import; before it the Python add-on's operator.
    if bpy.app.version >= (3, 6, 0):
        bpy.ops.wm.ply_import(filepath=path)
    else:
        bpy.ops.import_mesh.ply(filepath=path)
    return bpy.context.selected_objects[0]


def water_material():
    material = bpy.data.materials.new("water")
    material.use_nodes = True
    shader = material.node_tree.nodes["Principled BSDF"]
    shader.inputs["Base Color"].default_value = (0.55, 0.75, 0.95, 1.0)
    shader.inputs["Roughness"].default_value = 0.05
    shader.inputs["IOR"].default_value = 1.33
    transmission = "Transmission Weight" if "Transmission Weight" in shader.inputs else "Transmission"
    shader.inputs[transmission].default_value = 0.9
    return material


def bounds(objects):
    corners = [obj.matrix_world @ Vector(corner) for obj in objects for corner in obj.bound_box]
    low = Vector((min(c.x for c in corners), min(c.y for c in corners), min(c.z for c in corners)))
    high = Vector((max(c.x for c in corners), max(c.y for c in corners), max(c.z for c in corners)))
    return low, high


def stage(low, high):
    """Floor, sun, sky and a camera that sees the box [low, high] from the front, right and above."""
    centre, size = (low + high) / 2, (high - low).length
    bpy.ops.mesh.primitive_plane_add(size=4 * size, location=(centre.x, centre.y, low.z - 1e-3 * size))
    floor = bpy.context.active_object
    floor_material = bpy.data.materials.new("floor")
    floor_material.use_nodes = True
    floor_material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.6, 0.6, 0.6, 1.0)
    floor.data.materials.append(floor_material)

    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(40), math.radians(-20), math.radians(30)))
    bpy.context.active_object.data.energy = 3.0
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.8, 0.85, 0.9, 1.0)
    bpy.context.scene.world = world

    direction = Vector((0.6, -1.0, 0.7)).normalized()
    bpy.ops.object.camera_add(location=centre + 1.4 * size * direction)
    camera = bpy.context.active_object
    camera.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
    camera.data.lens = 35
    bpy.context.scene.camera = camera


def main():
    options = arguments()
    width, height = (int(v) for v in options.size.split("x"))
    files = frame_files(options.surface_dir, options.frames)
    os.makedirs(options.out_dir, exist_ok=True)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = options.samples
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"

    material = water_material()
    meshes = []
    for number, path in files:
        mesh = import_ply(path)
        mesh.data.materials.append(material)
        for polygon in mesh.data.polygons:
            polygon.use_smooth = True
        meshes.append((number, mesh))
    stage(*bounds([mesh for _, mesh in meshes]))

    for number, mesh in meshes:
        for _, other in meshes:
            other.hide_render = other is not mesh
        scene.render.filepath = os.path.join(options.out_dir, f"blender_{number:06d}.png")
        bpy.ops.render.render(write_still=True)
        print(f"blender_render_surfaces: wrote {scene.render.filepath}")


main()

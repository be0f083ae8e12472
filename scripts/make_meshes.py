#!/usr/bin/env python3
"""Writes the meshes shipped in scenes/meshes/ (docs/bodies.md, "Meshes"), each closed and with
outward (counter-clockwise seen from outside) triangles, in three formats: Wavefront OBJ, binary
STL and ASCII PLY.

  cylinder: radius 1, axis z from z = -2 to 2, 64 sides (a pillar in 3D; in 2D its section by
            z = 0 is a 64-gon of circumradius 1)
  wedge:    a triangular prism, the triangle (0, 0), (2, 0), (0, 1) in x, y, from z = -1 to 1
  sphere:   an icosphere of radius 1 (an icosahedron's faces split in four three times: 1280
            triangles)
  fan:      a stirrer about the z axis: a hub (a 32-sided cylinder of radius 0.25 from z = -0.3 to
            0.3) and four blades, each a box from radius 0.35 to 1, 0.4 wide and 0.2 thick,
            pitched 30 degrees about its radial axis; five closed shells that do not touch

Lengths are in file units; a scene scales and places them (the mesh keys). Run with
/usr/bin/python3 from the repository root; no packages beyond the standard library.
"""
import math
import pathlib
import struct

OUT = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "meshes"


def prism(outline, z0, z1):
    """A closed prism over a counter-clockwise outline: bottom, top and side quads split in two."""
    n = len(outline)
    vertices = [(x, y, z0) for x, y in outline] + [(x, y, z1) for x, y in outline]
    triangles = []
    for k in range(1, n - 1):  # caps as fans: the bottom seen from below, the top from above
        triangles.append((0, k + 1, k))
        triangles.append((n, n + k, n + k + 1))
    for k in range(n):
        j = (k + 1) % n
        triangles.append((k, j, n + j))
        triangles.append((k, n + j, n + k))
    return vertices, triangles


def cylinder(sides=64):
    outline = [(math.cos(2 * math.pi * k / sides), math.sin(2 * math.pi * k / sides)) for k in range(sides)]
    return prism(outline, -2.0, 2.0)


def wedge():
    return prism([(0.0, 0.0), (2.0, 0.0), (0.0, 1.0)], -1.0, 1.0)


def fan(blades=4, pitch_degrees=30.0):
    vertices, triangles = prism([(0.25 * math.cos(2 * math.pi * k / 32), 0.25 * math.sin(2 * math.pi * k / 32))
                                 for k in range(32)], -0.3, 0.3)
    pitch = math.radians(pitch_degrees)
    for b in range(blades):
        yaw = 2 * math.pi * b / blades
        blade, faces = prism([(0.35, -0.2), (1.0, -0.2), (1.0, 0.2), (0.35, 0.2)], -0.1, 0.1)
        offset = len(vertices)
        for x, y, z in blade:  # turned about the radial axis x by the pitch, then about z by the yaw
            y, z = y * math.cos(pitch) - z * math.sin(pitch), y * math.sin(pitch) + z * math.cos(pitch)
            vertices.append((x * math.cos(yaw) - y * math.sin(yaw), x * math.sin(yaw) + y * math.cos(yaw), z))
        triangles += [(i + offset, j + offset, k + offset) for i, j, k in faces]
    return vertices, triangles


def sphere(levels=3):
    g = (1 + math.sqrt(5)) / 2
    vertices = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
                (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]

    def unit(v):
        n = math.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    vertices = [unit(v) for v in vertices]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(vertices)
                vertices.append(unit(tuple(p + q for p, q in zip(vertices[a], vertices[b]))))
            return middle[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return vertices, faces


def write_obj(path, vertices, triangles):
    lines = [f"# {path.stem}, written by scripts/make_meshes.py"]
    lines += [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in triangles]
    path.write_text("\n".join(lines) + "\n")


def write_stl(path, vertices, triangles):
    header = f"{path.stem}, written by scripts/make_meshes.py".encode().ljust(80, b" ")
    records = [header, struct.pack("<I", len(triangles))]
    for triangle in triangles:
        corners = [vertices[i] for i in triangle]
        u = [corners[1][d] - corners[0][d] for d in range(3)]
        v = [corners[2][d] - corners[0][d] for d in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(sum(c * c for c in n)) or 1.0
        records.append(struct.pack("<3f", *(c / length for c in n)))
        for corner in corners:
            records.append(struct.pack("<3f", *corner))
        records.append(struct.pack("<H", 0))
    path.write_bytes(b"".join(records))


def write_ply(path, vertices, triangles):
    lines = ["ply", "format ascii 1.0", "comment written by scripts/make_meshes.py",
             f"element vertex {len(vertices)}", "property double x", "property double y", "property double z",
             f"element face {len(triangles)}", "property list uchar int vertex_indices", "end_header"]
    lines += [f"{x:.17g} {y:.17g} {z:.17g}" for x, y, z in vertices]
    lines += [f"3 {a} {b} {c}" for a, b, c in triangles]
    path.write_text("\n".join(lines) + "\n")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (vertices, triangles) in {"cylinder": cylinder(), "wedge": wedge(), "sphere": sphere(), "fan": fan()}.items():
        write_obj(OUT / f"{name}.obj", vertices, triangles)
        write_stl(OUT / f"{name}.stl", vertices, triangles)
        write_ply(OUT / f"{name}.ply", vertices, triangles)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""UV spheres and tori as Blender and similar modellers export them: rings of quads, each written as
two triangles split along the same diagonal, fans of triangles at a sphere's poles, float32 binary
STL (millimetres). A quad of a surface of revolution is an isosceles trapezoid, flat and cyclic in
exact arithmetic; with float corners it is neither, so its diagonal is a fold of the surface that may
not be Delaunay (README: known weaknesses of Steiner points, cones and tori). Deterministic: the same
bytes every run.

Usage: bench/make_uv_surfaces.py DIR    (then bench/run_cad.py DIR/*.stl)
"""
import math
import os
import sys

from run_cad import ROOT, rotation  # bench/run_cad.py: the parts placed at an angle

sys.path.insert(0, os.path.join(ROOT, "tests", "data", "scan"))
import make_scan_surfaces  # noqa: E402  (its binary STL writer)


def write_stl(path, triangles):
    """Triangles given by their corners' coordinates, as binary STL (float32)."""
    points = [p for t in triangles for p in t]
    make_scan_surfaces.write_stl(path, points, [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(len(triangles))],
                                 header=b"sweepcdt bench/make_uv_surfaces.py")


def turned(triangles, axis=(0.2, 0.9, 0.1), degrees=40.0):
    """The surface turned about `axis`, as an object placed at an angle is exported."""
    r = rotation(degrees, axis)
    return [tuple(tuple(sum(r[i][k] * p[k] for k in range(3)) for i in range(3)) for p in t) for t in triangles]


def uv_sphere(radius, segments, rings):
    """Blender's UV sphere: `segments` around, `rings` from pole to pole, the poles shared points."""
    def point(i, j):
        if j == 0:
            return (0.0, 0.0, radius)
        if j == rings:
            return (0.0, 0.0, -radius)
        i %= segments
        theta, phi = 2 * math.pi * i / segments, math.pi * j / rings
        return (radius * math.sin(phi) * math.cos(theta), radius * math.sin(phi) * math.sin(theta), radius * math.cos(phi))
    triangles = []
    for j in range(rings):
        for i in range(segments):
            a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
            if j > 0:
                triangles.append((a, d, b))
            if j < rings - 1:
                triangles.append((b, d, c))
    return triangles


def uv_torus(major, minor, segments, sides):
    """Blender's torus: `segments` around the axis, `sides` around the tube."""
    def point(i, j):
        i %= segments
        j %= sides
        theta, phi = 2 * math.pi * i / segments, 2 * math.pi * j / sides
        r = major + minor * math.cos(phi)
        return (r * math.cos(theta), r * math.sin(theta), minor * math.sin(phi))
    triangles = []
    for i in range(segments):
        for j in range(sides):
            a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
            triangles.append((a, b, d))
            triangles.append((b, c, d))
    return triangles


SURFACES = {
    "uv_sphere_32x16": lambda: uv_sphere(10.0, 32, 16),  # Blender's default
    "uv_sphere_64x32": lambda: uv_sphere(10.0, 64, 32),
    "uv_sphere_64x32_turned": lambda: turned(uv_sphere(10.0, 64, 32)),
    "uv_sphere_256x128": lambda: uv_sphere(10.0, 256, 128),
    "uv_sphere_1024x256": lambda: uv_sphere(10.0, 1024, 256),
    "uv_torus_48x12": lambda: uv_torus(10.0, 2.5, 48, 12),  # Blender's default
    "uv_torus_192x48_turned": lambda: turned(uv_torus(10.0, 2.5, 192, 48)),
}


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    for name, make in SURFACES.items():
        path = os.path.join(out_dir, name + ".stl")
        write_stl(path, make())
        print(path)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

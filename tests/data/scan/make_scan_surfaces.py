#!/usr/bin/env python3
"""Scan- and print-like closed surfaces, made here (no file committed): what 3D scanners and
voxel-based tools hand a user, as opposed to the CAD tessellations of tests/data/cad.

  - blobs_N.stl / blobs_N.obj: marching tetrahedra (Kuhn's six per grid cube) over an N^3 grid of a
    smooth implicit solid — four metaballs and a torus through them (genus 1). Such surfaces are
    full of thin and tiny triangles (edges cut close to a grid point), as isosurfaces of scans are.
    STL: binary float32; OBJ: 6 decimals (double coordinates, as many exporters write them).
  - gyroid_N.stl: the same over a gyroid sheet cut by a ball (a lattice infill, high genus).
  - shell_L.obj: an icosphere of level L displaced by smooth bumps, 6 decimals (a smooth organic
    scan: long runs of nearly cospherical points).

Usage: make_scan_surfaces.py OUT_DIR [--grid N] [--level L]
Each surface is closed, manifold and oriented outward (`sweepcdt info` says valid).
"""
import argparse
import math
import os
import struct


def metaballs(x, y, z):
    s = 0.0
    for cx, cy, cz, r in ((0.3, 0.5, 0.5, 0.18), (0.62, 0.45, 0.5, 0.22), (0.5, 0.7, 0.35, 0.15), (0.45, 0.3, 0.68, 0.14)):
        s += r * r / ((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2 + 1e-9)
    q = math.hypot(x - 0.5, z - 0.5) - 0.3
    s += 0.012 / (q * q + (y - 0.5) ** 2 + 1e-9)
    return 1.0 - s


def gyroid(x, y, z):
    k = 4 * math.pi
    g = math.sin(k * x) * math.cos(k * y) + math.sin(k * y) * math.cos(k * z) + math.sin(k * z) * math.cos(k * x)
    ball = (x - 0.5) ** 2 + (y - 0.5) ** 2 + (z - 0.5) ** 2 - 0.4 ** 2
    return max(abs(g) - 0.5, 12 * ball)


def marching_tetrahedra(f, n, size=100.0):
    """Points and outward triangles of {f < 0} over an n^3 grid of [0, 1]^3, scaled to `size`."""
    h = 1.0 / n
    values = {}

    def value(p):
        if p not in values:
            v = f(p[0] * h, p[1] * h, p[2] * h)
            values[p] = v if v != 0 else 1e-12  # no grid point on the surface: no degenerate triangle
        return values[p]

    index, points, triangles = {}, [], []

    def cut(a, b):  # the surface's point on grid edge ab (one end inside, one outside), shared by the cells around it
        key = (min(a, b), max(a, b))
        if key not in index:
            # Kept 0.2% of the edge away from its ends: cuts of the edges around a grid point where f is
            # nearly 0 would otherwise round to one point (a pinch). Any t in (0, 1) keeps the surface
            # embedded (each piece stays inside its own tetrahedron); slivers remain.
            t = min(max(value(a) / (value(a) - value(b)), 0.002), 0.998)
            index[key] = len(points)
            points.append(tuple((a[c] + t * (b[c] - a[c])) * h * size for c in range(3)))
        return index[key]

    def emit(tri, inside):  # oriented away from a point inside
        p = [points[i] for i in tri]
        u = [p[1][c] - p[0][c] for c in range(3)]
        w = [p[2][c] - p[0][c] for c in range(3)]
        normal = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        if sum(normal[c] * (p[0][c] - inside[c] * h * size) for c in range(3)) < 0:
            tri = (tri[0], tri[2], tri[1])
        triangles.append(tri)

    orders = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for i in range(n):
        for j in range(n):
            for k in range(n):
                for order in orders:  # Kuhn's tetrahedra: the paths from the cube's corner (i, j, k) to the opposite one
                    corner = [i, j, k]
                    tet = [tuple(corner)]
                    for axis in order:
                        corner[axis] += 1
                        tet.append(tuple(corner))
                    inside = [p for p in tet if value(p) < 0]
                    outside = [p for p in tet if value(p) >= 0]
                    if not inside or not outside:
                        continue
                    if len(inside) == 1:
                        emit(tuple(cut(inside[0], b) for b in outside), inside[0])
                    elif len(outside) == 1:
                        centre = [sum(p[c] for p in inside) / 3 for c in range(3)]
                        emit(tuple(cut(a, outside[0]) for a in inside), centre)
                    else:
                        (a0, a1), (b0, b1) = inside, outside
                        centre = [(a0[c] + a1[c]) / 2 for c in range(3)]
                        q00, q01, q10, q11 = cut(a0, b0), cut(a0, b1), cut(a1, b0), cut(a1, b1)
                        emit((q00, q01, q11), centre)
                        emit((q00, q11, q10), centre)
    return points, triangles


def displaced_icosphere(level, size=50.0):
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1),
              (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    triangles = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
                 (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        middle, finer = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(points[a][c] + points[b][c]) / 2 for c in range(3)]
                norm = math.sqrt(sum(x * x for x in p))
                points.append(tuple(x / norm for x in p))
                middle[key] = len(points) - 1
            return middle[key]

        for a, b, c in triangles:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        triangles = finer
    bumped = []
    for x, y, z in points:
        r = 1 + 0.15 * math.sin(3 * x + 1) * math.cos(2 * y) + 0.08 * math.sin(5 * z + 2 * x) + 0.03 * math.cos(9 * y - 4 * z)
        bumped.append((size * 1.3 * r * x, size * r * y, size * 0.8 * r * z))
    return bumped, triangles


def write_stl(path, points, triangles, header=b"scan-like surface"):
    """Binary STL (float32) of indexed triangles; bench/make_uv_surfaces.py writes its surfaces with it."""
    with open(path, "wb") as out:
        out.write(header.ljust(80, b" "))
        out.write(struct.pack("<I", len(triangles)))
        for tri in triangles:
            out.write(struct.pack("<3f", 0, 0, 0))
            for v in tri:
                out.write(struct.pack("<3f", *points[v]))
            out.write(b"\0\0")


def write_obj(path, points, triangles):
    with open(path, "w") as out:
        out.writelines("v %.6f %.6f %.6f\n" % p for p in points)
        out.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in triangles)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out_dir")
    parser.add_argument("--grid", type=int, default=16, help="marching grid cells per side (default 16)")
    parser.add_argument("--level", type=int, default=4, help="icosphere subdivisions of the shell (default 4)")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    n = args.grid
    blobs = marching_tetrahedra(metaballs, n)
    write_stl(os.path.join(args.out_dir, "blobs_%d.stl" % n), *blobs)
    write_obj(os.path.join(args.out_dir, "blobs_%d.obj" % n), *blobs)
    write_stl(os.path.join(args.out_dir, "gyroid_%d.stl" % n), *marching_tetrahedra(gyroid, n))
    write_obj(os.path.join(args.out_dir, "shell_%d.obj" % args.level), *displaced_icosphere(args.level))


if __name__ == "__main__":
    main()

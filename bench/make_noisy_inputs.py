#!/usr/bin/env python3
"""Surfaces whose coordinates are doubles off their ideal places, for measuring Steiner points that
rounding puts off their segments (README, "Session 18"): written as OFF into OUT_DIR.

  - *_noise*.off: the CAD parts of tests/data/cad with CAD rounding noise (run_cad.py's NOISY list,
    made by steiner_bench --cad-noise, as the tests make them);
  - *_jittered.off: a surface jittered by 2e-3 in each coordinate (seeded), as a scan's noise:
    tests/data/cad/vase_std.stl and, when given --more DIR (bench/make_more_cad_parts.py's output),
    a few more;
  - *_rotd.off: binary-STL parts turned by 23 degrees about (0.3, 0.5, 0.8) in double precision (an
    assembly exported as OBJ/OFF text; run_cad.py --rotated writes float32 STL instead).

Usage: bench/make_noisy_inputs.py OUT_DIR [--build BUILD] [--more DIR]
Then:  bench/compare_counts.sh SWEEPCDT_BEFORE SWEEPCDT_AFTER OUT_DIR/*.off
"""
import argparse
import os
import random
import struct
import subprocess

from run_cad import NOISY, ROOT, rotation

CAD = os.path.join(ROOT, "tests", "data", "cad")
ROTATED = ["pipe_tee_std.stl", "flange_std.stl", "plate_with_holes_std.stl", "box_fused_sphere_fine.stl", "gear_fine.stl",
           "two_bodies_fine.stl", "vase_std.stl"]
MORE = ["bolt_std.stl", "boss_plate_std.stl", "shaft_std.stl", "knob_fine.stl"]


def read_binary_stl(path):
    """Welded points (exact float32 values) and triangles."""
    data = open(path, "rb").read()
    count = struct.unpack_from("<I", data, 80)[0]
    index, points, triangles = {}, [], []
    for i in range(count):
        v = struct.unpack_from("<12f", data, 84 + 50 * i)
        ids = []
        for k in range(1, 4):
            p = v[3 * k:3 * k + 3]
            if p not in index:
                index[p] = len(points)
                points.append(p)
            ids.append(index[p])
        triangles.append(ids)
    return points, triangles


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(triangles)} 0\n")
        f.writelines("%r %r %r\n" % tuple(p) for p in points)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in triangles)


def turned(points):
    r = rotation()  # as run_cad.py --rotated, in double precision
    return [[sum(r[row][k] * p[k] for k in range(3)) for row in range(3)] for p in points]


def jittered(points, seed=1, amplitude=2e-3):
    rng = random.Random(seed)
    return [[c + rng.uniform(-amplitude, amplitude) for c in p] for p in points]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--more", help="bench/make_more_cad_parts.py's output folder")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    bench = os.path.join(args.build, "bench", "steiner_bench")
    for name, fraction in NOISY:
        out = os.path.join(args.out, f"{name.rsplit('.', 1)[0]}_noise{fraction}.off")
        subprocess.run([bench, os.path.join(CAD, name), "--cad-noise", str(fraction), "--off", out, "--count-only"],
                       check=True, stdout=subprocess.DEVNULL)
    sources = [os.path.join(CAD, name) for name in ROTATED]
    if args.more:
        sources += [os.path.join(args.more, name) for name in MORE]
    for path in sources:
        stem = os.path.basename(path).rsplit(".", 1)[0]
        points, triangles = read_binary_stl(path)
        write_off(os.path.join(args.out, f"{stem}_rotd.off"), turned(points), triangles)
        if stem == "vase_std" or args.more:
            write_off(os.path.join(args.out, f"{stem}_jittered.off"), jittered(points), triangles)
    print(f"written to {args.out}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""`sweepcdt check` on meshes with many fold points on large facets (issue 18): the fold-point search
of core/src/verify/surface_points.cpp. A mesh made with --facets triangles and checked as coplanar
has its Steiner points on input edges inside the coplanar facets, each a fold point of its facet:

  - fan: a slab [0,100]^2 x [0,10] whose top face is a fan of 4m long thin triangles from its
    centre (written here; --fan M, default 25: 3948 Steiner points);
  - plate_with_holes_std.stl (tests/data/cad; 15834 Steiner points).

Prints, per mesh, the Steiner points and the median wall-clock seconds of --repeat runs of
`check --facets coplanar -q` for each build given (e.g. main's build and this one's).

Usage: bench/run_check_folds.py [--repeat N] [--fan M] [--timeout S] BUILD [BUILD...]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def fan_slab(m, path):
    L, H = 100.0, 10.0
    pts, tris = [], []

    def point(x, y, z):
        pts.append((x, y, z))
        return len(pts) - 1

    ring = []  # the top face's boundary, counterclockwise seen from above
    for k in range(4 * m):
        side, i = divmod(k, m)
        t = L * i / m
        ring.append(point(*[(t, 0), (L, t), (L - t, L), (0, L - t)][side], H))
    centre = point(L / 2, L / 2, H)
    b = [point(0, 0, 0), point(L, 0, 0), point(L, L, 0), point(0, L, 0)]
    tris += [(centre, ring[k], ring[(k + 1) % (4 * m)]) for k in range(4 * m)]
    tris += [(b[0], b[1], b[2]), (b[0], b[2], b[3])]
    for side in range(4):  # each side a fan from its first bottom corner
        top = [ring[(side * m + i) % (4 * m)] for i in range(m + 1)]
        tris.append((b[side], b[(side + 1) % 4], top[m]))
        tris += [(b[side], top[i + 1], top[i]) for i in range(m)]

    def outward(t):  # the slab is convex: away from its centre
        a, p, q = (pts[v] for v in t)
        u = [p[i] - a[i] for i in range(3)]
        w = [q[i] - a[i] for i in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        return t if sum(n[i] * (a[i] - (L / 2, L / 2, H / 2)[i]) for i in range(3)) > 0 else (t[0], t[2], t[1])

    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        f.writelines("%.17g %.17g %.17g\n" % p for p in pts)
        f.writelines("3 %d %d %d\n" % outward(t) for t in tris)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("builds", nargs="+", metavar="BUILD")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--fan", type=int, default=25)
    parser.add_argument("--timeout", type=float, default=900, help="seconds per check run (then reported as > S)")
    args = parser.parse_args()
    cli = [os.path.join(b, "plugin", "cli", "sweepcdt") for b in args.builds]
    with tempfile.TemporaryDirectory() as work:
        fan = os.path.join(work, "fan%d.off" % args.fan)
        fan_slab(args.fan, fan)
        inputs = [fan, os.path.join(ROOT, "tests", "data", "cad", "plate_with_holes_std.stl")]
        print("| mesh (--facets triangles, checked as coplanar) | Steiner points | " + " | ".join(args.builds) + " |")
        print("|---|---|" + "---|" * len(cli))
        for surface in inputs:
            mesh = os.path.join(work, os.path.splitext(os.path.basename(surface))[0] + ".node")
            made = subprocess.run([cli[-1], "mesh", surface, "--facets", "triangles", "-o", mesh], capture_output=True,
                                  text=True, check=True)
            made = made.stdout + made.stderr  # "IN -> OUT: T tetrahedra, S Steiner points (...)"
            steiner = int(made.split(" Steiner points")[0].split()[-1])
            os.remove(mesh[:-5] + ".face")  # no face ids: a triangles mesh passes as coplanar without them
            cells = []
            for exe in cli:
                times = []
                for _ in range(args.repeat):
                    start = time.monotonic()
                    try:
                        subprocess.run([exe, "check", surface, mesh, "--facets", "coplanar", "-q"], check=True, timeout=args.timeout)
                    except subprocess.TimeoutExpired:
                        times = None
                        break
                    times.append(time.monotonic() - start)
                cells.append("> %g s" % args.timeout if times is None else "%.2f s" % statistics.median(times))
            print("| %s | %d | %s |" % (os.path.basename(surface), steiner, " | ".join(cells)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()

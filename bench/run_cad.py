#!/usr/bin/env python3
"""CAD parts and the shared meshes: sweepcdt's default command against TetGen on the same surfaces,
in the same run (issue 13). For each input: Steiner points, wall-clock seconds and peak memory of the
whole process (reading and writing included) for

  - `sweepcdt IN -o OUT.mesh` with the default options, and with --facets triangles when the default
    merges coplanar facets (so both of sweepcdt's modes are measured);
  - `tetgen -pQ` (merges coplanar facets within its tolerance: compare with coplanar facets) and
    `tetgen -pQM` (keeps every input triangle: compare with --facets triangles);

and the ratios. Medians of --repeat runs (default 1). Prints a Markdown table and the totals.

Usage: bench/run_cad.py [--build BUILD] [--repeat N] [--noise | --rotated | --more | --scad | --scan | --decimated] [FILE...]
       bench/run_cad.py --before BUILD_BEFORE [--build BUILD] [--repeat N] [FILE...]
  (default files: tests/data/cad/*.stl, *.obj, *.ply and the closed shared meshes)
  --noise: instead, CAD parts with rounding noise added (NOISY: the cases of
           tests/integration/steiner_vs_tetgen_test.cpp and more; steiner_bench --cad-noise makes them)
  --rotated: instead, the clean binary-STL parts turned by 23 degrees about (0.3, 0.5, 0.8) and
           written again as float32 STL, as an exporter writes a part placed at an angle: no face is
           then exactly flat (ROTATED)

  --scad: instead, the OpenSCAD parts of tests/data/scad exported by `openscad -o PART.stl` (ASCII
           STL with 6 significant digits, as 3D-print models are shared: double coordinates)
  --scan: instead, surfaces like scans' (tests/data/scan/make_scan_surfaces.py): marching-tetrahedra
           isosurfaces (metaballs, a gyroid lattice; slivers) at grids 16 and 40, a bumpy shell
  --decimated: instead, the fine CAD parts of tests/data/cad decimated to 10% and 30% by MeshLab's
           quadric edge collapse (bench/make_decimated_surfaces.py), as MeshLab users simplify surfaces

With --before, only the default command is timed, of both builds in turn (before, after, before,
after, ... --repeat pairs, default 5): per input the median seconds of each and the median of the
pairwise ratios after/before, which holds up on a shared machine better than two separate medians.
"""
import argparse
import glob
import json
import math
import os
import resource
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data")
SHARED_CLOSED = ["off/femur.off", "off/icosahedron.off", "stl_ascii/t13_data_ascii.stl", "stl_binary/spot.stl",
                 "stl_binary/torus.stl", "stl_ascii/gearwheel_ascii.stl", "stl_binary/thingi_1706459.stl",
                 "drc/knot1.drc", "glb/moon.glb", "drc/cube_att.drc"]
TIMEOUT = 600
# (part of tests/data/cad, fraction of coordinates moved by a few ulps): CAD exports' rounding noise.
NOISY = [("bracket_fine.stl", 0.5), ("flange_fine.stl", 0.1), ("flange_fine.stl", 0.5), ("two_bodies_fine.stl", 0.5),
         ("pipe_tee_std.stl", 0.1), ("plate_with_holes_std.stl", 0.5), ("plate_with_holes_fine.stl", 0.1),
         ("box_fused_sphere_fine.stl", 0.5), ("filleted_box_fine.stl", 1.0), ("gear_fine.stl", 0.5),
         ("hex_nut_fine.stl", 0.5), ("rotated_box_fine.stl", 0.5)]

ROTATED = ["bracket_std.stl", "filleted_box_std.stl", "flange_std.stl", "flange_fine.stl", "gear_fine.stl",
           "hex_nut_fine.stl", "plate_with_holes_std.stl", "plate_with_holes_fine.stl", "two_bodies_fine.stl"]


def rotation(degrees=23.0, axis=(0.3, 0.5, 0.8)):
    """The matrix turning by `degrees` about `axis` (Rodrigues): a part placed at an angle."""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1 - c
    return [[c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t]]


def rotated_stl(source, target, degrees=23.0, axis=(0.3, 0.5, 0.8)):
    """Binary STL `source` turned about `axis` through the origin, written as binary STL (float32)."""
    with open(source, "rb") as f:
        data = f.read()
    count = struct.unpack_from("<I", data, 80)[0]
    if len(data) != 84 + 50 * count:
        raise ValueError(f"{source}: not a binary STL")
    r = rotation(degrees, axis)
    out = bytearray(data[:84])
    for i in range(count):
        v = struct.unpack_from("<12f", data, 84 + 50 * i)
        corners = [v[3 * k:3 * k + 3] for k in range(1, 4)]
        turned = [sum(r[row][col] * p[col] for col in range(3)) for p in corners for row in range(3)]
        out += struct.pack("<12f", 0, 0, 0, *turned) + b"\0\0"
    with open(target, "wb") as f:
        f.write(out)


def timed(cmd, cwd):
    """(ok, seconds, peak MiB) of one run of cmd under /usr/bin/time; timed.cpu: its CPU seconds."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "%M"] + cmd, cwd=cwd, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return False, float(TIMEOUT), 0.0
    seconds = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    timed.cpu = (after.ru_utime + after.ru_stime) - (usage.ru_utime + usage.ru_stime)
    lines = p.stderr.strip().splitlines()
    peak = int(lines[-1]) / 1024 if lines and lines[-1].isdigit() else 0.0
    return p.returncode == 0, seconds, peak


def run_sweepcdt(cli, path, work, extra):
    out = os.path.join(work, "out.mesh")
    stats = os.path.join(work, "stats.json")
    ok, seconds, peak = timed([cli, path, "-o", out, "--quiet", "--stats", stats] + extra, work)
    points, message = None, ""
    if os.path.exists(stats):
        with open(stats) as f:
            entry = json.load(f)["files"][0]
        points = entry.get("steiner_points") if ok else None
        message = entry.get("message", "")
    for f in (out, stats):
        if os.path.exists(f):
            os.remove(f)
    return {"ok": ok, "seconds": seconds, "cpu": timed.cpu, "peak": peak, "points": points, "message": message}


def run_tetgen(work, switches, input_points):
    """tetgen on work/in.off (the welded surface steiner_bench wrote)."""
    ok, seconds, peak = timed(["tetgen", switches, "in.off"], work)
    node = os.path.join(work, "in.1.node")
    points = None
    if ok and os.path.exists(node):
        with open(node) as f:
            points = int(f.readline().split()[0]) - input_points
    for f in os.listdir(work):
        if f.startswith("in.1."):
            os.remove(os.path.join(work, f))
    return {"ok": ok and points is not None, "seconds": seconds, "peak": peak, "points": points}


def median_run(repeat, fn):
    runs = [fn() for _ in range(repeat)]
    best = runs[0]
    best["seconds"] = statistics.median(r["seconds"] for r in runs)
    best["peak"] = statistics.median(r["peak"] for r in runs)
    return best


def cell(r):
    if not r["ok"]:
        return "fails", f"{r['seconds']:.2f}", ""
    return str(r["points"]), f"{r['seconds']:.2f}", f"{r['peak']:.0f}"


def paired(before_cli, cli, files, pairs):
    """Default command of two builds in turn; per input the median wall and CPU seconds of each and
    the medians of the pairwise ratios after/before (CPU time is the steadier on a loaded machine)."""
    print("| input | before wall s | after wall s | wall after/before | before CPU s | after CPU s | "
          "CPU after/before (min–max of pairs) | exit before/after |")
    print("|---|---|---|---|---|---|---|---|")
    walls, cpus = [], []
    with tempfile.TemporaryDirectory() as work:
        for path in files:
            a, b = [], []
            for _ in range(pairs):
                b.append(run_sweepcdt(before_cli, path, work, []))
                a.append(run_sweepcdt(cli, path, work, []))
            wall = [x["seconds"] / y["seconds"] for x, y in zip(a, b)]
            cpu = [x["cpu"] / y["cpu"] for x, y in zip(a, b)]
            walls.append(statistics.median(wall))
            cpus.append(statistics.median(cpu))
            med = lambda runs, key: statistics.median(r[key] for r in runs)
            print(f"| {os.path.basename(path)} | {med(b, 'seconds'):.3f} | {med(a, 'seconds'):.3f} | {walls[-1]:.2f}x | "
                  f"{med(b, 'cpu'):.3f} | {med(a, 'cpu'):.3f} | {cpus[-1]:.2f}x ({min(cpu):.2f}–{max(cpu):.2f}) | "
                  f"{'ok' if b[0]['ok'] else 'fails'}/{'ok' if a[0]['ok'] else 'fails'} |", flush=True)
    print()
    print(f"geometric means over {len(files)} inputs: wall {statistics.geometric_mean(walls):.3f}x, "
          f"CPU {statistics.geometric_mean(cpus):.3f}x")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--before", help="a second build: time the default command of both, paired")
    ap.add_argument("--repeat", type=int)
    ap.add_argument("--noise", action="store_true", help="CAD parts with rounding noise (NOISY)")
    ap.add_argument("--rotated", action="store_true", help="CAD parts turned by 23 degrees (ROTATED)")
    ap.add_argument("--more", action="store_true", help="more FreeCAD parts (bench/make_more_cad_parts.py)")
    ap.add_argument("--scad", action="store_true", help="OpenSCAD parts (tests/data/scad), exported by openscad")
    ap.add_argument("--scan", action="store_true", help="scan-like surfaces (tests/data/scan/make_scan_surfaces.py)")
    ap.add_argument("--decimated", action="store_true", help="CAD parts decimated by MeshLab (bench/make_decimated_surfaces.py)")
    ap.add_argument("files", nargs="*")
    args = ap.parse_args()
    args.build = os.path.abspath(args.build)
    cli = os.path.join(args.build, "plugin", "cli", "sweepcdt")
    converter = os.path.join(args.build, "bench", "steiner_bench")
    files = args.files or sorted(glob.glob(os.path.join(ROOT, "tests", "data", "cad", "*.stl")) +
                                 glob.glob(os.path.join(ROOT, "tests", "data", "cad", "*.obj")) +
                                 glob.glob(os.path.join(ROOT, "tests", "data", "cad", "*.ply"))) + \
        [os.path.join(SHARED, f) for f in SHARED_CLOSED if os.path.exists(os.path.join(SHARED, f))]
    noisy_dir = tempfile.TemporaryDirectory()
    if args.noise:
        files = []
        for name, fraction in NOISY:
            stem = f"{os.path.splitext(name)[0]}_noise{fraction}"
            path = os.path.join(noisy_dir.name, stem + ".off")
            subprocess.run([converter, os.path.join(ROOT, "tests", "data", "cad", name), "--cad-noise", str(fraction),
                            "--off", path, "--count-only"], check=True, capture_output=True)
            files.append(path)
    if args.rotated:
        files = []
        for name in ROTATED:
            path = os.path.join(noisy_dir.name, name.replace(".stl", "_rotated.stl"))
            rotated_stl(os.path.join(ROOT, "tests", "data", "cad", name), path)
            files.append(path)
    if args.more:
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "bench", "make_more_cad_parts.py"), noisy_dir.name],
                       check=True, capture_output=True)
        files = sorted(glob.glob(os.path.join(noisy_dir.name, "*.stl")))
    if args.scad:
        files = []
        for source in sorted(glob.glob(os.path.join(ROOT, "tests", "data", "scad", "*.scad"))):
            path = os.path.join(noisy_dir.name, os.path.basename(source).replace(".scad", ".stl"))
            subprocess.run(["openscad", "-o", path, source], check=True, capture_output=True)
            files.append(path)
    if args.scan:
        make = os.path.join(ROOT, "tests", "data", "scan", "make_scan_surfaces.py")
        for grid, level in ((16, 4), (40, 6)):
            subprocess.run(["/usr/bin/python3", make, noisy_dir.name, "--grid", str(grid), "--level", str(level)], check=True,
                           capture_output=True)
        files = sorted(glob.glob(os.path.join(noisy_dir.name, "*.stl")) + glob.glob(os.path.join(noisy_dir.name, "*.obj")))
    if args.decimated:
        made = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "bench", "make_decimated_surfaces.py"), noisy_dir.name, "--cli", cli],
                              check=True, capture_output=True, text=True)
        files = made.stdout.splitlines()
    if args.before:
        paired(os.path.join(os.path.abspath(args.before), "plugin", "cli", "sweepcdt"), cli, files, args.repeat or 5)
        return
    args.repeat = args.repeat or 1
    if not shutil.which("tetgen"):
        sys.exit("tetgen not found (scripts/setup.sh installs it)")
    print("| input | triangles | sweepcdt default: points | s | MiB | --facets triangles: points | s | "
          "tetgen -pQ: points | s | MiB | tetgen -pQM: points | s | points default/-pQ | time default/-pQ | memory default/-pQ |")
    print("|" + "---|" * 16)
    totals = {"default": 0, "triangles": 0, "pQ": 0, "pQM": 0}
    failures = {"default": 0, "triangles": 0, "pQ": 0, "pQM": 0}
    with tempfile.TemporaryDirectory() as work:
        for path in files:
            # TetGen reads the welded surface sweepcdt sees, as OFF (steiner_bench --off writes it).
            info = subprocess.run([converter, path, "--off", os.path.join(work, "in.off"), "--count-only"],
                                  capture_output=True, text=True)
            try:
                counts = json.loads(info.stdout)
            except json.JSONDecodeError:
                print(f"| {os.path.basename(path)} | unreadable: {info.stderr.strip()[:80]} |")
                continue
            default = median_run(args.repeat, lambda: run_sweepcdt(cli, path, work, []))
            triangles = median_run(args.repeat, lambda: run_sweepcdt(cli, path, work, ["--facets", "triangles"]))
            pq = median_run(args.repeat, lambda: run_tetgen(work, "-pQ", counts["points"]))
            pqm = median_run(args.repeat, lambda: run_tetgen(work, "-pQM", counts["points"]))
            for key, r in (("default", default), ("triangles", triangles), ("pQ", pq), ("pQM", pqm)):
                if r["ok"]:
                    totals[key] += r["points"]
                else:
                    failures[key] += 1
            d, t, q, m = cell(default), cell(triangles), cell(pq), cell(pqm)
            ratio = lambda a, b, fmt: fmt.format(a / b) if b else "—"
            both = default["ok"] and pq["ok"]
            print(f"| {os.path.basename(path)} | {counts['triangles']} | {d[0]} | {d[1]} | {d[2]} | {t[0]} | {t[1]} | "
                  f"{q[0]} | {q[1]} | {q[2]} | {m[0]} | {m[1]} | "
                  f"{ratio(default['points'], pq['points'], '{:.2f}') if both else '—'} | "
                  f"{ratio(default['seconds'], pq['seconds'], '{:.1f}x') if both else '—'} | "
                  f"{ratio(default['peak'], pq['peak'], '{:.2f}') if both else '—'} |", flush=True)
    print()
    print(f"Steiner points in total (failures): sweepcdt default {totals['default']} ({failures['default']}), "
          f"--facets triangles {totals['triangles']} ({failures['triangles']}), tetgen -pQ {totals['pQ']} ({failures['pQ']}), "
          f"tetgen -pQM {totals['pQM']} ({failures['pQM']})")


if __name__ == "__main__":
    main()

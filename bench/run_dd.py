#!/usr/bin/env python3
"""The sweeps in D = 4 and 5 against CGAL's d-dimensional Delaunay triangulation (Epick_d) on the same
random points in the unit cube (issue 16: "d = 4, 5 sweeps: no slower than CGAL's
Delaunay_triangulation"). Without constraints the domain is the convex hull and the CDT is the
Delaunay triangulation (under the §6 perturbation), so both compute the same simplices up to the
choice made among cospherical points (random points have none); the simplex counts are printed to
show it. Medians of --repeat runs in one process each; prints a Markdown table.

Usage: bench/run_dd.py [BUILD_DIR] [--repeat 3] [--sizes 1000,4000,16000] [--dimensions 4,5]
       [--algorithms cavity-sweep,sweep-sphere]   (the default algorithm, and the whole-PLC sweep; the
       sweep plane needs a facet-bounded domain: on points it is the sphere)
The sweep sphere takes long in D = 5 (16000 points: minutes a run); the README's session 17 table ran
--dimensions 4, then --dimensions 5 --sizes 1000,4000 --algorithms cavity-sweep.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": (p.stderr or p.stdout).strip()[:200] or f"exit {p.returncode}"}
    return json.loads(p.stdout.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build", nargs="?", default="build")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--sizes", default="1000,4000,16000")
    parser.add_argument("--dimensions", default="4,5")
    parser.add_argument("--algorithms", default="cavity-sweep,sweep-sphere")
    args = parser.parse_args()
    bench = os.path.join(args.build, "bench")
    cgal = os.path.join(bench, "cgal_delaunay_dd")
    if not os.path.exists(cgal):
        sys.exit(f"{cgal} not built (CGAL not found when configuring?)")
    algorithms = args.algorithms.split(",")
    # "s": the whole cdt() call; "build": without the PLC check and the final validate() (CGAL does neither).
    print("| D | points | CGAL simplices | CGAL s | " + " | ".join(f"{a} s | build s | {a} / CGAL | build / CGAL" for a in algorithms) + " |")
    print("|---|---|---|---|" + "---|---|---|---|" * len(algorithms))
    with tempfile.TemporaryDirectory() as work:
        for d in map(int, args.dimensions.split(",")):
            for n in map(int, args.sizes.split(",")):
                points = os.path.join(work, "points.txt")
                subprocess.run([os.path.join(bench, "dd_bench"), str(d), str(n), "--points", points], check=True)
                c = run([cgal, str(d), points, "--repeat", str(args.repeat)])
                row = f"| {d} | {n} | {c.get('simplices', '-')} | {c.get('median_seconds', float('nan')):.3f} |"
                for a in algorithms:
                    s = run([os.path.join(bench, "dd_bench"), str(d), str(n), "--algorithm", a, "--repeat", str(args.repeat)])
                    if s.get("error"):
                        row += f" failed: {s['error'][:60]} | — | — | — |"
                        continue
                    same = "" if s["simplices"] == c.get("simplices") else f" ({s['simplices']} simplices)"
                    build = s["setup"] + s["build"]
                    row += (f" {s['median_seconds']:.3f}{same} | {build:.3f} | {s['median_seconds'] / c['median_seconds']:.1f}x |"
                            f" {build / c['median_seconds']:.1f}x |")
                print(row, flush=True)


if __name__ == "__main__":
    main()

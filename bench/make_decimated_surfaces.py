#!/usr/bin/env python3
"""Surfaces as MeshLab users simplify them before they mesh them (issue 13): MeshLab's "Simplification:
Quadric Edge Collapse Decimation" (meshlabserver 2020.09 under Xvfb, installed by scripts/setup.sh) of
closed surfaces to 10% and 30% of their triangles, with MeshLab's default quality threshold (0.3),
topology and normals preserved, and each collapsed vertex placed where its quadric error is least.
Those vertices leave the parts' flat faces, so the results have faces flat only up to the decimation's
rounding, long thin triangles across them and nearly flat creases: binary PLY, float coordinates.

Decimation can make a surface meet itself; `sweepcdt info` rejects those, and only the surfaces it
accepts are kept (their names are printed). tests/data/decimated holds six made this way.

Usage: bench/make_decimated_surfaces.py OUT_DIR --cli BUILD/plugin/cli/sweepcdt [SOURCE...]
  (default sources: the fine CAD parts of tests/data/cad)
Writes OUT_DIR/STEM_10.ply and OUT_DIR/STEM_30.ply for each source.
"""
import argparse
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCES = ["box_fused_sphere_fine.stl", "filleted_box_fine.stl", "flange_fine.stl", "gear_fine.stl", "hollow_sphere_fine.ply",
           "pipe_tee_fine.stl", "plate_with_holes_fine.stl"]
PERCENTS = (10, 30)

# The filter's parameters (meshlabserver -d lists them), TargetPerc set per run.
PARAMETERS = [("RichInt", "TargetFaceNum", "0"), ("RichFloat", "TargetPerc", "{fraction}"), ("RichFloat", "QualityThr", "0.3"),
              ("RichBool", "PreserveBoundary", "false"), ("RichFloat", "BoundaryWeight", "1"), ("RichBool", "PreserveNormal", "true"),
              ("RichBool", "PreserveTopology", "true"), ("RichBool", "OptimalPlacement", "true"), ("RichBool", "PlanarQuadric", "false"),
              ("RichFloat", "PlanarWeight", "0.001"), ("RichBool", "QualityWeight", "false"), ("RichBool", "AutoClean", "true"),
              ("RichBool", "Selected", "false")]
SCRIPT = ("<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name=\"Simplification: Quadric Edge Collapse Decimation\">\n" +
          "".join(f'  <Param type="{kind}" value="{value}" name="{name}"/>\n' for kind, name, value in PARAMETERS) +
          " </filter>\n</FilterScript>\n")


def decimate(source, output, percent, work):
    script = os.path.join(work, f"decimate_{percent}.mlx")
    with open(script, "w") as f:
        f.write(SCRIPT.format(fraction=percent / 100))
    # meshlabserver needs an X server (HOSTS.md): xvfb-run gives it one.
    subprocess.run(["xvfb-run", "-a", "meshlabserver", "-i", source, "-o", output, "-s", script], check=True, capture_output=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("--cli", required=True, help="the sweepcdt converter, for `sweepcdt info`")
    ap.add_argument("sources", nargs="*")
    args = ap.parse_intermixed_args()
    sources = args.sources or [os.path.join(ROOT, "tests", "data", "cad", name) for name in SOURCES]
    os.makedirs(args.out_dir, exist_ok=True)
    kept = []
    with tempfile.TemporaryDirectory() as work:
        for source in sources:
            stem = os.path.splitext(os.path.basename(source))[0]
            for percent in PERCENTS:
                output = os.path.join(args.out_dir, f"{stem}_{percent}.ply")
                decimate(source, output, percent, work)
                if subprocess.run([args.cli, "info", output], capture_output=True).returncode == 0:
                    kept.append(output)
                else:
                    os.remove(output)
                    print(f"{os.path.basename(output)}: not a valid closed surface (it meets itself), left out", file=sys.stderr)
    for path in kept:
        print(path)


if __name__ == "__main__":
    main()

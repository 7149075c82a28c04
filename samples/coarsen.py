#!/usr/bin/python3
# (Debian's python3: the module is built for it, not for a pyenv or venv python earlier on PATH.)
"""Sample: coarsen a tetrahedral mesh by deleting vertices (sweepcdt.EditableCdt, paper §5).

A plate whose faces are finely tessellated — as CAD exporters do, a grid of triangles on every
flat face — is tetrahedralized, then every vertex that can go is deleted: each vertex inside a flat
face, or on a straight edge between its two neighbours, leaves the face triangulated anew without
it; corners, and deletions that would leave no CDT, are refused and kept. Each deletion costs time
proportional to the vertex's star, not to the mesh. The result is checked against the CDT computed
from scratch, and both meshes are written as Medit .mesh and VTK .vtu.

Usage: samples/coarsen.py [OUT_DIR]    (default: sample-output/; from the project folder after
scripts/setup.sh, or with PYTHONPATH=build/python)
"""
import pathlib
import sys
import time

import numpy as np

root = pathlib.Path(__file__).resolve().parents[1]
try:
    import sweepcdt
except ImportError:  # not installed: the build tree's package
    sys.path.insert(0, str(root / "build" / "python"))
    import sweepcdt


def plate_surface(size=(4, 2, 0.5), step=0.125):
    """The box [0, size] with every face a grid of squares of side `step`, each split into two
    triangles, counterclockwise seen from outside. Coordinates are multiples of a power of two, so
    every point lies exactly on its face's plane."""
    ticks = [np.arange(round(s / step) + 1) * step for s in size]
    index = {}
    points, triangles = [], []

    def point(p):
        key = tuple(float(x) for x in p)
        if key not in index:
            index[key] = len(points)
            points.append(key)
        return index[key]

    for axis in range(3):
        u, v = [a for a in range(3) if a != axis]
        for side in (0, 1):
            for i in range(len(ticks[u]) - 1):
                for j in range(len(ticks[v]) - 1):
                    corners = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0] * 3
                        p[axis] = size[axis] * side
                        p[u], p[v] = ticks[u][i + di], ticks[v][j + dj]
                        corners.append(point(p))
                    a, b, c, d = corners
                    # (u, v, axis) is a right-handed frame for axis 1 only: flip the others' far side.
                    outward = (side == 1) == (axis != 1)
                    quad = (a, b, c, d) if outward else (a, d, c, b)
                    triangles += [quad[:3], (quad[0], quad[2], quad[3])]
    return np.array(points), np.array(triangles, dtype=np.int64)


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "sample-output")
    out.mkdir(parents=True, exist_ok=True)
    points, triangles = plate_surface()
    fine = sweepcdt.tetrahedralize(points, triangles)
    print(f"fine:   {len(fine.points)} points, {len(fine.tetrahedra)} tetrahedra, "
          f"{len(fine.triangles)} boundary triangles")
    sweepcdt.write_volume_mesh(out / "plate-fine.mesh", fine)

    edit = sweepcdt.EditableCdt.from_tet_mesh(fine)
    start = time.perf_counter()
    # In random order: deleted in id order (row by row across each face) the vertices left on a face
    # gather ever larger stars, and the same deletions take about 6x longer. A vertex refused now
    # may go once its neighbours have: repeat while a pass deletes something.
    candidates, passes = np.random.default_rng(1).permutation(len(fine.points)).tolist(), 0
    while True:
        passes += 1
        report = edit.remove_vertices(candidates)
        candidates = report.refused_ids
        if not report.removed:
            break
    seconds = time.perf_counter() - start
    kept = {type(e).__name__ for _, e in report.refused}
    coarse = edit.snapshot()
    print(f"coarse: {len(coarse.points)} points, {len(coarse.simplices)} tetrahedra, "
          f"{len(coarse.constraints)} boundary triangles ({len(fine.points) - len(coarse.points)} vertices "
          f"deleted in {passes} passes, {seconds:.2f} s; {len(candidates)} kept: {', '.join(sorted(kept))})")

    # The CDT from scratch of the PLC that is left must be the same triangulation.
    scratch = sweepcdt.cdt(coarse.points, coarse.constraints, exterior=coarse.exterior, facets="triangles")
    same = sorted(map(sorted, scratch.simplices.tolist())) == sorted(map(sorted, coarse.simplices.tolist()))
    print(f"same as the CDT computed from scratch: {'yes' if same else 'NO'}")
    mesh = coarse.to_tet_mesh()
    for name in ("plate-coarse.mesh", "plate-coarse.vtu"):
        sweepcdt.write_volume_mesh(out / name, mesh)
    print(f"written: {out / 'plate-fine.mesh'}, {out / 'plate-coarse.mesh'}, {out / 'plate-coarse.vtu'}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())

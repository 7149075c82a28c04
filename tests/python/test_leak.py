# No memory leaks over 1000 calls, including the exception paths: the process's resident memory
# (from /proc, independent of Python's allocator) must not grow with the number of calls.
import numpy as np

import sweepcdt
from conftest import unit_cube


def resident_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS in /proc/self/status")


def calls(n, points, triangles, bad):
    for _ in range(n):
        mesh = sweepcdt.tetrahedralize(points, triangles, progress=lambda *a: None)
        assert len(mesh.tetrahedra) > 0
        try:
            sweepcdt.tetrahedralize(points, bad)
        except sweepcdt.InvalidInputError:
            pass
        try:
            sweepcdt.tetrahedralize(points, triangles, steiner="none", progress=lambda *a: False)
        except sweepcdt.CancelledError:
            pass


def test_no_growth_over_1000_calls():
    # A cube refined with an interior grid of points would be more work than needed: a nested cube
    # pair (cavity) gives every array some size.
    outer, t = unit_cube()
    points = np.vstack([outer * 4, outer * 2 + 1])
    triangles = np.vstack([t, t + 8])
    bad = triangles.copy()
    bad[3, 1] = 999
    calls(100, points, triangles, bad)  # warm-up: allocator pools, lazily imported modules
    before = resident_kib()
    calls(1000, points, triangles, bad)
    grown = resident_kib() - before
    # A leak of even one result per call (~10 arrays, ~2 KiB) would add ~2 MiB; allow 1 MiB of noise.
    assert grown < 1024, f"resident memory grew by {grown} KiB over 1000 calls"

# Shared fixtures of the Python module's tests. ctest sets PYTHONPATH (the build tree's package),
# SWEEPCDT_CLI (the converter) and SWEEPCDT_SHARED_DATA; a missing prerequisite fails the test
# (never a skip that ctest would count as a pass).
import os
import pathlib

import numpy as np
import pytest


def _env_path(name, default=None):
    value = os.environ.get(name, default)
    if not value:
        pytest.fail(f"{name} is not set (run the tests through ctest)")
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def shared_data():
    path = _env_path("SWEEPCDT_SHARED_DATA", str(pathlib.Path(__file__).parents[3] / "shared" / "data"))
    if not path.is_dir():
        pytest.fail(f"shared meshes not found at {path}")
    return path


@pytest.fixture(scope="session")
def converter():
    path = _env_path("SWEEPCDT_CLI")
    if not path.is_file():
        pytest.fail(f"the converter {path} does not exist")
    return path


def shared_file(shared_data, relative):
    path = shared_data / relative
    if not path.is_file():
        pytest.fail(f"shared mesh {path} is missing")
    return path


def unit_cube():
    """The unit cube: 8 points, 12 triangles counterclockwise from outside."""
    points = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], dtype=np.int64)
    return points, triangles


def signed_volumes(points, tetrahedra):
    """det[b - a, c - a, d - a] / 6 per tetrahedron, in numpy (independent of sweepcdt)."""
    a, b, c, d = (points[tetrahedra[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6

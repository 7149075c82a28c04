# sweepcdt.cdt in dimensions 2..5: orientation and volume checked with numpy (independent).
import math

import numpy as np
import pytest

import sweepcdt


def volumes(points, simplices):
    d = points.shape[1]
    edges = points[simplices[:, 1:]] - points[simplices[:, :1]]
    return np.linalg.det(edges) / math.factorial(d)


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_cube_corners_fill_the_cube(d):
    corners = np.array(np.meshgrid(*[[0.0, 1.0]] * d, indexing="ij")).reshape(d, -1).T
    rng = np.random.default_rng(d)
    inner = rng.uniform(0.1, 0.9, size=(5, d))
    points = np.vstack([corners, inner])
    tri = sweepcdt.cdt(points, np.zeros((0, d), dtype=int), check=True)
    assert tri.dimension == d and tri.simplices.shape[1] == d + 1
    v = volumes(tri.points, tri.simplices)
    assert (v > 0).all()
    assert v.sum() == pytest.approx(1.0, rel=1e-9)
    assert tri.stats["checked"]


def test_square_with_a_constraining_diagonal():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    for diagonal in ([0, 2], [1, 3]):
        tri = sweepcdt.cdt(square, np.array([diagonal]))
        edges = {tuple(sorted((int(s[i]), int(s[j])))) for s in tri.simplices for i in range(3) for j in range(i + 1, 3)}
        assert tuple(diagonal) in edges


def test_facet_bounded_cube_in_3d():
    from conftest import unit_cube
    points, triangles = unit_cube()
    tri = sweepcdt.cdt(points, triangles, exterior=-np.ones(12, dtype=int), tags=np.arange(12))
    assert volumes(tri.points, tri.simplices).sum() == pytest.approx(1.0)
    assert len(tri.regions) == len(tri.simplices)

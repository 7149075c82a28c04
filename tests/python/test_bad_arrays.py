# Bad arrays give a clear ValueError (or TypeError for non-arrays) naming what is wrong, and never
# crash: wrong shapes, dtypes, NaN/inf, ids out of range.
import numpy as np
import pytest

import sweepcdt
from conftest import unit_cube

P, T = unit_cube()


@pytest.mark.parametrize("points, triangles, message", [
    (P[:, :2], T, r"points must have shape \(n, 3\), not \(8, 2\)"),
    (P.ravel(), T, r"points must have shape \(n, 3\), not \(24,\)"),
    (P, T[:, :2], r"triangles must have shape \(n, 3\), not \(12, 2\)"),
    (P, T.reshape(2, 6, 3), r"triangles must have shape \(n, 3\), not \(2, 6, 3\)"),
    (P, T.astype(float), r"triangles must be an integer array \(point ids\), not dtype float64"),
    (P.astype(complex), T, r"points must hold real numbers, not dtype complex128"),
    (P.astype(str), T, r"points must hold real numbers"),
    (P > 0, T, r"points must hold real numbers, not dtype bool"),
])
def test_shape_and_dtype(points, triangles, message):
    with pytest.raises(ValueError, match=message):
        sweepcdt.tetrahedralize(points, triangles)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinate_names_the_point(value):
    points = P.copy()
    points[5, 2] = value
    with pytest.raises(ValueError, match=r"point 5: coordinate 2 is not finite") as e:
        sweepcdt.tetrahedralize(points, T)
    assert isinstance(e.value, sweepcdt.InvalidInputError) and e.value.exit_code == 3


@pytest.mark.parametrize("bad_id", [8, 1000, -1, 2**40])
def test_id_out_of_range_names_the_triangle(bad_id):
    triangles = T.copy()
    triangles[7, 1] = bad_id
    with pytest.raises(ValueError, match=rf"triangle 7: point id {bad_id} is not in \[0, 8\)"):
        sweepcdt.tetrahedralize(P, triangles)


def test_uint64_id_that_would_wrap():
    triangles = T.astype(np.uint64)
    triangles[3, 0] = np.uint64(2**64 - 1)
    with pytest.raises(ValueError, match="out of range"):
        sweepcdt.tetrahedralize(P, triangles)


def test_none_and_non_arrays():
    with pytest.raises(TypeError, match="points must be an array, not None"):
        sweepcdt.tetrahedralize(None, T)
    with pytest.raises(ValueError):
        sweepcdt.tetrahedralize("not an array", T)
    with pytest.raises(TypeError):
        sweepcdt.tetrahedralize(P, T, check="yes please")


def test_empty_surface_is_invalid_input():
    with pytest.raises(ValueError):
        sweepcdt.tetrahedralize(np.zeros((0, 3)), np.zeros((0, 3), dtype=int))


def test_cdt_arrays():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    with pytest.raises(ValueError, match="2 to 5 columns"):
        sweepcdt.cdt(np.zeros((4, 6)), np.zeros((0, 6), dtype=int))
    with pytest.raises(ValueError, match=r"simplices must have shape \(n, 2\)"):
        sweepcdt.cdt(square, np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match=r"exterior must have shape \(1,\)"):
        sweepcdt.cdt(square, np.array([[0, 2]]), exterior=[1, 1])
    with pytest.raises(ValueError, match=r"exterior\[0\] must be -1"):
        sweepcdt.cdt(square, np.array([[0, 2]]), exterior=[5])
    with pytest.raises(ValueError, match="steiner='auto' is implemented for D = 3 only"):
        sweepcdt.cdt(square, np.array([[0, 2]]), steiner="auto")
    with pytest.raises(sweepcdt.InvalidInputError):  # core's PLC check names the simplex
        sweepcdt.cdt(square, np.array([[0, 9]]))

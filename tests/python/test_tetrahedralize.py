# sweepcdt.tetrahedralize on small surfaces whose answers are known without sweepcdt: the volume
# of a cube, orientation, ids, options, help text.
import numpy as np
import pytest

import sweepcdt
from conftest import signed_volumes, unit_cube


def test_cube_fills_its_volume_with_positive_tetrahedra():
    points, triangles = unit_cube()
    mesh = sweepcdt.tetrahedralize(points, triangles, facets="triangles")  # face ids: input triangles
    assert mesh.points.shape[1] == 3 and mesh.tetrahedra.shape[1] == 4
    assert mesh.points.dtype == np.float64 and mesh.tetrahedra.dtype == np.int64
    # Welding numbers points by first use in the triangles; point_ids maps input rows to mesh rows.
    assert mesh.num_input_points == 8 and sorted(mesh.point_ids.tolist()) == list(range(8))
    np.testing.assert_array_equal(mesh.points[mesh.point_ids], points)
    volumes = signed_volumes(mesh.points, mesh.tetrahedra)
    assert (volumes > 0).all()
    assert volumes.sum() == pytest.approx(1.0, rel=1e-12)
    # Every boundary triangle lies on an input triangle: its points are among that triangle's plane.
    assert len(mesh.triangles) == len(mesh.triangle_ids) >= 12
    assert set(mesh.triangle_ids.tolist()) == set(range(12))
    assert mesh.regions.shape == (len(mesh.tetrahedra),) and len(set(mesh.regions.tolist())) == 1
    assert mesh.stats["tetrahedra"] == len(mesh.tetrahedra)
    assert mesh.stats["steiner_points"] == len(mesh.points) - mesh.num_input_points == len(mesh.steiner_triangles)


def test_by_default_each_flat_face_is_one_facet():
    # The converter's default (facets="coplanar"): a face id names the face's first input triangle.
    points, triangles = unit_cube()
    faces = {}
    for j, t in enumerate(triangles.tolist()):
        normal = np.cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]])
        faces.setdefault(tuple(np.sign(normal).astype(int)), []).append(j)
    assert sweepcdt.DEFAULTS["facets"] == "coplanar"
    mesh = sweepcdt.tetrahedralize(points, triangles)
    assert set(mesh.triangle_ids.tolist()) == {min(js) for js in faces.values()}
    assert len(faces) == 6


def test_lists_and_other_dtypes_are_accepted():
    points, triangles = unit_cube()
    a = sweepcdt.tetrahedralize(points.tolist(), triangles.tolist())
    b = sweepcdt.tetrahedralize(points.astype(np.float32), triangles.astype(np.uint16))
    c = sweepcdt.tetrahedralize(np.asfortranarray(points), triangles[:, :].astype(np.int32))
    for m in (b, c):
        np.testing.assert_array_equal(m.tetrahedra, a.tetrahedra)


def test_duplicate_and_unused_points_are_mapped():
    points, triangles = unit_cube()
    points = np.vstack([points, [[7.0, 7.0, 7.0]], points[:1]])  # 8: unused, 9: copy of point 0
    triangles = triangles.copy()
    triangles[0, 0] = 9
    mesh = sweepcdt.tetrahedralize(points, triangles)
    assert mesh.point_ids[8] == -1
    assert mesh.point_ids[9] == mesh.point_ids[0]
    used = mesh.point_ids >= 0
    np.testing.assert_array_equal(mesh.points[mesh.point_ids[used]], points[used])


def test_nested_cube_is_a_cavity():
    outer, t = unit_cube()
    inner = outer * 0.5 + 0.25
    points = np.vstack([outer * 4, inner * 4])
    triangles = np.vstack([t, t + 8])
    mesh = sweepcdt.tetrahedralize(points, triangles)
    assert signed_volumes(mesh.points, mesh.tetrahedra).sum() == pytest.approx(64 - 8)


def test_options_are_the_converters():
    assert sweepcdt.DEFAULTS["algorithm"] == "cavity-sweep" == sweepcdt.ALGORITHMS[0]
    assert set(sweepcdt.DEFAULTS) == {"algorithm", "steiner", "facets"}
    points, triangles = unit_cube()
    assert sweepcdt.ALGORITHMS == ["cavity-sweep", "sweep-sphere", "sweep-plane", "giftwrap"]
    for algorithm in sweepcdt.ALGORITHMS:
        mesh = sweepcdt.tetrahedralize(points, triangles, algorithm=algorithm, check=True)
        assert mesh.stats["algorithm"] == algorithm and mesh.stats["checked"]
    coplanar = sweepcdt.tetrahedralize(points, triangles, facets="coplanar")
    assert coplanar.stats["facets"] == "coplanar"
    for bad in ({"algorithm": "delaunay"}, {"steiner": "yes"}, {"facets": "quads"}, {"snap": 0.0}, {"snap": 0.1},
                {"snap": float("nan")}):
        with pytest.raises(ValueError, match=next(iter(bad))):
            sweepcdt.tetrahedralize(points, triangles, **bad)


def test_snap_repairs_rounding_noise():
    points, triangles = unit_cube()
    noisy = points.copy()
    noisy[1, 2] = 5e-17  # a bottom corner lifted by rounding noise: the bottom face folds
    mesh = sweepcdt.tetrahedralize(noisy, triangles, snap=1e-12, facets="coplanar")
    assert mesh.stats["snapped_points"] == 1
    assert mesh.points[mesh.point_ids[1], 2] == 0.0


def test_help_is_useful():
    doc = sweepcdt.tetrahedralize.__doc__
    for word in ("points", "triangles", "algorithm", "steiner", "facets", "snap", "check", "progress", "NoCdtError"):
        assert word in doc
    assert "to_meshio" in sweepcdt.TetMesh.__doc__ or "to_meshio" in dir(sweepcdt.TetMesh)


def test_progress_receives_phases():
    points, triangles = unit_cube()
    phases = []
    sweepcdt.tetrahedralize(points, triangles, progress=lambda phase, done, total: phases.append(phase))
    assert phases[0] == "checking surface" and "volume mesh" in phases


def test_to_meshio():
    import meshio  # Debian python3-meshio (scripts/setup.sh): required, not skipped

    points, triangles = unit_cube()
    mesh = sweepcdt.tetrahedralize(points, triangles)
    m = mesh.to_meshio()
    assert isinstance(m, meshio.Mesh)
    np.testing.assert_array_equal(m.cells_dict["tetra"], mesh.tetrahedra)
    np.testing.assert_array_equal(m.cell_data["region"][0], mesh.regions)
    b = mesh.to_meshio(boundary=True)
    np.testing.assert_array_equal(b.cells_dict["triangle"], mesh.triangles)

# sweepcdt.EditableCdt (vertex deletion, paper §5) against sweepcdt.cdt computed from scratch: after
# deletions, the snapshot must be the CDT of the PLC it says is left (the CDT is unique under the
# perturbation of §6, by vertex id, which snapshots keep), every simplex positively oriented (numpy),
# and refused deletions must leave the mesh unchanged and be refused for the reason cdt() confirms.
import math

import numpy as np
import pytest

import sweepcdt
from conftest import unit_cube


def simplex_set(simplices):
    return sorted(tuple(sorted(s)) for s in np.asarray(simplices).tolist())


def volumes(points, simplices):
    edges = points[simplices[:, 1:]] - points[simplices[:, :1]]
    return np.linalg.det(edges) / math.factorial(points.shape[1])


def from_scratch(snap):
    # In 3D the snapshot's facets are already triangulated: keep them as given.
    facets = {"facets": "triangles"} if snap.dimension == 3 else {}
    return sweepcdt.cdt(snap.points, snap.constraints, exterior=snap.exterior, tags=snap.tags, **facets)


def assert_is_cdt_of_its_plc(snap):
    ref = from_scratch(snap)
    assert ref.stats["perturbation_order"] == 0  # perturbed by vertex id, as the snapshot
    assert np.array_equal(ref.points, snap.points)
    assert simplex_set(snap.simplices) == simplex_set(ref.simplices)
    assert (volumes(snap.points, snap.simplices) > 0).all()
    if snap.exterior is None:  # a hull domain loses no volume when interior vertices go
        assert volumes(snap.points, snap.simplices).sum() == pytest.approx(volumes(ref.points, ref.simplices).sum())


def cube_with_inner_points(d, inner, seed):
    """The unit d-cube's corners (its hull vertices) then `inner` random inner points."""
    corners = np.array(np.meshgrid(*[[0.0, 1.0]] * d, indexing="ij")).reshape(d, -1).T
    rng = np.random.default_rng(seed)
    return np.vstack([corners, rng.uniform(0.05, 0.95, size=(inner, d))]), len(corners)


@pytest.mark.parametrize("d,inner,deletions", [(2, 60, 30), (3, 50, 20), (4, 30, 10), (5, 20, 5)])
def test_interior_deletions_give_the_cdt_from_scratch(d, inner, deletions):
    points, corners = cube_with_inner_points(d, inner, seed=d)
    edit = sweepcdt.EditableCdt(points)
    assert edit.dimension == d and edit.num_vertices == len(points)
    order = np.random.default_rng(10 + d).permutation(np.arange(corners, len(points)))[:deletions]
    for k, v in enumerate(order):
        edit.remove_vertex(v)
        assert v not in edit
        if k % 4 == 0 or k == deletions - 1:
            snap = edit.snapshot()
            assert len(snap.points) == len(points) - k - 1
            assert np.array_equal(snap.points, points[snap.old_ids])
            assert_is_cdt_of_its_plc(snap)
    assert edit.num_simplices == len(edit.snapshot().simplices)


@pytest.mark.parametrize("d", [2, 3])
def test_grid_with_exact_ties(d):
    """Integer grid points: cocircular/cospherical everywhere, decided by the perturbation."""
    side = 5 if d == 2 else 3
    points = np.array(np.meshgrid(*[np.arange(side, dtype=float)] * d, indexing="ij")).reshape(d, -1).T
    edit = sweepcdt.EditableCdt(points)
    inner = [i for i, p in enumerate(points) if ((p > 0) & (p < side - 1)).all()]
    report = edit.remove_vertices(inner)
    assert report.removed == inner and report.refused == []
    assert_is_cdt_of_its_plc(edit.snapshot())


@pytest.mark.parametrize("facets", ["coplanar", "triangles"])
def test_face_centres_of_a_tetrahedralized_box(facets):
    """A TetMesh from tetrahedralize(): a face's centre goes when the face is one facet (coplanar:
    its triangles share one tag), not when each triangle is a facet of its own; corners stay."""
    points, _ = unit_cube()
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]  # counterclockwise from outside
    centres = points[np.array(quads)].mean(axis=1)  # exact: halves
    fans = [(quad[i], quad[(i + 1) % 4], 8 + q) for q, quad in enumerate(quads) for i in range(4)]
    mesh = sweepcdt.tetrahedralize(np.vstack([points, centres]), np.array(fans), facets=facets, steiner="none")
    edit = sweepcdt.EditableCdt.from_tet_mesh(mesh)
    report = edit.remove_vertices(range(len(mesh.points)))
    # Vertex ids are the mesh's (welded: in order of first use), mapped from the input's by point_ids.
    centre_ids, corner_ids = sorted(mesh.point_ids[8:]), sorted(mesh.point_ids[:8])
    assert all(isinstance(e, sweepcdt.VertexRemovalError) and e.vertex == v for v, e in report.refused)
    if facets == "triangles":  # each centre is a corner of its four facets
        assert report.removed == [] and sorted(report.refused_ids) == sorted(centre_ids + corner_ids)
        return
    assert sorted(report.removed) == centre_ids and sorted(report.refused_ids) == corner_ids
    snap = edit.snapshot()
    assert len(snap.points) == 8 and len(snap.constraints) == 12
    assert volumes(snap.points, snap.simplices).sum() == pytest.approx(1.0)
    tet = snap.to_tet_mesh()
    assert len(tet.triangles) == 12 and (tet.point_ids[mesh.point_ids[8:]] == -1).all()
    # Outward: the boundary triangles' normals point away from the cube's centre.
    a, b, c = (tet.points[tet.triangles[:, k]] for k in range(3))
    assert (np.einsum("ij,ij->i", np.cross(b - a, c - a), (a + b + c) / 3 - 0.5) > 0).all()
    # The cube's corners are cospherical: exact ties, decided by the perturbation as cdt() decides them.
    assert_is_cdt_of_its_plc(snap)


def unit_cube_surface():
    """The unit cube's corners (point i = (i&1, (i>>1)&1, (i>>2)&1)), 12 triangles CCW from outside."""
    points = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=float)
    triangles = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                          [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
    return points, triangles


def test_refusals_are_reported_and_change_nothing():
    cube, triangles = unit_cube_surface()
    solid = sweepcdt.EditableCdt(cube, triangles, exterior=-np.ones(12, dtype=int), facets="triangles")
    with pytest.raises(sweepcdt.VertexRemovalError) as facet_corner:
        solid.remove_vertex(0)
    assert facet_corner.value.vertex == 0 and isinstance(facet_corner.value, ValueError)
    assert solid.num_vertices == 8

    points, corners = cube_with_inner_points(3, 20, seed=5)
    edit = sweepcdt.EditableCdt(points)
    before = edit.snapshot()
    for bad in (-1, len(points), 2**40):
        with pytest.raises(sweepcdt.VertexRemovalError):
            edit.remove_vertex(bad)
    after = edit.snapshot()
    assert simplex_set(after.simplices) == simplex_set(before.simplices)
    # A hull corner goes too (paper §5: the vertex may lie on the boundary); a vertex already gone
    # or missing is refused, and the rest go on.
    report = edit.remove_vertices([corners, 1, corners, len(points), corners + 1])
    assert report.removed == [corners, 1, corners + 1]
    assert report.refused_ids == [corners, len(points)]  # already gone, no such vertex
    assert all(isinstance(e, sweepcdt.VertexRemovalError) for _, e in report.refused)
    assert_is_cdt_of_its_plc(edit.snapshot())
    with pytest.raises(TypeError):
        edit.remove_vertices([1.5])


def twisted_prism(twist=0.5):
    """Schönhardt's polyhedron: no CDT (no tetrahedralization at all) without Steiner points."""
    level = [(math.cos(2 * math.pi * i / 3 + (twist if z else 0)), math.sin(2 * math.pi * i / 3 + (twist if z else 0)), float(z))
             for z in (0, 1) for i in range(3)]
    triangles = [(0, 2, 1), (3, 4, 5)]
    for i in range(3):
        j = (i + 1) % 3
        triangles += [(i, j, 3 + j), (i, 3 + j, 3 + i)]
    return np.array(level), np.array(triangles)


def test_deletions_that_leave_no_cdt_are_refused_as_cdt_confirms():
    points, triangles = twisted_prism()
    with pytest.raises(sweepcdt.NoCdtError):
        sweepcdt.cdt(points, triangles, exterior=-np.ones(8, dtype=int), facets="triangles")
    edit = sweepcdt.EditableCdt(points, triangles, exterior=-np.ones(8, dtype=int), steiner="auto", facets="triangles")
    n = edit.snapshot().num_ids
    assert n > 6
    no_cdt = 0
    for v in range(6, n):
        try:
            left = edit.plc_without(v)
        except sweepcdt.VertexRemovalError:  # a rounded Steiner point off its segment: a corner
            continue
        try:
            has_cdt = sweepcdt.cdt(left["points"], left["constraints"], exterior=left["exterior"],
                                   facets="triangles").stats["perturbation_order"] == 0
        except sweepcdt.NoCdtError:
            has_cdt = False
        before = edit.snapshot()
        report = edit.remove_vertices([v])
        assert (report.removed == [v]) == has_cdt, v
        if not has_cdt:
            no_cdt += 1
            (_, error), = report.refused
            assert isinstance(error, sweepcdt.NoCdtError) and error.vertex == v and len(error.witness) > 0
            assert simplex_set(edit.snapshot().simplices) == simplex_set(before.simplices)
            with pytest.raises(sweepcdt.NoCdtError):
                edit.remove_vertex(v)
        else:
            assert_is_cdt_of_its_plc(edit.snapshot())
    assert no_cdt > 0


def test_from_triangulation_validates():
    points, corners = cube_with_inner_points(2, 10, seed=3)
    tri = sweepcdt.cdt(points, np.zeros((0, 2), dtype=int))
    edit = sweepcdt.EditableCdt.from_triangulation(tri.points, tri.simplices, np.zeros((0, 2), dtype=int))
    assert edit.num_simplices == len(tri.simplices)
    flipped = tri.simplices[:, [0, 2, 1]]  # negatively oriented
    with pytest.raises(sweepcdt.CheckError) as e:
        sweepcdt.EditableCdt.from_triangulation(tri.points, flipped, np.zeros((0, 2), dtype=int))
    assert any(check == "orientation" for check, _ in e.value.failures)
    with pytest.raises(sweepcdt.CheckError):  # half the triangles: not the domain
        sweepcdt.EditableCdt.from_triangulation(tri.points, tri.simplices[: len(tri.simplices) // 2], np.zeros((0, 2), dtype=int))


def test_threads_sharing_one_object_take_turns():
    """remove_vertices releases the GIL: two threads on one EditableCdt must not race."""
    import threading

    points, corners = cube_with_inner_points(3, 400, seed=9)
    edit = sweepcdt.EditableCdt(points)
    inner = np.arange(corners, len(points))
    halves, reports = [inner[::2], inner[1::2]], [None, None]

    def work(k):
        reports[k] = edit.remove_vertices(halves[k])

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert sorted(reports[0].removed + reports[1].removed) == inner.tolist()  # every inner vertex went
    assert edit.num_vertices == corners
    assert_is_cdt_of_its_plc(edit.snapshot())


def test_a_mesh_made_under_another_perturbation_order():
    """The cube's fixed face diagonals have a CDT only under a later order (paper §6): from_tet_mesh
    must find that order, as `sweepcdt check` does, and keep it."""
    points, triangles = unit_cube()
    mesh = sweepcdt.tetrahedralize(points, triangles, steiner="none", facets="triangles")
    assert mesh.stats["perturbation_order"] != 0
    snap = sweepcdt.EditableCdt.from_tet_mesh(mesh).snapshot()
    assert snap.perturbation_rank is not None and sorted(snap.perturbation_rank) == list(range(8))
    assert simplex_set(snap.simplices) == simplex_set(mesh.tetrahedra)


def test_progress_cancels_remove_vertices_between_whole_deletions():
    points, corners = cube_with_inner_points(2, 200, seed=4)
    edit = sweepcdt.EditableCdt(points)
    calls = []

    def progress(phase, done, total):  # asked every 64 deletions: stop at the second call
        calls.append((phase, done, total))
        return done < 64

    with pytest.raises(sweepcdt.CancelledError):
        edit.remove_vertices(range(corners, len(points)), progress=progress)
    assert calls == [("deleting vertices", 0, 200), ("deleting vertices", 64, 200)]
    assert edit.num_vertices == len(points) - 64  # the deletions made before stay, each whole
    assert_is_cdt_of_its_plc(edit.snapshot())

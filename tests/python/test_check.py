# sweepcdt.check_files: the library's verification (what `sweepcdt check` runs) from Python. It
# accepts the file mesh_file() wrote, rejects it with a moved vertex or under the other facets mode
# (saying which mode it passes in), and raises for an unreadable file.
import numpy as np
import pytest

import sweepcdt
from conftest import shared_file


def test_accepts_what_mesh_file_wrote_and_rejects_a_moved_vertex(shared_data, tmp_path):
    surface = shared_file(shared_data, "off/icosahedron.off")
    good = tmp_path / "ico.mesh"
    sweepcdt.mesh_file(surface, good)
    report = sweepcdt.check_files(surface, good)
    assert report["valid"], report["problems"]
    assert report["problems"] == [] and report["total_problems"] == 0
    assert report["validated"]
    assert report["facets"] == sweepcdt.DEFAULTS["facets"]

    mesh = sweepcdt.read_volume_mesh(good)
    points = mesh.points.copy()
    points[3, 1] += 1e-3
    tampered = tmp_path / "tampered.mesh"
    sweepcdt.write_volume_mesh(tampered, points=points, tetrahedra=mesh.tetrahedra, regions=mesh.regions,
                               triangles=mesh.triangles, triangle_ids=mesh.triangle_ids)
    bad = sweepcdt.check_files(surface, tampered)
    assert not bad["valid"]
    assert bad["total_problems"] >= 1
    assert any(p.startswith("vertex 3 is (") for p in bad["problems"]), bad["problems"]
    assert not bad["validated"]


def test_the_other_facets_mode_is_suggested(shared_data, tmp_path):
    surface = shared_file(shared_data, "glb/cubevc.glb")
    coplanar = tmp_path / "coplanar.msh"
    sweepcdt.mesh_file(surface, coplanar, facets="coplanar")
    assert sweepcdt.check_files(surface, coplanar, facets="coplanar")["valid"]
    as_triangles = sweepcdt.check_files(surface, coplanar, facets="triangles")
    assert not as_triangles["valid"]
    assert as_triangles["suggest_coplanar"] and not as_triangles["suggest_triangles"]


def test_errors(shared_data, tmp_path):
    surface = shared_file(shared_data, "off/icosahedron.off")
    junk = tmp_path / "junk.mesh"
    junk.write_text("not a mesh\n")
    with pytest.raises(sweepcdt.InvalidInputError, match="junk.mesh"):
        sweepcdt.check_files(surface, junk)
    with pytest.raises(ValueError, match="facets"):
        sweepcdt.check_files(surface, junk, facets="polygons")

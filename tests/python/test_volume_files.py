# read_volume_mesh / write_volume_mesh: every format round-trips a TetMesh exactly, and the files are
# the converter's (read back independently with meshio for .vtu).
import meshio
import numpy as np
import pytest

import sweepcdt
from conftest import shared_file, signed_volumes


@pytest.mark.parametrize("ext", ["mesh", "vtu", "msh", "node"])
def test_round_trip(ext, shared_data, tmp_path):
    mesh = sweepcdt.tetrahedralize(*sweepcdt.read_surface(shared_file(shared_data, "gltf/two_objects_inverse_materials.gltf")))
    path = tmp_path / f"m.{ext}"
    sweepcdt.write_volume_mesh(path, mesh)
    back = sweepcdt.read_volume_mesh(path)
    np.testing.assert_array_equal(back.points, mesh.points)
    np.testing.assert_array_equal(back.tetrahedra, mesh.tetrahedra)
    np.testing.assert_array_equal(back.regions, mesh.regions)
    np.testing.assert_array_equal(back.triangles, mesh.triangles)
    np.testing.assert_array_equal(back.triangle_ids, mesh.triangle_ids)
    assert (signed_volumes(back.points, back.tetrahedra) > 0).all()


def test_same_file_as_mesh_file(shared_data, tmp_path):
    surface = shared_file(shared_data, "off/icosahedron.off")
    mesh = sweepcdt.mesh_file(surface, tmp_path / "a.vtu")
    sweepcdt.write_volume_mesh(tmp_path / "b.vtu", mesh)
    assert (tmp_path / "a.vtu").read_bytes() != b""
    a, b = meshio.read(tmp_path / "a.vtu"), meshio.read(tmp_path / "b.vtu")
    np.testing.assert_array_equal(a.cells_dict["tetra"], b.cells_dict["tetra"])
    np.testing.assert_array_equal(a.points, b.points)


def test_arrays_and_errors(tmp_path):
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    sweepcdt.write_volume_mesh(tmp_path / "t.mesh", points=points, tetrahedra=[[0, 1, 2, 3]])
    back = sweepcdt.read_volume_mesh(tmp_path / "t.mesh")
    np.testing.assert_array_equal(back.tetrahedra, [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match=r"tetrahedra: entry 3 \(4\) is not in \[0, 4\)"):
        sweepcdt.write_volume_mesh(tmp_path / "t.mesh", points=points, tetrahedra=[[0, 1, 2, 4]])
    with pytest.raises(ValueError, match="unknown volume-mesh format"):
        sweepcdt.write_volume_mesh(tmp_path / "t.xyz", points=points, tetrahedra=[[0, 1, 2, 3]])
    with pytest.raises(sweepcdt.OutputError):
        sweepcdt.write_volume_mesh(tmp_path / "no" / "t.mesh", points=points, tetrahedra=[[0, 1, 2, 3]])
    bad = tmp_path / "bad.mesh"
    bad.write_text("MeshVersionFormatted 2\nDimension 3\nVertices\n2\n")
    with pytest.raises(sweepcdt.InvalidInputError, match="bad.mesh"):
        sweepcdt.read_volume_mesh(bad)

# The module's arrays equal the converter's files on the shared meshes: `sweepcdt mesh IN -o OUT.vtu`
# read back with meshio (independent of sweepcdt's readers) against sweepcdt.tetrahedralize on the
# surface read by sweepcdt.read_surface. The .vtu holds coordinates exactly and numbers regions and
# boundary tags from 1 (io/src/volume_mesh_formats.h), so region/tag = module's + 1.
import os
import subprocess

import meshio
import numpy as np
import pytest

import sweepcdt
from conftest import shared_file, signed_volumes

CASES = [
    ("off/icosahedron.off", {}),
    ("gltf/Box.gltf", {}),
    ("gltf/two_objects_inverse_materials.gltf", {}),
    ("drc/cube_att.drc", {"facets": "coplanar"}),
    ("drc/knot1.drc", {"algorithm": "sweep-plane"}),
    ("glb/cubevc.glb", {}),
    ("glb/moon.glb", {}),
    ("stl_ascii/t13_data_ascii.stl", {}),
    ("stl_binary/spot.stl", {"steiner": "auto"}),
]


def cli_options(options):
    return [a for k, v in options.items() for a in (f"--{k}", str(v))]


@pytest.mark.parametrize("relative, options", CASES, ids=[c[0] for c in CASES])
def test_arrays_equal_the_converters_file(relative, options, shared_data, converter, tmp_path):
    surface = shared_file(shared_data, relative)
    out = tmp_path / "out.vtu"
    subprocess.run([converter, "mesh", surface, "-o", out, "--quiet", *cli_options(options)], check=True)
    file = meshio.read(out)

    points, triangles = sweepcdt.read_surface(surface)
    mesh = sweepcdt.tetrahedralize(points, triangles, **options)

    np.testing.assert_array_equal(mesh.points, file.points)
    np.testing.assert_array_equal(mesh.tetrahedra, file.cells_dict["tetra"])
    np.testing.assert_array_equal(mesh.triangles, file.cells_dict["triangle"])
    blocks = [c.type for c in file.cells]
    tet_block, tri_block = blocks.index("tetra"), blocks.index("triangle")
    np.testing.assert_array_equal(mesh.regions + 1, file.cell_data["region"][tet_block])
    np.testing.assert_array_equal(mesh.triangle_ids + 1, file.cell_data["boundary_tag"][tri_block])
    # Steiner provenance: the file's input_triangle is the triangle + 1 for Steiner points, else 0.
    n = mesh.num_input_points
    np.testing.assert_array_equal(file.point_data["steiner"][n:], 1)
    np.testing.assert_array_equal(mesh.steiner_triangles + 1, file.point_data["input_triangle"][n:])
    on = mesh.steiner_triangles >= 0
    if on.any():  # each lies on its input triangle: in its plane up to rounding (checked with numpy)
        corners = points[triangles[mesh.steiner_triangles[on]]]
        normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        normal /= np.linalg.norm(normal, axis=1)[:, None]
        distance = np.abs(np.einsum("ij,ij->i", mesh.steiner_points[on] - corners[:, 0], normal))
        size = np.abs(points).max()
        assert distance.max() <= 1e-12 * size, distance.max()
    assert (signed_volumes(mesh.points, mesh.tetrahedra) > 0).all()
    assert mesh.stats["tetrahedra"] == len(file.cells_dict["tetra"])


def test_mesh_file_writes_what_the_converter_writes(shared_data, converter, tmp_path):
    surface = shared_file(shared_data, "gltf/two_objects_inverse_materials.gltf")
    for ext in ("mesh", "vtu", "msh", "node", "inp"):
        ours, theirs = tmp_path / f"ours.{ext}", tmp_path / f"theirs.{ext}"
        sweepcdt.mesh_file(surface, ours)
        subprocess.run([converter, "mesh", surface, "-o", theirs, "--quiet"], check=True)
        assert ours.read_bytes() == theirs.read_bytes(), ext
    mesh = sweepcdt.mesh_file(surface, [tmp_path / "a.msh"], format="msh22")
    subprocess.run([converter, "mesh", surface, "-o", tmp_path / "b.msh", "--format", "msh22", "--quiet"], check=True)
    assert (tmp_path / "a.msh").read_bytes() == (tmp_path / "b.msh").read_bytes()
    assert mesh.stats["regions"] == 2
    # The import's intersection check and, given a second core, its tetrahedralization were reused.
    assert mesh.stats["check_recorded"]
    assert mesh.stats["tetrahedralization_recorded"] == ((os.cpu_count() or 1) > 1)

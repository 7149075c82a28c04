# Every exception path, with the converter's exit-code meaning: InvalidInputError (3), NoCdtError (4),
# OutputError (5), CancelledError (130) / KeyboardInterrupt, the callback's own exception.
import math

import numpy as np
import pytest

import sweepcdt
from conftest import shared_file, unit_cube


def schoenhardt_prism():
    """Schönhardt's twisted prism: no tetrahedralization without Steiner points (a classical fact,
    independent of sweepcdt). Bottom triangle at z = 0, top rotated by 30 degrees, each side quad
    split by its reflex diagonal."""
    bottom = [(math.cos(a), math.sin(a), 0.0) for a in (0, 2 * math.pi / 3, 4 * math.pi / 3)]
    top = [(math.cos(a + math.pi / 6), math.sin(a + math.pi / 6), 1.0) for a in (0, 2 * math.pi / 3, 4 * math.pi / 3)]
    points = np.array(bottom + top)
    triangles = [(0, 2, 1), (3, 4, 5)]
    for i in range(3):
        j = (i + 1) % 3
        # Side quad (a_i, a_j, b_j, b_i): the diagonal a_i-b_j, which the twist makes reflex.
        triangles += [(i, j, 3 + j), (i, 3 + j, 3 + i)]
    return points, np.array(triangles)


def test_reflex_diagonals_make_the_prism_non_convex():
    # Independent check that the prism is Schönhardt's (non-convex, side diagonals reflex): the
    # midpoint of diagonal a_0-b_1 lies strictly inside the convex hull's side plane direction,
    # i.e. closer to the axis than the hull edge through the same height allows.
    points, _ = schoenhardt_prism()
    mid = (points[0] + points[4]) / 2
    other = (points[1] + points[3]) / 2
    assert np.hypot(*mid[:2]) < np.hypot(*other[:2])


def test_no_cdt_carries_the_witness():
    points, triangles = schoenhardt_prism()
    with pytest.raises(sweepcdt.NoCdtError) as e:
        sweepcdt.tetrahedralize(points, triangles, steiner="none")
    assert e.value.exit_code == 4
    assert len(e.value.witness) >= 3 and all(0 <= v < 6 for v in e.value.witness)
    assert "witness vertices" in str(e.value)
    # With Steiner points it has one.
    mesh = sweepcdt.tetrahedralize(points, triangles, steiner="auto", check=True)
    assert mesh.stats["steiner_points"] > 0


def test_invalid_surfaces_name_their_problems(shared_data, tmp_path):
    with pytest.raises(sweepcdt.InvalidInputError) as e:
        sweepcdt.mesh_file(shared_file(shared_data, "bad/open_cube.off"), tmp_path / "never_written.mesh")
    assert not (tmp_path / "never_written.mesh").exists()
    assert e.value.exit_code == 3 and "open_cube.off" in str(e.value)
    assert e.value.problems and e.value.problems[0][0] == "boundary-edge"
    with pytest.raises(sweepcdt.InvalidInputError, match="intersect"):
        sweepcdt.tetrahedralize(*sweepcdt.read_surface(shared_file(shared_data, "bad/selfintersect_issue945e_ascii.stl")))


def test_malformed_and_missing_files(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(sweepcdt.InvalidInputError, match=r"bad.off") as e:
        sweepcdt.read_surface(bad)
    assert e.value.file.endswith("bad.off")
    with pytest.raises(sweepcdt.InvalidInputError, match="missing.stl"):
        sweepcdt.read_surface(tmp_path / "missing.stl")


def test_output_error_leaves_nothing(tmp_path, shared_data):
    ico = shared_file(shared_data, "off/icosahedron.off")
    first = tmp_path / "ok.vtu"
    with pytest.raises(sweepcdt.OutputError) as e:
        sweepcdt.mesh_file(ico, [first, tmp_path / "no" / "such" / "dir.mesh"])
    assert e.value.exit_code == 5 and isinstance(e.value, OSError)
    assert not first.exists()  # written first, removed again: a conversion completes or leaves nothing
    with pytest.raises(ValueError, match="unknown extension"):
        sweepcdt.mesh_file(ico, tmp_path / "x.txt")


def test_progress_returning_false_cancels():
    points, triangles = unit_cube()
    with pytest.raises(sweepcdt.CancelledError) as e:
        sweepcdt.tetrahedralize(points, triangles, progress=lambda *a: False)
    assert e.value.exit_code == 130


class Stop(Exception):
    pass


def test_callback_exception_propagates_and_the_next_run_works():
    points, triangles = unit_cube()

    def progress(phase, done, total):
        if phase != "checking surface":
            raise Stop(phase)

    with pytest.raises(Stop):
        sweepcdt.tetrahedralize(points, triangles, progress=progress)
    assert len(sweepcdt.tetrahedralize(points, triangles).tetrahedra) > 0


def test_keyboard_interrupt_from_callback():
    points, triangles = unit_cube()

    def progress(phase, done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweepcdt.tetrahedralize(points, triangles, progress=progress)

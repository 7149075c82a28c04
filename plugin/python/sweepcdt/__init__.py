"""sweepcdt: exact constrained Delaunay tetrahedralizations (Shewchuk's sweep algorithms) for numpy.

    import sweepcdt
    points, triangles = sweepcdt.read_surface("part.stl")
    mesh = sweepcdt.tetrahedralize(points, triangles)      # a TetMesh: points, tetrahedra, regions, ...
    mesh.to_meshio().write("part.vtu")                     # with meshio installed
    edit = sweepcdt.EditableCdt.from_tet_mesh(mesh)         # delete vertices (paper §5)
    sweepcdt.mesh_file("part.stl", "part.inp")              # file to file, as `sweepcdt mesh` does

Options are the converter's (``sweepcdt help mesh``), spelled the same: ``algorithm``
(``sweepcdt.ALGORITHMS``: "cavity-sweep", "sweep-sphere", "sweep-plane", "giftwrap"), ``steiner`` ("auto", "none"), ``facets``
("triangles", "coplanar"), ``snap`` (None, or a tolerance such as 1e-12), ``check``; their defaults
are the converter's (``sweepcdt.DEFAULTS``). Failures raise the exceptions of ``sweepcdt.errors``
(``InvalidInputError``, ``NoCdtError``, ``VertexRemovalError``, ``OutputError``, ``CheckError``), bad arrays ``ValueError``;
computations release the GIL, and Ctrl-C raises KeyboardInterrupt after cancelling cleanly.
"""

import os

from . import errors
from ._sweepcdt import algorithms as _algorithms
from ._sweepcdt import cdt as _cdt
from ._sweepcdt import check_files as _check_files
from ._sweepcdt import defaults as _defaults
from ._sweepcdt import mesh_file as _mesh_file
from ._sweepcdt import read_surface as _read_surface
from ._sweepcdt import read_volume_mesh as _read_volume_mesh
from ._sweepcdt import tetrahedralize as _tetrahedralize
from ._sweepcdt import write_volume_mesh as _write_volume_mesh
from .editable import EditableCdt, EditedTriangulation, RemovalReport
from .errors import CancelledError, CheckError, Error, InvalidInputError, NoCdtError, OutputError, VertexRemovalError
from .result import Surface, TetMesh, Triangulation

__all__ = [
    "tetrahedralize", "read_surface", "mesh_file", "cdt", "read_volume_mesh", "write_volume_mesh", "check_files", "DEFAULTS", "ALGORITHMS", "TetMesh", "Triangulation", "Surface",
    "EditableCdt", "EditedTriangulation", "RemovalReport",
    "Error", "InvalidInputError", "NoCdtError", "VertexRemovalError", "OutputError", "CheckError", "CancelledError",
]

#: The converter's defaults (read from its own option parser), used by every function here.
DEFAULTS = _defaults()
#: The values ``algorithm`` takes, the default first.
ALGORITHMS = _algorithms()


def tetrahedralize(points, triangles, *, algorithm=DEFAULTS["algorithm"], steiner=DEFAULTS["steiner"],
                   facets=DEFAULTS["facets"], snap=None, check=False, progress=None, name="input"):
    """Tetrahedralize the volume bounded by a closed triangle surface.

    points: (n, 3) array of real numbers; triangles: (m, 3) array of point ids (any integer dtype).
    The surface must be closed, manifold and free of self-intersections; shells nested inside
    others are cavities (or bodies inside cavities); orientation is repaired per shell. Points are
    used exactly (no tolerance anywhere): exactly equal points are merged.

    algorithm: "cavity-sweep" (default), "sweep-sphere", "sweep-plane" or "giftwrap".
    steiner: "auto" adds Steiner points on the surface where it has no CDT as given; "none" raises
        NoCdtError instead.
    facets: "triangles" (every input triangle is a facet) or "coplanar" (edge-adjacent, exactly
        coplanar triangles form one polygonal facet: fewer Steiner points).
    snap: None, or a tolerance relative to the bounding-box diagonal (e.g. 1e-12, at most 1e-3):
        first snap coordinates that differ by CAD rounding noise (``sweepcdt --snap``).
    check: validate the result exactly once more; raise CheckError if it is not a valid CDT.
    progress: None or a callable ``progress(phase: str, done: int, total: int)``, called now and
        then from the computing thread; returning False cancels (CancelledError), raising cancels
        with that exception.
    name: how messages name the input.

    Returns a TetMesh (points, tetrahedra, regions, triangles, triangle_ids, steiner_triangles,
    point_ids, stats). Raises ValueError/TypeError for malformed arrays, InvalidInputError (a
    ValueError) naming the point or triangle for NaN coordinates, ids out of range and surfaces that
    do not bound a volume, NoCdtError (with .witness), CheckError, KeyboardInterrupt on Ctrl-C.
    """
    return TetMesh(_tetrahedralize(points, triangles, algorithm, steiner, facets, snap, check, progress, name))


def read_surface(path):
    """Read a triangle surface from any format the converter reads (OFF, STL ascii/binary, OBJ, PLY,
    glTF/GLB with Draco, Draco .drc; recognised by content). Returns a Surface (``points``,
    ``triangles`` as stored, ``format``), which also unpacks as ``points, triangles``. Raises
    InvalidInputError naming the file and line/byte/element."""
    return Surface(_read_surface(os.fspath(path)))


def mesh_file(input, output, *, format=None, algorithm=DEFAULTS["algorithm"], steiner=DEFAULTS["steiner"],
              facets=DEFAULTS["facets"], snap=None, check=False, progress=None):
    """Mesh a surface file into volume-mesh files, as ``sweepcdt mesh INPUT -o OUTPUT`` does.

    output: a path or a list of paths (one computation, several files). The format comes from each
    extension (.mesh Medit, .vtu, .msh Gmsh 4.1, .node TetGen .node/.ele/.face, .inp
    Abaqus/CalculiX) or from ``format`` ("mesh", "vtu", "msh", "msh22", "node", "inp").
    Every file is written atomically; if one cannot be written (OutputError), the ones already
    written by this call are removed. Other keywords as for tetrahedralize(). Returns the TetMesh.
    """
    outputs = [output] if isinstance(output, (str, bytes, os.PathLike)) else list(output)
    return TetMesh(_mesh_file(os.fspath(input), [os.fspath(o) for o in outputs], format, algorithm, steiner, facets,
                              snap, check, progress))


def cdt(points, simplices, *, exterior=None, tags=None, algorithm=DEFAULTS["algorithm"], steiner="none",
        facets=DEFAULTS["facets"], check=False, progress=None):
    """The constrained Delaunay triangulation of a PLC in dimension D = 2..5 (``sweepcdt cdt``).

    points: (n, D) real array; simplices: (m, D) point ids, the constraining (D-1)-simplices
    (segments in 2D, triangles in 3D, ...). exterior: None (the domain is the convex hull), or (m,)
    integers per simplex: -1 if its negative side is exterior, 1 if its positive side is, 0 if
    neither (the positive side of (f_0..f_{D-1}) holds the p with orient(f_0, ..., f_{D-1}, p) > 0;
    a closed surface counterclockwise from outside has -1 everywhere). tags: None or (m,) ids.
    steiner: "none" (default: the PLC as given) or "auto" (D = 3 only). facets (D = 3 only):
    "coplanar" (default: exactly coplanar neighbouring triangles form one facet, triangulated anew
    by its 2D CDT) or "triangles" (each triangle stays a constraint as given). Returns a
    Triangulation.
    """
    return Triangulation(_cdt(points, simplices, exterior, tags, algorithm, steiner, facets, check, progress))


def read_volume_mesh(path):
    """Read a volume mesh in any format the converter writes (.mesh, .vtu, .msh, .node/.ele/.face,
    .inp) as a TetMesh (its stats hold the counts only). Raises InvalidInputError naming the file."""
    return TetMesh(_read_volume_mesh(os.fspath(path)))


def write_volume_mesh(path, mesh=None, *, points=None, tetrahedra=None, regions=None, triangles=None,
                      triangle_ids=None, format=None):
    """Write a TetMesh (or the arrays: points (n, 3), tetrahedra (t, 4) with det[b-a, c-a, d-a] > 0,
    optional regions (t,), boundary triangles (b, 3) and their triangle_ids (b,)) to a volume-mesh
    file, format from the extension or ``format`` as in mesh_file(). Atomic; OutputError if the file
    cannot be written."""
    if mesh is not None:
        points, tetrahedra, regions = mesh.points, mesh.tetrahedra, mesh.regions
        triangles, triangle_ids = mesh.triangles, mesh.triangle_ids
    _write_volume_mesh(os.fspath(path), points, tetrahedra, regions, triangles, triangle_ids, format)


def check_files(input, output, *, facets=DEFAULTS["facets"], snap=None):
    """Verify exactly, as ``sweepcdt check INPUT OUTPUT`` does, that the volume-mesh file ``output`` is
    the CDT of the surface file ``input``, trusting only its points and tetrahedra. ``facets`` and
    ``snap``: the ones the mesh was made with. Returns a dict: ``valid``, ``problems`` (the first
    ones, one line each), ``total_problems``, ``steiner_points``, ``boundary_triangles``,
    ``perturbation_order``, ``suggest_coplanar``/``suggest_triangles`` (it passes in the other
    facets mode), ... Raises InvalidInputError when a file cannot be read."""
    return _check_files(os.fspath(input), os.fspath(output), facets, snap)

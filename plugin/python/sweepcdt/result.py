"""Results of sweepcdt: numpy arrays with their meaning attached."""

import numpy as np


class TetMesh:
    """The tetrahedralization of a closed surface (``sweepcdt.tetrahedralize``, ``mesh_file``).

    Attributes (numpy arrays):

    * ``points`` (n, 3) float64: the welded input points first (``num_input_points`` of them, as the
      converter numbers them: exactly equal points merged, in order of first use by the triangles,
      unused ones dropped; ``point_ids`` maps input rows to these), then Steiner points.
    * ``tetrahedra`` (t, 4) int64: point ids, each tetrahedron positively oriented
      (VTK/Gmsh/TetGen/Medit order: ``det[b-a, c-a, d-a] > 0``).
    * ``regions`` (t,) int32: region id per tetrahedron (a connected part of the domain).
    * ``triangles`` (b, 3) int64: the boundary triangles, counterclockwise seen from outside.
    * ``triangle_ids`` (b,) int64: for each boundary triangle, the input triangle (its row in the
      ``triangles`` given) it lies on: boundary patches keep their input face.
    * ``steiner_triangles`` (n - num_input_points,) int64: per Steiner point, the input triangle it
      lies on, or -1 for a point inside the domain.
    * ``point_ids`` (input points,) int64: per input point, its row in ``points`` (-1: unused).
    * ``stats``: dict of counts (``tetrahedra``, ``steiner_points``, ``regions``, ...), the
      algorithm that ran and the seconds of each phase.
    """

    def __init__(self, data):
        self.points = data["points"]
        self.tetrahedra = data["tetrahedra"]
        self.regions = data["regions"]
        self.triangles = data["triangles"]
        self.triangle_ids = data["triangle_ids"]
        self.steiner_triangles = data["steiner_triangles"]
        self.point_ids = data["point_ids"]
        self.num_input_points = int(data["num_input_points"])
        self.stats = data["stats"]

    @property
    def steiner_points(self):
        """The Steiner points, (k, 3): ``points[num_input_points:]``."""
        return self.points[self.num_input_points:]

    def to_meshio(self, boundary=False):
        """This mesh as a ``meshio.Mesh`` (needs meshio: Debian ``python3-meshio``).

        Cell data ``"region"`` holds the region ids. With ``boundary=True`` the boundary triangles
        are a second cell block, and cell data ``"face_id"`` holds their input triangle (-1 for
        tetrahedra; region 0 for triangles).
        """
        import meshio  # optional dependency

        if not boundary:
            return meshio.Mesh(self.points, [("tetra", self.tetrahedra)], cell_data={"region": [self.regions]})
        t, b = len(self.tetrahedra), len(self.triangles)
        return meshio.Mesh(
            self.points,
            [("tetra", self.tetrahedra), ("triangle", self.triangles)],
            cell_data={
                "region": [self.regions, np.zeros(b, dtype=np.int32)],
                "face_id": [np.full(t, -1, dtype=np.int64), self.triangle_ids],
            },
        )

    def __repr__(self):
        s = self.stats
        return (f"<sweepcdt.TetMesh: {len(self.points)} points ({s['steiner_points']} Steiner), "
                f"{len(self.tetrahedra)} tetrahedra, {len(self.triangles)} boundary triangles, "
                f"{s['regions']} regions ({s['algorithm']}, {s['seconds_total']:.2f} s)>")


class Triangulation:
    """The CDT of a PLC of any dimension D = 2..5 (``sweepcdt.cdt``).

    * ``points`` (n, D) float64: the input points first (``num_input_points``), then Steiner points.
    * ``simplices`` (s, D + 1) int64: positively oriented simplices, det[p_1 - p_0, ..., p_D - p_0] > 0.
    * ``regions`` (s,) int32: region ids (empty for convex-hull domains).
    * ``steiner_simplices``: per Steiner point, the constraining simplex it lies on, or -1.
    * ``stats``: dict (algorithm, counts, seconds).
    """

    def __init__(self, data):
        self.dimension = int(data["dimension"])
        self.points = data["points"]
        self.simplices = data["simplices"]
        self.regions = data["regions"]
        self.num_input_points = int(data["num_input_points"])
        self.steiner_simplices = data["steiner_simplices"]
        self.stats = data["stats"]

    def __repr__(self):
        return (f"<sweepcdt.Triangulation: D={self.dimension}, {len(self.points)} points, "
                f"{len(self.simplices)} simplices ({self.stats['algorithm']})>")


class Surface:
    """A triangle surface as read from a file (``sweepcdt.read_surface``): ``points`` (n, 3) and
    ``triangles`` (m, 3) exactly as stored (not welded; polygons fan-triangulated in order), and the
    ``format`` detected from the content."""

    def __init__(self, data):
        self.points = data["points"]
        self.triangles = data["triangles"]
        self.format = data["format"]

    def __iter__(self):  # points, triangles = sweepcdt.read_surface(path)
        return iter((self.points, self.triangles))

    def __repr__(self):
        return f"<sweepcdt.Surface ({self.format}): {len(self.points)} points, {len(self.triangles)} triangles>"

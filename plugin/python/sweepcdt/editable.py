"""Vertex deletion (paper §5): a CDT that can be edited, and what it gives back."""

import numpy as np

from . import _sweepcdt
from .errors import NoCdtError, VertexRemovalError
from .result import TetMesh, Triangulation

_DEFAULTS = _sweepcdt.defaults()  # the converter's, as sweepcdt.DEFAULTS


class EditableCdt:
    """A PLC and its constrained Delaunay triangulation, kept in step while vertices are deleted.

        cdt = sweepcdt.EditableCdt(points, constraints, exterior=exterior)   # any D = 2..5
        cdt = sweepcdt.EditableCdt.from_tet_mesh(sweepcdt.tetrahedralize(points, triangles))
        cdt.remove_vertex(17)                        # NoCdtError / VertexRemovalError: unchanged
        report = cdt.remove_vertices([3, 4, 5])      # report.removed, report.refused
        mesh = cdt.snapshot()                        # points, simplices, constraints, old_ids, ...

    Deleting vertex v empties its star (the simplices holding it) and fills the hole with the CDT
    of the polytope its link bounds, by the inward sweep of paper §5: time proportional to the
    star's size (times a log), not to the mesh's. A vertex may lie inside the domain, or inside a
    facet (a flat group of constraining simplices, with equal tags when there are tags; in 3D also
    on a straight facet edge between its two neighbours along it): the facet is then triangulated
    anew without it. Every deletion is
    checked exactly; one that would leave a PLC without a CDT raises NoCdtError and changes nothing.

    Vertex ids are those of the points given (for a TetMesh: its rows of ``points``) and do not
    change while editing; ``snapshot()`` numbers the vertices left anew, in the same order, and maps
    them back (``old_ids``).

    Construction computes the CDT like ``sweepcdt.cdt()``: ``constraints`` (m, D) point ids are
    cdt()'s ``simplices`` (None: none, the Delaunay triangulation of the points' convex hull),
    ``exterior``, ``tags``, ``algorithm``, ``steiner`` ("none" or, in 3D, "auto": the Steiner
    points cdt() keeps become vertices with ids after the input's) and ``facets`` (3D) as there; ``progress`` as
    for tetrahedralize(). Raises what cdt() raises.
    """

    def __init__(self, points, constraints=None, *, exterior=None, tags=None, algorithm=_DEFAULTS["algorithm"],
                 steiner="none", facets=_DEFAULTS["facets"], progress=None):
        if constraints is None:
            constraints = np.zeros((0, np.shape(points)[1] if np.ndim(points) == 2 else 0), dtype=np.int64)
        self._cdt = _sweepcdt.editable_from_plc(points, constraints, exterior, tags, algorithm, steiner, facets, progress)

    @classmethod
    def from_triangulation(cls, points, simplices, constraints, *, exterior=None, tags=None, regions=None):
        """An EditableCdt of a triangulation you already have, in any D = 2..5.

        points (n, D); simplices (s, D + 1) positively oriented, det[p_1 - p_0, ..., p_D - p_0] > 0
        (as cdt() and tetrahedralize() return them); constraints (m, D), exterior (m,) and tags as
        for cdt(); regions (s,) or None. The simplices must be the CDT of the constraints — they are
        validated exactly (raising CheckError, with ``failures``, if not), under the first of
        cdt()'s perturbation orders that makes them one, as ``sweepcdt check`` does. Bad PLCs raise
        InvalidInputError, bad arrays ValueError.
        """
        self = cls.__new__(cls)
        self._cdt = _sweepcdt.editable_from_triangulation(points, simplices, constraints, exterior, tags, regions)
        return self

    @classmethod
    def from_tet_mesh(cls, mesh):
        """An EditableCdt of a TetMesh (from tetrahedralize(), mesh_file() or read_volume_mesh()):
        its tetrahedra, constrained by its boundary triangles (outside their counterclockwise side,
        tagged with ``triangle_ids``), validated as in from_triangulation().

        Triangles with different ``triangle_ids`` belong to different facets: in a mesh made with
        facets="coplanar" (the default) a flat face is one facet, whose inner vertices can go; with
        facets="triangles" every input triangle is a facet, and its corners stay."""
        exterior = np.full(len(mesh.triangles), -1, dtype=np.int64)  # counterclockwise from outside
        return cls.from_triangulation(mesh.points, mesh.tetrahedra, mesh.triangles, exterior=exterior,
                                      tags=mesh.triangle_ids, regions=mesh.regions)

    @property
    def dimension(self):
        """D, 2..5."""
        return self._cdt.dimension

    @property
    def num_vertices(self):
        """Vertices left."""
        return self._cdt.num_vertices

    @property
    def num_simplices(self):
        """Simplices (triangles, tetrahedra, ...) now."""
        return self._cdt.num_simplices

    @property
    def vertices(self):
        """The ids of the vertices left, ascending (an int64 array; a snapshot: O(size of the mesh))."""
        return self.snapshot().old_ids

    def has_vertex(self, v):
        """Whether v is (still) a vertex of the triangulation."""
        return self._cdt.has_vertex(v)

    __contains__ = has_vertex

    def remove_vertex(self, v):
        """Delete vertex v. Raises NoCdtError (the PLC without v has no CDT; ``witness`` names the
        face) or VertexRemovalError (v cannot be deleted); either way the CDT is unchanged and the
        exception's ``vertex`` is v."""
        try:
            self._cdt.remove_vertex(v)
        except (NoCdtError, VertexRemovalError) as e:
            e.vertex = v
            raise

    def remove_vertices(self, vertices, *, progress=None):
        """Delete the vertices in the order given, going on past refusals.

        Returns a RemovalReport: ``removed`` (the ids deleted, in order) and ``refused`` (a list of
        ``(id, exception)``, the NoCdtError or VertexRemovalError that remove_vertex() would have
        raised). The order matters: a vertex refused early may be deletable after others have gone.
        ``progress`` as for tetrahedralize() (phase "deleting vertices"); cancelling keeps the
        deletions made so far (each one is whole) and raises.
        """
        ids = np.asarray(vertices).reshape(-1)
        if ids.size and ids.dtype.kind not in "iu":  # a float is no vertex id: refuse it instead of truncating
            raise TypeError(f"vertices must be integer ids, not dtype {ids.dtype}")
        removed, refused = self._cdt.remove_vertices(ids.astype(np.int64).tolist(), progress)
        return RemovalReport(removed, refused)

    def snapshot(self):
        """The triangulation now, as an EditedTriangulation (a Triangulation with the PLC it is the
        CDT of and the map to the ids here). O(size of the mesh)."""
        return EditedTriangulation(self._cdt.snapshot())

    def plc_without(self, v):
        """The PLC that remove_vertex(v) would leave (facets through v triangulated anew as it
        would), numbered as snapshot() would then number it: a dict with ``points``,
        ``constraints``, ``exterior`` and ``tags`` (None when absent), ``old_ids``. ``cdt()`` of it
        fails exactly when remove_vertex(v) does. Raises VertexRemovalError as remove_vertex()."""
        return self._cdt.plc_without(v)

    def __repr__(self):
        return (f"<sweepcdt.EditableCdt: D={self.dimension}, {self.num_vertices} vertices, "
                f"{self.num_simplices} simplices>")


class RemovalReport:
    """What EditableCdt.remove_vertices() did: ``removed`` (ids deleted, in order) and ``refused``
    (``(id, exception)`` pairs, in order)."""

    def __init__(self, removed, refused):
        self.removed = list(removed)
        self.refused = list(refused)

    @property
    def refused_ids(self):
        """The ids refused, in order."""
        return [v for v, _ in self.refused]

    def __repr__(self):
        return f"<sweepcdt.RemovalReport: {len(self.removed)} removed, {len(self.refused)} refused>"


class EditedTriangulation(Triangulation):
    """A snapshot of an EditableCdt: the Triangulation's attributes (``points``, ``simplices``
    positively oriented, ``regions``, ``num_input_points``, ``steiner_simplices``) and

    * ``constraints`` (m, D) int64: the constraining simplices of the PLC now (facets through
      deleted vertices triangulated anew); ``exterior`` (m,) and ``tags`` (m,): as cdt() takes them,
      or None when the PLC has none (exterior None: a convex-hull domain).
    * ``old_ids`` (n,) int64: per point here, its id in the EditableCdt (= in the input).
    * ``perturbation_rank``: None (perturbed by id, paper §6), or the order the CDT is under.

    ``sweepcdt.cdt(s.points, s.constraints, exterior=s.exterior, tags=s.tags)`` computes the same
    triangulation from scratch (in 3D with ``facets="triangles"``, since the facets are given here
    already triangulated).
    """

    def __init__(self, data):
        data = dict(data)
        n = len(data["points"])
        data["stats"] = {"algorithm": "edited", "simplices": len(data["simplices"]),
                         "steiner_points": n - int(data["num_input_points"])}
        super().__init__(data)
        self.constraints = data["constraints"]
        self.exterior = data["exterior"]
        self.tags = data["tags"]
        self.old_ids = data["old_ids"]
        self.perturbation_rank = data["perturbation_rank"]
        self.num_ids = int(data["num_ids"])  # the EditableCdt's ids are 0 .. num_ids - 1

    def to_tet_mesh(self):
        """This 3D triangulation as a TetMesh, e.g. for write_volume_mesh(): its boundary triangles
        are the constraints with an exterior side, counterclockwise from outside, ``triangle_ids``
        their tags (or constraint rows); ``point_ids`` maps the EditableCdt's ids to rows (-1:
        deleted)."""
        if self.dimension != 3:
            raise ValueError(f"to_tet_mesh() needs a 3D triangulation, not D = {self.dimension}")
        if self.exterior is None:
            raise ValueError("to_tet_mesh() needs a facet-bounded domain (exterior notations); this one is a convex hull")
        side = np.asarray(self.exterior)
        keep = side != 0
        triangles = self.constraints[keep].copy()
        flip = side[keep] == 1  # positive side outside: reversed to be counterclockwise from outside
        triangles[flip] = triangles[flip][:, [0, 2, 1]]
        ids = self.tags if self.tags is not None else np.arange(len(self.constraints), dtype=np.int64)
        point_ids = np.full(self.num_ids, -1, dtype=np.int64)
        point_ids[self.old_ids] = np.arange(len(self.old_ids))
        regions = self.regions if len(self.regions) == len(self.simplices) else np.zeros(len(self.simplices), np.int32)
        return TetMesh({
            "points": self.points, "tetrahedra": self.simplices, "regions": regions, "triangles": triangles,
            "triangle_ids": np.asarray(ids, dtype=np.int64)[keep], "steiner_triangles": self.steiner_simplices,
            "point_ids": point_ids, "num_input_points": self.num_input_points,
            "stats": {"tetrahedra": len(self.simplices), "steiner_points": len(self.steiner_simplices),
                      "regions": len(set(regions.tolist())), "algorithm": "edited", "seconds_total": 0.0},
        })

    def __repr__(self):
        return (f"<sweepcdt.EditedTriangulation: D={self.dimension}, {len(self.points)} points, "
                f"{len(self.simplices)} simplices, {len(self.constraints)} constraints>")

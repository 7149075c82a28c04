"""The Tetrahedralize command's logic, without GUI: a FreeCAD solid becomes a Fem::FemMeshObject.

    import sweepcdt_femmesh
    mesh_obj, result = sweepcdt_femmesh.tetrahedralize_object(doc.Box, deflection=0.1)

Works in freecadcmd and in the GUI; the GUI command (sweepcdt_gui.py) only collects the options and
reports. All geometry is sweepcdt's (the `sweepcdt` Python module); this file converts between
FreeCAD's objects and arrays.
"""

import time

import FreeCAD
import numpy as np

import sweepcdt

#: Options of the command, with the values a FreeCAD user starts from. The algorithm and Steiner mode
#: are the converter's defaults; facets "coplanar" because CAD solids have planar faces made of many
#: triangles, which then need far fewer Steiner points.
DEFAULTS = {
    "algorithm": sweepcdt.DEFAULTS["algorithm"],
    "steiner": sweepcdt.DEFAULTS["steiner"],
    "facets": "coplanar",
    "deflection": 0.1,           # mm: MeshPart LinearDeflection (largest distance surface - triangles)
    "angular_deflection": 0.5,   # rad: MeshPart AngularDeflection
}


#: The algorithms the command offers, the default first.
ALGORITHMS = sweepcdt.ALGORITHMS


class SweepCDTError(Exception):
    """Why an object cannot be meshed (not a solid, not closed, no CDT, ...): the message is the
    converter's."""


def surface_of(obj, deflection=DEFAULTS["deflection"], angular_deflection=DEFAULTS["angular_deflection"]):
    """The closed triangle surface of a Part feature (tessellated with MeshPart) or a Mesh feature,
    as numpy arrays (points (n, 3), triangles (m, 3))."""
    if hasattr(obj, "Mesh") and obj.isDerivedFrom("Mesh::Feature"):
        mesh = obj.Mesh
    elif hasattr(obj, "Shape"):
        shape = obj.Shape
        if shape.isNull() or not shape.Solids:
            raise SweepCDTError(f"{obj.Label}: not a solid (a Part feature with a solid, or a closed Mesh feature)")
        if not deflection > 0:
            raise SweepCDTError(f"deflection must be > 0, not {deflection}")
        import MeshPart
        mesh = MeshPart.meshFromShape(Shape=shape, LinearDeflection=float(deflection),
                                      AngularDeflection=float(angular_deflection), Relative=False)
        # A placement of a Part feature is in its Shape already; a Mesh feature's is applied below.
    else:
        raise SweepCDTError(f"{obj.Label}: not a Part or Mesh feature")
    vertices, facets = mesh.Topology
    points = np.array([(v.x, v.y, v.z) for v in vertices], dtype=float).reshape(-1, 3)
    triangles = np.array(facets, dtype=np.int64).reshape(-1, 3)
    return points, triangles


def femmesh_of(result):
    """A Fem.FemMesh of a sweepcdt.TetMesh: nodes 1..n, linear tetrahedra 1..t, boundary triangles
    t+1..t+b; a volume group per region ("Region1", ...) and a face group "Boundary"."""
    import Fem

    fm = Fem.FemMesh()
    for i, (x, y, z) in enumerate(result.points.tolist(), start=1):
        fm.addNode(x, y, z, i)
    # SMESH (FreeCAD) orders tetrahedra with the first two nodes swapped relative to VTK/Abaqus, whose
    # order sweepcdt returns (see shared HOSTS.md 1.3): its .inp writer swaps them back for CalculiX.
    t = len(result.tetrahedra)
    for e, (a, b, c, d) in enumerate((result.tetrahedra + 1).tolist(), start=1):
        fm.addVolume([b, a, c, d], e)
    for f, tri in enumerate((result.triangles + 1).tolist(), start=t + 1):
        fm.addFace(tri, f)
    for region in np.unique(result.regions).tolist():
        group = fm.addGroup(f"Region{region + 1}", "Volume")
        fm.addGroupElements(group, (np.flatnonzero(result.regions == region) + 1).tolist())
    if len(result.triangles):
        group = fm.addGroup("Boundary", "Face")
        fm.addGroupElements(group, list(range(t + 1, t + 1 + len(result.triangles))))
    return fm


def tetrahedralize_object(obj, doc=None, analysis=None, name=None, progress=None, **options):
    """Tetrahedralize a Part feature with a solid, or a closed Mesh feature; add the result to `doc`
    (default: obj's document) as a Fem::FemMeshObject, inside `analysis` when given.

    options: deflection, angular_deflection (Part tessellation), algorithm, steiner, facets, snap,
    check (as sweepcdt.tetrahedralize). Returns (mesh_object, sweepcdt.TetMesh, seconds).
    Raises SweepCDTError with the converter's message; the document is unchanged then.
    """
    o = dict(DEFAULTS)
    o.update(options)
    doc = doc or obj.Document
    start = time.perf_counter()
    points, triangles = surface_of(obj, o.pop("deflection"), o.pop("angular_deflection"))
    try:
        result = sweepcdt.tetrahedralize(points, triangles, name=obj.Label, progress=progress, **o)
    except sweepcdt.Error as e:
        raise SweepCDTError(str(e)) from e
    fm = femmesh_of(result)
    mesh_obj = doc.addObject("Fem::FemMeshObject", name or f"{obj.Name}_TetMesh")
    mesh_obj.FemMesh = fm
    mesh_obj.Label = name or f"{obj.Label} tetrahedra"
    if analysis is not None:
        analysis.addObject(mesh_obj)
    doc.recompute()
    return mesh_obj, result, time.perf_counter() - start


def summary(result, seconds):
    """One line for the report view: "1234 tetrahedra, 12 Steiner points, 2 regions (sweep-sphere, 0.31 s)"."""
    s = result.stats
    return (f"{s['tetrahedra']} tetrahedra, {len(result.points)} nodes, {s['steiner_points']} Steiner points, "
            f"{s['regions']} regions ({s['algorithm']}, {seconds:.2f} s)")

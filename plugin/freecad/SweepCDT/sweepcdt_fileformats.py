"""File > Open / Import / Export of the volume-mesh formats sweepcdt writes that FreeCAD does not read
itself: Medit .mesh, Gmsh .msh, TetGen .node/.ele (registered in Init.py). Reading and writing are
sweepcdt's (sweepcdt.read_volume_mesh / write_volume_mesh); this file converts to and from
Fem::FemMeshObject. FreeCAD's importer protocol: open(), insert(), export()."""

import builtins  # noqa: F401  (this module's open() shadows the builtin: use builtins.open if needed)
import os

import FreeCAD
import numpy as np

import sweepcdt
import sweepcdt_femmesh


def _add_mesh(doc, filename):
    try:
        result = sweepcdt.read_volume_mesh(filename)
    except sweepcdt.Error as e:
        FreeCAD.Console.PrintError(f"SweepCDT: {e}\n")
        raise
    name = os.path.splitext(os.path.basename(filename))[0]
    obj = doc.addObject("Fem::FemMeshObject", name)
    obj.FemMesh = sweepcdt_femmesh.femmesh_of(result)
    doc.recompute()
    return obj


def open(filename):
    """A new document holding the mesh of `filename`."""
    doc = FreeCAD.newDocument(os.path.splitext(os.path.basename(filename))[0])
    _add_mesh(doc, filename)
    return doc


def insert(filename, docname):
    """The mesh of `filename` added to document `docname`."""
    try:
        doc = FreeCAD.getDocument(docname)
    except NameError:
        doc = FreeCAD.newDocument(docname)
    FreeCAD.ActiveDocument = doc
    return _add_mesh(doc, filename)


def arrays_of(femmesh):
    """points, tetrahedra (det[b-a, c-a, d-a] > 0), regions, boundary triangles of a FemMesh with
    linear or quadratic tetrahedra (quadratic ones are written by their corners)."""
    node_ids = sorted(femmesh.Nodes)
    row = {nid: i for i, nid in enumerate(node_ids)}
    nodes = femmesh.Nodes
    points = np.array([(nodes[i].x, nodes[i].y, nodes[i].z) for i in node_ids], dtype=float).reshape(-1, 3)
    tets, volume_ids = [], []
    for e in femmesh.Volumes:
        n = femmesh.getElementNodes(e)
        if len(n) not in (4, 10):
            raise ValueError(f"volume element {e} has {len(n)} nodes: only tetrahedra can be exported")
        # SMESH order has the first two corners swapped relative to VTK/Medit/Gmsh (HOSTS.md 1.3).
        tets.append((row[n[1]], row[n[0]], row[n[2]], row[n[3]]))
        volume_ids.append(e)
    if not tets:
        raise ValueError("the mesh has no tetrahedra")
    regions = np.zeros(len(tets), dtype=np.int64)
    index = {e: k for k, e in enumerate(volume_ids)}
    for g in femmesh.Groups:  # the workbench's "Region<k>" groups keep their region ids
        name = femmesh.getGroupName(g)
        if femmesh.getGroupElementType(g) == "Volume" and name.startswith("Region") and name[6:].isdigit():
            for e in femmesh.getGroupElements(g):
                if e in index:
                    regions[index[e]] = int(name[6:]) - 1
    triangles = [tuple(row[i] for i in femmesh.getElementNodes(f)[:3]) for f in femmesh.Faces]
    return points, np.array(tets), regions, np.array(triangles, dtype=np.int64).reshape(-1, 3)


def export(objects, filename):
    """Writes the first FEM mesh among `objects` (sweepcdt's writers; format from the extension)."""
    meshes = [o for o in objects if o.isDerivedFrom("Fem::FemMeshObject")]
    if not meshes:
        FreeCAD.Console.PrintError("SweepCDT: select a FEM mesh to export\n")
        return
    points, tets, regions, triangles = arrays_of(meshes[0].FemMesh)
    try:
        sweepcdt.write_volume_mesh(filename, points=points, tetrahedra=tets, regions=regions,
                                   triangles=triangles if len(triangles) else None)
    except (sweepcdt.Error, ValueError) as e:
        FreeCAD.Console.PrintError(f"SweepCDT: {e}\n")
        raise
    FreeCAD.Console.PrintMessage(f"SweepCDT: {meshes[0].Label} -> {filename}: {len(tets)} tetrahedra\n")

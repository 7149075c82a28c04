# The SweepCDT workbench headless (freecadcmd, FREECAD_USER_DATA pointing at a folder whose Mod/
# holds the repository's plugin/freecad/SweepCDT, so FreeCAD loads it as an installed workbench):
# the Part block with holes and a fillet becomes a FemMesh equal to the module's result on the same
# tessellation, with no inverted element; a CalculiX static analysis on it gives finite
# displacements; a non-closed Mesh feature gives the error, not a crash.
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import FreeCAD
import Fem
import Mesh
import MeshPart
import numpy as np

import sweepcdt
import sweepcdt_femmesh
from freecad_test_support import block_with_holes_and_fillet, run

DEFLECTION = 0.1


def inp_tetrahedra(path):
    """Nodes and C3D4 elements of an Abaqus file FreeCAD wrote (parsed here, not by FreeCAD)."""
    nodes, elements, section = {}, [], None
    with open(path) as f:
        for line in f:
            if line.startswith("*"):
                head = line.upper().replace(" ", "")
                section = "node" if head.startswith("*NODE") else "c3d4" if "TYPE=C3D4" in head else None
                continue
            fields = [x for x in line.replace(",", " ").split()]
            if section == "node" and fields:
                nodes[int(fields[0])] = [float(x) for x in fields[1:4]]
            elif section == "c3d4" and fields:
                elements.append([int(x) for x in fields[1:5]])
    return nodes, elements


class Workbench(unittest.TestCase):
    def test_loaded_as_a_workbench(self):
        # Init.py ran at start-up: its file types are registered.
        self.assertIn("sweepcdt_fileformats", FreeCAD.getImportType("mesh"))
        self.assertIn("sweepcdt_fileformats", FreeCAD.getExportType("node"))


class Block(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("SweepCDTHeadless")
        cls.part = cls.doc.addObject("Part::Feature", "Block")
        cls.part.Shape = block_with_holes_and_fillet()
        cls.doc.recompute()
        cls.mesh_obj, cls.result, cls.seconds = sweepcdt_femmesh.tetrahedralize_object(cls.part, deflection=DEFLECTION)
        print(f"\nBlock: {sweepcdt_femmesh.summary(cls.result, cls.seconds)}")

    def test_counts_equal_the_module_on_the_same_tessellation(self):
        m = MeshPart.meshFromShape(Shape=self.part.Shape, LinearDeflection=DEFLECTION,
                                   AngularDeflection=sweepcdt_femmesh.DEFAULTS["angular_deflection"], Relative=False)
        self.assertTrue(m.isSolid())
        v, f = m.Topology
        direct = sweepcdt.tetrahedralize([(p.x, p.y, p.z) for p in v], f, facets="coplanar")
        fm = self.mesh_obj.FemMesh
        self.assertEqual(fm.NodeCount, len(direct.points))
        self.assertEqual(fm.VolumeCount, len(direct.tetrahedra))
        self.assertEqual(fm.TetraCount, len(direct.tetrahedra))
        self.assertEqual(fm.TriangleCount, len(direct.triangles))
        self.assertGreater(fm.VolumeCount, 100)
        self.assertEqual(self.mesh_obj.TypeId, "Fem::FemMeshObject")

    def test_no_inverted_element_and_the_volume_is_the_parts(self):
        # What CalculiX reads: FreeCAD's own .inp writer output, parsed and measured here.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "block.inp")
            self.mesh_obj.FemMesh.write(path)
            nodes, elements = inp_tetrahedra(path)
        self.assertEqual(len(elements), self.mesh_obj.FemMesh.VolumeCount)
        p = np.array([[nodes[i] for i in e] for e in elements])
        vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6
        self.assertTrue((vol > 0).all(), f"{(vol <= 0).sum()} inverted C3D4 elements")
        # The tessellation's volume (facets lie inside the curved faces: slightly less than the B-rep).
        self.assertAlmostEqual(vol.sum() / self.part.Shape.Volume, 1.0, delta=0.01)

    def test_regions_and_boundary_groups(self):
        fm = self.mesh_obj.FemMesh
        names = {fm.getGroupName(g): g for g in fm.Groups}
        self.assertIn("Region1", names)
        self.assertIn("Boundary", names)
        self.assertEqual(len(fm.getGroupElements(names["Region1"])), fm.VolumeCount)

    def test_inside_the_analysis(self):
        import ObjectsFem
        analysis = ObjectsFem.makeAnalysis(self.doc, "AnalysisForGroupTest")
        mesh_obj, _, _ = sweepcdt_femmesh.tetrahedralize_object(self.part, analysis=analysis, deflection=DEFLECTION)
        self.assertIn(mesh_obj, analysis.Group)


class FileFormats(unittest.TestCase):
    def test_export_and_import_round_trip(self):
        import sweepcdt_fileformats
        doc = FreeCAD.newDocument("SweepCDTFiles")
        part = doc.addObject("Part::Feature", "Block")
        part.Shape = block_with_holes_and_fillet()
        doc.recompute()
        mesh_obj, result, _ = sweepcdt_femmesh.tetrahedralize_object(part, deflection=DEFLECTION)
        with tempfile.TemporaryDirectory() as d:
            for ext in ("mesh", "msh", "node"):
                path = os.path.join(d, f"block.{ext}")
                sweepcdt_fileformats.export([mesh_obj], path)
                back = sweepcdt.read_volume_mesh(path)  # the exported file holds the module's mesh
                np.testing.assert_array_equal(back.points, result.points)
                np.testing.assert_array_equal(back.tetrahedra, result.tetrahedra)
                np.testing.assert_array_equal(back.regions, result.regions)
                imported = sweepcdt_fileformats.insert(path, doc.Name)
                self.assertEqual(imported.FemMesh.VolumeCount, len(result.tetrahedra))
                self.assertEqual(imported.FemMesh.NodeCount, len(result.points))
                inp = os.path.join(d, "back.inp")
                imported.FemMesh.write(inp)
                nodes, elements = inp_tetrahedra(inp)
                p = np.array([[nodes[i] for i in e] for e in elements])
                vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
                self.assertTrue((vol > 0).all(), ext)
            # File > Open goes through FreeCAD's registry to this module.
            self.assertIn("sweepcdt_fileformats", FreeCAD.getImportType("ele"))
            opened = sweepcdt_fileformats.open(os.path.join(d, "block.mesh"))
            self.assertEqual(len([o for o in opened.Objects if o.TypeId == "Fem::FemMeshObject"]), 1)


class OpenMesh(unittest.TestCase):
    def test_non_closed_mesh_feature_gives_the_error(self):
        doc = FreeCAD.newDocument("SweepCDTOpen")
        cube = Mesh.createBox(10, 10, 10)
        facets = cube.Topology[1][:-1]  # one triangle missing: open
        open_mesh = Mesh.Mesh([[tuple(cube.Topology[0][i]) for i in f] for f in facets])
        self.assertFalse(open_mesh.isSolid())
        feature = doc.addObject("Mesh::Feature", "OpenCube")
        feature.Mesh = open_mesh
        doc.recompute()
        before = len(doc.Objects)
        with self.assertRaises(sweepcdt_femmesh.SweepCDTError) as e:
            sweepcdt_femmesh.tetrahedralize_object(feature)
        self.assertIn("open", str(e.exception))
        self.assertIn("OpenCube", str(e.exception))
        self.assertEqual(len(doc.Objects), before)  # nothing added

    def test_not_a_solid(self):
        doc = FreeCAD.newDocument("SweepCDTFace")
        import Part
        face = doc.addObject("Part::Feature", "Face")
        face.Shape = Part.makePlane(10, 10)
        with self.assertRaises(sweepcdt_femmesh.SweepCDTError):
            sweepcdt_femmesh.tetrahedralize_object(face)


if __name__ in ("__main__", "headless_test"):
    run([Workbench, Block, FileFormats, OpenMesh])

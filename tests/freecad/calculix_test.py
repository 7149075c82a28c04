# A static CalculiX analysis built with FreeCAD FEM on the SweepCDT mesh of the block (headless):
# steel, the face at x = 0 fixed, a force on the face at x = 40, FreeCAD's ccxtools run CalculiX
# (Debian calculix-ccx) and read the results back. The displacements must be finite, non-zero,
# zero on the fixed face, and point along the force.
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import FreeCAD
import ObjectsFem
import numpy as np
from femtools import ccxtools

import sweepcdt_femmesh
from freecad_test_support import block_with_holes_and_fillet, run


def face_at_x(shape, x):
    for i, f in enumerate(shape.Faces, start=1):
        bb = f.BoundBox
        if abs(bb.XMin - x) < 1e-9 and abs(bb.XMax - x) < 1e-9:
            return f"Face{i}"
    raise AssertionError(f"no planar face at x = {x}")


class CalculiX(unittest.TestCase):
    def fixed_block_analysis(self, name):
        """A document with the block, an analysis with the CalculiX solver, steel and the face at
        x = 0 fixed: what both tests load in their own way."""
        doc = FreeCAD.newDocument(name)
        part = doc.addObject("Part::Feature", "Block")
        part.Shape = block_with_holes_and_fillet()
        doc.recompute()
        analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
        solver = ObjectsFem.makeSolverCalculixCcxTools(doc, "CalculiXccxTools")
        solver.AnalysisType = "static"
        solver.GeometricalNonlinearity = "linear"
        solver.SplitInputWriter = False
        analysis.addObject(solver)
        material = ObjectsFem.makeMaterialSolid(doc, "Steel")
        mat = material.Material
        mat["Name"], mat["YoungsModulus"], mat["PoissonRatio"] = "CalculiX-Steel", "210000 MPa", "0.30"
        material.Material = mat
        analysis.addObject(material)
        fixed = ObjectsFem.makeConstraintFixed(doc, "Fixed")
        fixed.References = [(part, face_at_x(part.Shape, 0))]
        analysis.addObject(fixed)
        return doc, part, analysis, solver

    def ccx_tools(self, analysis, solver):
        """FreeCAD's ccxtools on the analysis, in a working folder of its own, the input file written."""
        fea = ccxtools.FemToolsCcx(analysis, solver)
        fea.update_objects()
        workdir = tempfile.TemporaryDirectory(prefix="sweepcdt_ccx_")
        self.addCleanup(workdir.cleanup)
        fea.setup_working_dir(workdir.name)
        self.assertEqual(fea.check_prerequisites(), "")
        fea.write_inp_file()
        return fea

    def test_static_analysis_gives_finite_displacements(self):
        doc, part, analysis, solver = self.fixed_block_analysis("SweepCDTCcx")
        force = ObjectsFem.makeConstraintForce(doc, "Force")
        force.References = [(part, face_at_x(part.Shape, 40))]
        force.Force = 10000.0  # N
        z_edges = [f"Edge{i}" for i, e in enumerate(part.Shape.Edges, start=1)
                   if e.Curve.__class__.__name__ == "Line" and abs(e.Curve.Direction.z) > 0.999]
        force.Direction = (part, [z_edges[0]])
        force.Reversed = False
        analysis.addObject(force)
        doc.recompute()

        mesh_obj, result, _ = sweepcdt_femmesh.tetrahedralize_object(part, analysis=analysis, deflection=0.1)

        fea = self.ccx_tools(analysis, solver)
        self.assertTrue(os.path.isfile(fea.inp_file_name))
        fea.setup_ccx()
        ret = fea.ccx_run()
        self.assertEqual(ret, 0, f"ccx failed: {fea.ccx_stderr if hasattr(fea, 'ccx_stderr') else ''}")
        fea.load_results()
        self.assertTrue(fea.results_present)
        results = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")]
        self.assertEqual(len(results), 1)
        disp = np.array([(v.x, v.y, v.z) for v in results[0].DisplacementVectors])
        self.assertEqual(len(disp), mesh_obj.FemMesh.NodeCount)
        self.assertTrue(np.isfinite(disp).all())
        largest = np.abs(disp).max()
        self.assertGreater(largest, 0)
        # Sign and place: the free end moves along the force (+z), the fixed face does not move.
        nodes = mesh_obj.FemMesh.Nodes
        ids = results[0].NodeNumbers
        x = np.array([nodes[i].x for i in ids])
        self.assertTrue(np.allclose(disp[x == 0], 0))
        tip = disp[x == 40]
        self.assertGreater(len(tip), 0)
        self.assertGreater(abs(tip[:, 2].mean()), 10 * max(abs(tip[:, 0].mean()), abs(tip[:, 1].mean())))
        print(f"\nCalculiX: {mesh_obj.FemMesh.VolumeCount} C3D4, largest displacement {largest:.4g} mm, "
              f"tip z mean {disp[x == 40][:, 2].mean():.4g} mm")

    def test_pressure_on_a_face_reaches_the_elements(self):
        # A pressure load needs the mesh's element faces on the CAD face (FreeCAD finds them
        # geometrically, as for its Gmsh meshes): it must appear as *DLOAD and push the end inward.
        doc, part, analysis, solver = self.fixed_block_analysis("SweepCDTCcxPressure")
        pressure = ObjectsFem.makeConstraintPressure(doc, "Pressure")
        pressure.References = [(part, face_at_x(part.Shape, 40))]
        pressure.Pressure = 10.0  # MPa, onto the face
        analysis.addObject(pressure)
        doc.recompute()
        mesh_obj, _, _ = sweepcdt_femmesh.tetrahedralize_object(part, analysis=analysis, deflection=0.1)
        fea = self.ccx_tools(analysis, solver)
        with open(fea.inp_file_name) as f:
            self.assertIn("*DLOAD", f.read())
        fea.setup_ccx()
        self.assertEqual(fea.ccx_run(), 0)
        fea.load_results()
        result = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")][0]
        disp = np.array([(v.x, v.y, v.z) for v in result.DisplacementVectors])
        x = np.array([mesh_obj.FemMesh.Nodes[i].x for i in result.NodeNumbers])
        self.assertTrue(np.isfinite(disp).all())
        self.assertLess(disp[x == 40][:, 0].mean(), 0)  # compressed along -x


if __name__ in ("__main__", "calculix_test"):
    run([CalculiX])

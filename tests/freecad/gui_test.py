# GUI smoke test (FreeCAD under xvfb-run): the SweepCDT workbench is listed and activates, the
# Tetrahedralize command opens its task panel on the selected block, OK meshes it (a FemMesh object
# shown in the 3D view), a screenshot is saved to $SWEEPCDT_TEST_OUTPUT/freecad_tetrahedralize.png
# and must show the mesh (not a blank view); a non-closed Mesh feature gives the error in the panel
# and FreeCAD keeps running.
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# The GUI binary does not pass PYTHONPATH on to its interpreter: put the build tree's module first
# explicitly (an installed module would be found in dist-packages).
sys.path.insert(0, os.environ.get("SWEEPCDT_PYTHON_DIR", ""))

import FreeCAD
import FreeCADGui
import Mesh

from freecad_test_support import block_with_holes_and_fillet, run


def screenshot_path():
    out = os.environ.get("SWEEPCDT_TEST_OUTPUT")
    if not out:
        raise AssertionError("SWEEPCDT_TEST_OUTPUT is not set (run through ctest)")
    return os.path.join(out, "freecad_tetrahedralize.png")


class Gui(unittest.TestCase):
    def test_1_workbench_command_and_screenshot(self):
        self.assertTrue(FreeCAD.GuiUp)
        self.assertIn("SweepCDTWorkbench", FreeCADGui.listWorkbenches())
        FreeCADGui.activateWorkbench("SweepCDTWorkbench")
        self.assertEqual(FreeCADGui.activeWorkbench().name(), "SweepCDTWorkbench")

        doc = FreeCAD.newDocument("SweepCDTGui")
        part = doc.addObject("Part::Feature", "Block")
        part.Shape = block_with_holes_and_fillet()
        doc.recompute()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(part)
        FreeCADGui.runCommand("SweepCDT_Tetrahedralize")
        import sweepcdt_gui
        panel = sweepcdt_gui.last_panel
        self.assertIsNotNone(panel, "the command opened no task panel")
        self.assertIs(panel.obj, part)
        panel.accept()  # OK: mesh with the panel's defaults
        meshes = [o for o in doc.Objects if o.TypeId == "Fem::FemMeshObject"]
        self.assertEqual(len(meshes), 1)
        self.assertGreater(meshes[0].FemMesh.VolumeCount, 100)
        self.assertIn("tetrahedra", panel.message)
        self.assertTrue(meshes[0].ViewObject.Visibility)
        self.assertFalse(part.ViewObject.Visibility)

        view = FreeCADGui.ActiveDocument.ActiveView
        view.viewIsometric()
        view.fitAll()
        FreeCADGui.updateGui()
        path = screenshot_path()
        if os.path.exists(path):
            os.remove(path)
        view.saveImage(path, 800, 600, "White")
        self.assertTrue(os.path.isfile(path))
        from PySide import QtGui
        image = QtGui.QImage(path)
        self.assertFalse(image.isNull())
        # The mesh must be in the picture: a good share of the pixels are not the white background.
        white = QtGui.QColor("white").rgb()
        step = 4
        samples = [(x, y) for x in range(0, image.width(), step) for y in range(0, image.height(), step)]
        drawn = sum(1 for x, y in samples if image.pixel(x, y) != white)
        self.assertGreater(drawn / len(samples), 0.05, "the screenshot shows (almost) nothing")
        print(f"\nscreenshot {path}: {100 * drawn / len(samples):.0f} % of the view drawn")

    def test_2_open_mesh_reports_the_error_and_freecad_keeps_running(self):
        doc = FreeCAD.newDocument("SweepCDTGuiOpen")
        cube = Mesh.createBox(10, 10, 10)
        facets = cube.Topology[1][:-1]
        feature = doc.addObject("Mesh::Feature", "OpenCube")
        feature.Mesh = Mesh.Mesh([[tuple(cube.Topology[0][i]) for i in f] for f in facets])
        doc.recompute()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(feature)
        FreeCADGui.runCommand("SweepCDT_Tetrahedralize")
        import sweepcdt_gui
        panel = sweepcdt_gui.last_panel
        self.assertIs(panel.obj, feature)
        self.assertFalse(panel.run())
        self.assertIn("open", panel.message)
        panel.reject()
        self.assertEqual([o for o in doc.Objects if o.TypeId == "Fem::FemMeshObject"], [])
        self.assertTrue(FreeCAD.GuiUp)


run([Gui])

# Shared by the FreeCAD tests (run inside freecadcmd or the GUI, not pytest): the CAD part the issue
# asks for, and a unittest runner whose exit code ctest sees (freecadcmd itself exits 0 whatever the
# script does, so the runner ends the process with os._exit).
import os
import sys
import traceback
import unittest

import FreeCAD
import Part


def block_with_holes_and_fillet():
    """A 40 x 20 x 10 mm box with two vertical cylindrical holes (r = 3) and one vertical edge
    filleted (r = 3): the part of issue 14."""
    shape = Part.makeBox(40, 20, 10)
    for x in (10, 30):
        shape = shape.cut(Part.makeCylinder(3, 10, FreeCAD.Vector(x, 10, 0)))
    edge = [e for e in shape.Edges
            if all(abs(v.Point.x - 40) < 1e-9 and abs(v.Point.y - 20) < 1e-9 for v in e.Vertexes)]
    assert len(edge) == 1, "the vertical edge at (40, 20) not found"
    shape = shape.makeFillet(3, edge)
    assert any(f.Surface.__class__.__name__ == "Cylinder" and abs(f.Surface.Radius - 3) < 1e-9
               and abs(f.Surface.Center.x - 37) < 1e-9 for f in shape.Faces), "no fillet face"
    return shape


def run(test_case_classes):
    """Runs the tests, prints the report and ends the process: 0 if all passed, 1 otherwise."""
    try:
        suite = unittest.TestSuite()
        for c in test_case_classes:
            suite.addTests(unittest.defaultTestLoader.loadTestsFromTestCase(c))
        result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
        ok = result.wasSuccessful() and result.testsRun > 0 and not result.skipped
        sys.stdout.flush()
        os._exit(0 if ok else 1)
    except BaseException:
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)

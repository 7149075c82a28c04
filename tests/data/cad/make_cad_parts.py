"""Generates the CAD test parts of tests/data/cad: solids modelled with FreeCAD's Part workbench and
tessellated the way a FreeCAD user exports them (MeshPart, "standard" and "fine" deflection), written
as binary STL (float coordinates) and, for a few, as OBJ text. These are the surfaces issue 13 is
about: long thin triangles fanned across planar faces, cylinders and fillets with dihedral angles
close to 180 degrees, oblique planes whose rounded coordinates are not exactly flat.

Run with Debian's FreeCAD (freecad-python3), from the repository root:
    /usr/bin/python3 tests/data/cad/make_cad_parts.py tests/data/cad [PART ...]
The outputs are committed, so the tests do not need FreeCAD; rerunning gives the same files for the
same FreeCAD/OCC version (0.20.2 / 7.6.3 when they were made).
"""
import math
import os
import sys

sys.path.append("/usr/lib/freecad-python3/lib")
import FreeCAD  # noqa: E402
import MeshPart  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector

# (linear deflection in mm, angular deflection in radians): FreeCAD's Mesh Design "Standard" mesher
# defaults, and a finer setting a user picks for FEM.
DEFLECTIONS = {"std": (0.1, math.radians(28.5)), "fine": (0.01, math.radians(10))}


def plate_with_holes():
    plate = Part.makeBox(120, 80, 6)
    for i in range(5):
        for j in range(3):
            r = 3 + (i + j) % 3
            plate = plate.cut(Part.makeCylinder(r, 10, V(15 + 22 * i, 15 + 25 * j, -2)))
    return plate


def flange():
    disk = Part.makeCylinder(50, 10)
    hub = Part.makeCylinder(25, 30)
    body = disk.fuse(hub).removeSplitter()
    body = body.cut(Part.makeCylinder(15, 40, V(0, 0, -5)))
    for k in range(8):
        a = 2 * math.pi * k / 8
        body = body.cut(Part.makeCylinder(4, 20, V(38 * math.cos(a), 38 * math.sin(a), -5)))
    return body


def bracket():
    base = Part.makeBox(60, 40, 8)
    wall = Part.makeBox(8, 40, 50)
    body = base.fuse(wall).removeSplitter()
    inner = [e for e in body.Edges if abs(e.Vertexes[0].Point.x - 8) < 1e-9 and abs(e.Vertexes[-1].Point.x - 8) < 1e-9
             and abs(e.Vertexes[0].Point.z - 8) < 1e-9 and abs(e.Vertexes[-1].Point.z - 8) < 1e-9]
    body = body.makeFillet(6, inner)
    body = body.cut(Part.makeCylinder(5, 20, V(40, 20, -5)))
    body = body.cut(Part.makeCylinder(4, 20, V(-5, 20, 35), V(1, 0, 0)))
    outer = [e for e in body.Edges if isinstance(e.Curve, Part.Line) and abs(e.Vertexes[0].Point.z - e.Vertexes[-1].Point.z) > 1
             and abs(e.Vertexes[0].Point.x - 60) < 1e-9]
    return body.makeFillet(4, outer) if outer else body


def gear(teeth=24):
    pts = []
    r_root, r_tip = 40, 46
    for k in range(teeth):
        a0 = 2 * math.pi * k / teeth
        step = 2 * math.pi / teeth
        for f, r in ((0.0, r_root), (0.2, r_tip), (0.5, r_tip), (0.7, r_root)):
            a = a0 + f * step
            pts.append(V(r * math.cos(a), r * math.sin(a), 0))
    pts.append(pts[0])
    face = Part.Face(Part.makePolygon(pts))
    body = face.extrude(V(0, 0, 12))
    body = body.cut(Part.makeCylinder(10, 20, V(0, 0, -5)))
    key = Part.makeBox(6, 4, 20, V(-3, 8, -5))
    return body.cut(key)


def pipe_tee():
    main = Part.makeCylinder(12, 100, V(0, 0, 0), V(1, 0, 0))
    branch = Part.makeCylinder(10, 50, V(50, 0, 0), V(0, 1, 0))
    body = main.fuse(branch).removeSplitter()
    body = body.cut(Part.makeCylinder(9, 110, V(-5, 0, 0), V(1, 0, 0)))
    return body.cut(Part.makeCylinder(7, 60, V(50, 0, 0), V(0, 1, 0)))


def filleted_box():
    box = Part.makeBox(40, 30, 20)
    return box.makeFillet(4, box.Edges)


def rotated_box_oblique_hole():
    box = Part.makeBox(30, 20, 10)
    box = box.cut(Part.makeCylinder(4, 60, V(15, -10, 5), V(0.2, 1, 0.3)))
    box.rotate(V(0, 0, 0), V(1, 2, 3), 27)
    return box


def hex_nut():
    r = 10
    pts = [V(r * math.cos(math.pi / 3 * k), r * math.sin(math.pi / 3 * k), 0) for k in range(7)]
    body = Part.Face(Part.makePolygon(pts)).extrude(V(0, 0, 8))
    body = body.common(Part.makeCone(11.5, 7, 6, V(0, 0, 1)).fuse(Part.makeCylinder(11.5, 1)).removeSplitter())
    return body.cut(Part.makeCylinder(5, 20, V(0, 0, -5)))


def two_bodies():
    a = Part.makeBox(10, 10, 10)
    b = Part.makeCylinder(5, 12, V(25, 5, 0))
    return Part.makeCompound([a, b])


def box_fused_sphere():
    return Part.makeBox(10, 10, 10).fuse(Part.makeSphere(4, V(10, 10, 10))).removeSplitter()


def hollow_sphere():
    # Two concentric spheres tessellated alike: each band of the inner one is nearly cospherical with
    # the outer one's, and at fine deflection Steiner refinement walks those bands one split after
    # another, for more than 200 passes (the round limit refused it until session 14).
    return Part.makeSphere(20).cut(Part.makeSphere(17))


def vase():
    # A revolved spline profile, shelled to a 1.2 mm wall (a 3D print): long thin strips on smooth
    # faces close to each other. Jittered like a scan, it is the test of deleting Steiner points that
    # rounding put off their segments (steiner_vs_tetgen_test.cpp).
    pts = [V(20, 0, 0), V(28, 0, 20), V(18, 0, 50), V(12, 0, 70), V(16, 0, 90)]
    spline = Part.BSplineCurve()
    spline.interpolate(pts)
    profile = Part.Wire([Part.LineSegment(V(0, 0, 0), V(20, 0, 0)).toShape(), spline.toShape(),
                         Part.LineSegment(V(16, 0, 90), V(0, 0, 90)).toShape(), Part.LineSegment(V(0, 0, 90), V(0, 0, 0)).toShape()])
    solid = Part.Face(profile).revolve(V(0, 0, 0), V(0, 0, 1), 360)
    top = [f for f in solid.Faces if abs(f.CenterOfMass.z - 90) < 1e-6]
    return solid.makeThickness(top, -1.2, 1e-3)


def perforated_tube():  # a strainer: a 2 mm tube wall drilled radially 48 times (long fans on both walls)
    t = Part.makeCylinder(20, 80).cut(Part.makeCylinder(18, 80))
    for k in range(12):
        for j in range(4):
            a = 2 * math.pi * k / 12 + j * 0.26
            t = t.cut(Part.makeCylinder(2.5, 30, V(0, 0, 12 + 18 * j), V(math.cos(a), math.sin(a), 0)))
    return t


def oblique_cylinders():  # two rods fused at 29 degrees: a long saddle curve of thin triangles
    a = Part.makeCylinder(10, 100, V(0, 0, -50))
    b = Part.makeCylinder(7, 100, V(-50 * math.cos(0.5), 0, -50 * math.sin(0.5)), V(math.cos(0.5), 0.1, math.sin(0.5)))
    return a.fuse(b).removeSplitter()


PARTS = {
    "plate_with_holes": plate_with_holes,
    "flange": flange,
    "bracket": bracket,
    "gear": gear,
    "pipe_tee": pipe_tee,
    "filleted_box": filleted_box,
    "rotated_box": rotated_box_oblique_hole,
    "hex_nut": hex_nut,
    "two_bodies": two_bodies,
    "box_fused_sphere": box_fused_sphere,
    "hollow_sphere": hollow_sphere,
    "vase": vase,
    "perforated_tube": perforated_tube,
    "oblique_cylinders": oblique_cylinders,
}
OBJ_TOO = {"rotated_box", "bracket"}  # text output: 6 decimals, so even more rounding
PLY_ONLY = {"hollow_sphere"}  # binary PLY (FreeCAD's float32 coordinates, indexed): 0.38x the STL's size
# The vase's fine export has 86530 triangles (4 MB); the perforated tube's takes minutes to mesh and
# the rods' seconds (bench/make_more_cad_parts.py makes both).
STD_ONLY = {"vase", "perforated_tube", "oblique_cylinders"}


def main(out_dir, names):
    os.makedirs(out_dir, exist_ok=True)
    for name in names or PARTS:
        shape = PARTS[name]()
        for label, (linear, angular) in DEFLECTIONS.items():
            if name in STD_ONLY and label != "std":
                continue
            mesh = MeshPart.meshFromShape(Shape=shape, LinearDeflection=linear, AngularDeflection=angular, Relative=False)
            ok = mesh.isSolid() and not mesh.hasNonManifolds() and not mesh.hasSelfIntersections()
            stem = os.path.join(out_dir, f"{name}_{label}")
            mesh.write(stem + (".ply" if name in PLY_ONLY else ".stl"))
            if name in OBJ_TOO:
                mesh.write(stem + ".obj")
            print(f"{name}_{label}: {mesh.CountFacets} triangles, closed solid: {ok}")


if __name__ == "__main__":
    # Optional part names after the folder: make only those (the others' files stay as they are).
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)), sys.argv[2:])


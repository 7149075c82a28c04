"""More CAD parts for bench/run_cad.py --more (issue 13): solids the committed parts of tests/data/cad
do not cover, modelled with FreeCAD's Part workbench and exported as a FreeCAD user exports them
(MeshPart, the same "standard" and "fine" deflections as tests/data/cad/make_cad_parts.py), binary
STL. Session 14 found two parts here that failed by default (sphere_with_holes_fine: the round
limit; the hollow sphere is committed as tests/data/cad/hollow_sphere_*.ply). Not committed (about
20 MB); made in about a minute whenever the bench runs. Session 30's fine perforated tube is the
slow one to mesh: about 160 s for sweepcdt, 40 s for `tetgen -pQ`; session 40's drilled board
placed at an angle at fine deflection the other (191 s and 1.4 GB; `tetgen -pQM`, which keeps every
triangle as we do, aborts after 35 s; `-pQ` merges its faces within 1e-8 and takes 0.14 s).

Run with Debian's FreeCAD (freecad-python3):
    /usr/bin/python3 bench/make_more_cad_parts.py OUT_DIR
"""
import math
import os
import sys

sys.path.append("/usr/lib/freecad-python3/lib")
sys.path.append(os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tests", "data", "cad"))
import FreeCAD  # noqa: E402
import MeshPart  # noqa: E402
import Part  # noqa: E402
from make_cad_parts import DEFLECTIONS, oblique_cylinders, perforated_tube  # noqa: E402  the committed parts' "standard" and "fine"

V = FreeCAD.Vector
TILT = (V(0.3, 0.5, 0.8), 23)  # as run_cad.py --rotated: a part placed at an angle in an assembly


def sheet():  # 1.5 mm sheet metal with 32 holes: long thin fans on two large parallel faces
    p = Part.makeBox(200, 100, 1.5)
    for i in range(8):
        for j in range(4):
            p = p.cut(Part.makeCylinder(2 + (i * j) % 3, 5, V(12 + 25 * i, 12 + 25 * j, -1)))
    return p


def shaft():  # turned: cones, a groove, a keyway, a cross hole
    profile = Part.Face(Part.makePolygon([V(0, 0, 0), V(10, 0, 0), V(10, 0, 10), V(8, 0, 12), V(8, 0, 40), V(6.5, 0, 41),
                                          V(6.5, 0, 43), V(8, 0, 44), V(8, 0, 70), V(12, 0, 74), V(12, 0, 90), V(0, 0, 90),
                                          V(0, 0, 0)]))
    s = profile.revolve(V(0, 0, 0), V(0, 0, 1), 360)
    s = s.cut(Part.makeBox(20, 3, 20, V(-10, 6.5, 50)))
    return s.cut(Part.makeCylinder(2, 30, V(-15, 0, 80), V(1, 0, 0)))


def sphere_with_holes():  # a hollow sphere drilled along four axes
    s = Part.makeSphere(20).cut(Part.makeSphere(17))
    for d in (V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1)):
        s = s.cut(Part.makeCylinder(4, 60, d * (-30 / d.Length), d))
    return s


def chamfered_block():  # 45-degree chamfers everywhere: oblique planes, not flat in floats
    b = Part.makeBox(40, 40, 20)
    b = b.makeChamfer(2, b.Edges)
    b = b.cut(Part.makeCylinder(6, 30, V(20, 20, -5)))
    return b.cut(Part.makeCone(10, 6, 8, V(20, 20, 12)))


def ring_torus():  # a torus fused with a box
    return Part.makeTorus(30, 5).fuse(Part.makeBox(10, 10, 14, V(25, -5, -7))).removeSplitter()


def loft():  # a smooth lofted body (B-spline faces)
    wires = [Part.Wire(Part.makeCircle(10 + 4 * math.sin(k), V(2 * k, 0, z))) for k, z in enumerate([0, 10, 25, 40])]
    return Part.makeLoft(wires, True)


def offset_plate():  # far from the origin: coordinates of 1234.5 beside 4 mm features
    p = Part.makeBox(50, 30, 4)
    for i in range(3):
        p = p.cut(Part.makeCylinder(3, 10, V(10 + 15 * i, 15, -2)))
    p.translate(V(1234.5, -876.25, 350.0))
    return p


def bolt():
    head = Part.Face(Part.makePolygon([V(8 * math.cos(math.pi / 3 * k), 8 * math.sin(math.pi / 3 * k), 0) for k in range(7)]))
    b = head.extrude(V(0, 0, 5)).fuse(Part.makeCylinder(4, 30, V(0, 0, 5))).removeSplitter()
    tip = [e for e in b.Edges if isinstance(e.Curve, Part.Circle) and abs(e.Vertexes[0].Point.z - 35) < 1e-6]
    return b.makeChamfer(0.8, tip) if tip else b


def elbow():  # a quarter of a pipe bent round: two concentric tori
    return Part.makeTorus(40, 10, V(0, 0, 0), V(0, 0, 1), 0, 360, 90).cut(Part.makeTorus(40, 8, V(0, 0, 0), V(0, 0, 1), 0, 360, 90))


def bearing_ring():  # concentric cylinders and a torus groove
    r = Part.Face(Part.makePolygon([V(20, 0, -5), V(30, 0, -5), V(30, 0, 5), V(20, 0, 5), V(20, 0, -5)])).revolve(V(0, 0, 0), V(0, 0, 1), 360)
    return r.cut(Part.makeTorus(30, 3))


def frustum():  # a cone frustum drilled through its side
    c = Part.makeCone(30, 15, 25)
    for k in range(6):
        a = 2 * math.pi * k / 6
        c = c.cut(Part.makeCylinder(2, 40, V(20 * math.cos(a), 20 * math.sin(a), -5)))
    return c


def boss_plate():  # bosses fused onto a plate, drilled
    p = Part.makeBox(100, 60, 5)
    for i in range(4):
        p = p.fuse(Part.makeCylinder(4, 10, V(15 + 23 * i, 30, 5)))
    p = p.removeSplitter()
    for i in range(4):
        p = p.cut(Part.makeCylinder(2, 30, V(15 + 23 * i, 30, -5)))
    return p


def knob():
    profile = Part.Face(Part.makePolygon([V(0, 0, 0), V(15, 0, 0), V(15, 0, 8), V(10, 0, 14), V(5, 0, 14), V(5, 0, 20),
                                          V(0, 0, 20), V(0, 0, 0)]))
    return profile.revolve(V(0, 0, 0), V(0, 0, 1), 360)


def cube_void():  # a cube with a spherical void: a nested shell
    return Part.makeBox(30, 30, 30).cut(Part.makeSphere(8, V(15, 15, 15)))


def enclosure():  # a shelled box with rounded vertical edges
    b = Part.makeBox(80, 50, 30)
    b = b.makeFillet(5, [e for e in b.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[-1].Point.z) > 1])
    return b.makeThickness([f for f in b.Faces if abs(f.CenterOfMass.z - 30) < 1e-6], -2, 1e-3)


def tiny_fillet():  # 0.2 mm fillets on a 200 mm block
    b = Part.makeBox(200, 100, 20)
    return b.makeFillet(0.2, b.Edges)


# Session 30: shapes none of the above covers, each a common kind of part (the perforated tube and
# the oblique rods are made by tests/data/cad/make_cad_parts.py, their standard exports committed).
def spring():  # a circle swept along a helix: a twisted B-spline tube, no face flat
    helix = Part.Wire(Part.makeHelix(4, 40, 10))
    return helix.makePipeShell([Part.Wire(Part.makeCircle(1, V(10, 0, 0), V(0, 1, 0)))], True, True)


def ribbed_housing():  # an open box with 1.2 mm ribs and screw bosses: thin walls, many coplanar faces
    b = Part.makeBox(120, 80, 40).cut(Part.makeBox(116, 76, 38, V(2, 2, 2)))
    for i in range(1, 6):
        b = b.fuse(Part.makeBox(1.2, 76, 30, V(20 * i, 2, 2)))
    for i in range(3):
        b = b.fuse(Part.makeCylinder(4, 36, V(10 + 50 * i, 10, 2))).cut(Part.makeCylinder(1.5, 36, V(10 + 50 * i, 10, 4)))
    return b.removeSplitter()


def knurled_knob():  # 40 grooves cut at 45 degrees round a cylinder, a shaft on top
    k = Part.makeCylinder(15, 12)
    for i in range(40):
        a = 2 * math.pi * i / 40
        corner = V(15 * math.cos(a), 15 * math.sin(a), 0)
        k = k.cut(Part.makeBox(1, 1, 14, corner + V(0, 0, -1)).rotated(corner, V(0, 0, 1), math.degrees(a) + 45))
    return k.fuse(Part.makeCylinder(5, 20, V(0, 0, 12)))


def twisted_loft():  # a rectangle lofted through six sections, each turned 15 degrees: ruled, not flat
    sections = []
    for i in range(6):
        w = Part.makePolygon([V(-10, -5, 0), V(10, -5, 0), V(10, 5, 0), V(-10, 5, 0), V(-10, -5, 0)])
        w.rotate(V(0, 0, 0), V(0, 0, 1), 15 * i)
        w.translate(V(0, 0, 10 * i))
        sections.append(w)
    return Part.makeLoft(sections, True, False)


def far_bracket():  # a filleted, drilled bracket placed at an angle 8 m from the origin, as in an assembly
    b = Part.makeBox(50, 30, 5).fuse(Part.makeBox(5, 30, 40))
    b = b.makeFillet(2, [e for e in b.Edges if abs(e.Length - 30) < 1e-6][:2])
    b = b.cut(Part.makeCylinder(3, 10, V(25, 15, -1)))
    b.rotate(V(0, 0, 0), V(0.2, 0.9, 0.4), 37)
    b.translate(V(-8123.25, 4410.5, 1200.125))
    return b


# Session 40: thin-walled prints and a drilled board, the kind of part that reaches the point budget
# when placed at an angle (faces flat only up to rounding, fanned between small holes).
def thin_cup():  # a 0.8 mm walled cup, as printed in vase mode
    c = Part.makeCylinder(25, 60)
    return c.makeThickness([f for f in c.Faces if abs(f.CenterOfMass.z - 60) < 1e-6], -0.8, 1e-3)


def thin_enclosure():  # a 1 mm shelled box with rounded vertical edges and six vent slots in its floor
    b = Part.makeBox(90, 60, 25)
    b = b.makeFillet(4, [e for e in b.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[-1].Point.z) > 1])
    b = b.makeThickness([f for f in b.Faces if abs(f.CenterOfMass.z - 25) < 1e-6], -1.0, 1e-3)
    for i in range(6):
        b = b.cut(Part.makeBox(3, 30, 5, V(20 + 9 * i, 15, -1)))
    return b


def long_rod():  # a 1 m rod of 2 mm diameter with a 0.8 mm cross hole every 100 mm
    r = Part.makeCylinder(1, 1000, V(0, 0, 0), V(1, 0, 0))
    for i in range(1, 10):
        r = r.cut(Part.makeCylinder(0.4, 4, V(100 * i, 0, -2), V(0, 0, 1)))
    return r


def pcb_standoffs():  # a 1.6 mm board with 40 holes of 1 mm and four drilled standoffs
    p = Part.makeBox(100, 80, 1.6)
    for i in range(8):
        for j in range(5):
            p = p.cut(Part.makeCylinder(0.5, 3, V(10 + 11 * i, 10 + 14 * j, -1)))
    for (x, y) in [(4, 4), (96, 4), (4, 76), (96, 76)]:
        p = p.fuse(Part.makeCylinder(2.5, 8, V(x, y, 1.6))).cut(Part.makeCylinder(1.2, 12, V(x, y, -1)))
    return p.removeSplitter()


PARTS = {"sheet": sheet, "shaft": shaft, "sphere_with_holes": sphere_with_holes, "chamfered_block": chamfered_block,
         "ring_torus": ring_torus, "loft": loft, "offset_plate": offset_plate, "bolt": bolt, "elbow": elbow,
         "bearing_ring": bearing_ring, "frustum": frustum, "boss_plate": boss_plate, "knob": knob,
         "cube_void": cube_void, "enclosure": enclosure, "tiny_fillet": tiny_fillet,
         "perforated_tube": perforated_tube, "oblique_cylinders": oblique_cylinders, "spring": spring,
         "ribbed_housing": ribbed_housing, "knurled_knob": knurled_knob, "twisted_loft": twisted_loft,
         "far_bracket": far_bracket, "thin_cup": thin_cup, "thin_enclosure": thin_enclosure, "long_rod": long_rod,
         "pcb_standoffs": pcb_standoffs}
TILTED = {"sheet", "bolt", "frustum", "boss_plate", "thin_cup", "thin_enclosure", "long_rod", "pcb_standoffs"}  # also placed at an angle (standard deflection)
TILTED_FINE = {"pcb_standoffs"}  # and at fine deflection: 191 s and 1.4 GB for sweepcdt (session 40)
FINE_ONLY = {"perforated_tube", "oblique_cylinders"}  # their standard exports are in tests/data/cad


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    for name, make in PARTS.items():
        shape = make()
        variants = [(label, shape, d) for label, d in DEFLECTIONS.items() if name not in FINE_ONLY or label == "fine"]
        if name in TILTED:
            tilted = shape.copy()
            tilted.rotate(V(0, 0, 0), *TILT)
            variants.append(("std_tilted", tilted, DEFLECTIONS["std"]))
            if name in TILTED_FINE:
                variants.append(("fine_tilted", tilted, DEFLECTIONS["fine"]))
        for label, s, (linear, angular) in variants:
            mesh = MeshPart.meshFromShape(Shape=s, LinearDeflection=linear, AngularDeflection=angular, Relative=False)
            mesh.write(os.path.join(out_dir, f"{name}_{label}.stl"))
            print(f"{name}_{label}: {mesh.CountFacets} triangles, closed solid: {mesh.isSolid()}")


if __name__ == "__main__":
    main(sys.argv[1])

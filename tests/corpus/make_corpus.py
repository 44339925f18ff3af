# Builds the corpus of real models the import tests read: solids made by FreeCAD's Part and PartDesign
# (booleans with holes and trimmed spheres, fillets, chamfers, fused cylinders, pad/pocket/revolution/hole,
# lofts, sweeps, primitives, multi-solid compounds) and the solids of the .fcstd files FreeCAD ships, each
# written as STEP and as OpenCASCADE .brep by FreeCAD itself.
#
# Run with FreeCAD's headless interpreter (FreeCAD 0.20, Debian's package):
#     freecadcmd tests/corpus/make_corpus.py            (writes tests/corpus/freecad/)
# The files are committed: the tests read them without FreeCAD. Re-running rewrites them (STEP files carry
# a timestamp, so they differ byte-wise; the geometry does not).
import math
import os
import sys
import traceback

import FreeCAD as App
import Part
from FreeCAD import Vector

HERE = os.path.dirname(os.path.abspath(os.environ.get("RATBEZ_CORPUS_SCRIPT", "tests/corpus/make_corpus.py")))
OUT = os.path.join(HERE, "freecad")
SHIPPED = "/usr/share/freecad/Mod/Path/PathTests"


def box_with_hole():
    return Part.makeBox(20, 20, 10).cut(Part.makeCylinder(4, 10, Vector(10, 10, 0)))


def filleted_box():
    box = Part.makeBox(20, 16, 10)
    return box.makeFillet(2.0, box.Edges)


def chamfered_box():
    box = Part.makeBox(20, 16, 10)
    return box.makeChamfer(1.5, box.Edges)


def box_minus_sphere():
    return Part.makeBox(10, 10, 10).cut(Part.makeSphere(6, Vector(10, 10, 10)))


def sphere_minus_box():
    return Part.makeSphere(6).cut(Part.makeBox(10, 10, 10))


def sphere_minus_box_off_axis():
    # The box's face y = 0 of the sphere runs along the sphere's seam: OpenCASCADE's STEP reader, FreeCAD's too,
    # reads FreeCAD's file of it, placed anywhere off the plane y = 0, as the eighth of the sphere in the box.
    centre = Vector(0, -40, 0)
    return Part.makeSphere(6, centre).cut(Part.makeBox(10, 10, 10, centre))


def box_with_void():
    return Part.makeBox(20, 20, 20).cut(Part.makeSphere(5, Vector(10, 10, 10)))


def fused_cylinders():
    a = Part.makeCylinder(3, 20, Vector(0, 0, -10))
    b = Part.makeCylinder(2, 20, Vector(-10, 0, 0), Vector(1, 0, 0))
    return a.fuse(b).removeSplitter()


def cylinder_cut_cylinder():
    a = Part.makeCylinder(5, 10)
    b = Part.makeCylinder(2, 20, Vector(-10, 0, 5), Vector(1, 0, 0))
    return a.cut(b)


def torus_cut():
    return Part.makeTorus(8, 2).cut(Part.makeBox(20, 20, 10, Vector(0, 0, -5)))


def cone_fillet():
    cone = Part.makeCone(6, 3, 8)
    return cone.makeFillet(1.0, [e for e in cone.Edges if e.Curve.TypeId == "Part::GeomCircle" and abs(e.Curve.Radius - 6) < 1e-9])


def loft_solid():
    wires = [Part.Wire(Part.makeCircle(4, Vector(0, 0, 0))),
             Part.Wire(Part.makePolygon([Vector(-3, -3, 5), Vector(3, -3, 5), Vector(3, 3, 5), Vector(-3, 3, 5), Vector(-3, -3, 5)])),
             Part.Wire(Part.makeCircle(2, Vector(0, 0, 10)))]
    return Part.makeLoft(wires, True, False)


def sweep_solid():
    path = Part.Wire(Part.makeHelix(6, 12, 10))
    profile = Part.Wire(Part.makeCircle(1.2, Vector(10, 0, 0), Vector(0, 1, 0)))
    return Part.Wire(path).makePipeShell([profile], True, True)


def revolved_spline():
    spline = Part.BSplineCurve()
    spline.interpolate([Vector(2, 0, 0), Vector(4, 0, 3), Vector(3, 0, 6), Vector(5, 0, 9)])
    edge = spline.toShape()
    top, bottom = edge.Vertexes[-1].Point, edge.Vertexes[0].Point
    wire = Part.Wire([Part.makeLine(Vector(0, 0, 0), bottom), edge, Part.makeLine(top, Vector(0, 0, top.z)),
                      Part.makeLine(Vector(0, 0, top.z), Vector(0, 0, 0))])
    return Part.Face(wire).revolve(Vector(0, 0, 0), Vector(0, 0, 1), 360)


def extruded_spline():
    spline = Part.BSplineCurve()
    spline.interpolate([Vector(0, 0, 0), Vector(4, 3, 0), Vector(8, -1, 0), Vector(12, 2, 0)])
    edge = spline.toShape()
    wire = Part.Wire([edge, Part.makeLine(edge.Vertexes[-1].Point, Vector(12, -6, 0)),
                      Part.makeLine(Vector(12, -6, 0), Vector(0, -6, 0)), Part.makeLine(Vector(0, -6, 0), Vector(0, 0, 0))])
    return Part.Face(wire).extrude(Vector(0, 0, 5))


def two_solids():
    return Part.makeCompound([Part.makeBox(5, 5, 5), Part.makeCylinder(2, 6, Vector(10, 0, 0))])


def partdesign_body(doc):
    import Sketcher
    body = doc.addObject("PartDesign::Body", "Body")

    def rectangle_sketch(name, support, w, h, x=0.0, y=0.0):
        sketch = body.newObject("Sketcher::SketchObject", name)
        sketch.Support = support
        sketch.MapMode = "FlatFace"
        pts = [Vector(x, y, 0), Vector(x + w, y, 0), Vector(x + w, y + h, 0), Vector(x, y + h, 0)]
        for k in range(4):
            sketch.addGeometry(Part.LineSegment(pts[k], pts[(k + 1) % 4]), False)
        for k in range(4):
            sketch.addConstraint(Sketcher.Constraint("Coincident", k, 2, (k + 1) % 4, 1))
        return sketch

    def on_top(sketch, z):
        # Attached to the XY plane, lifted to the pad's top face (a face name would follow FreeCAD's numbering).
        sketch.Support = (doc.getObject("XY_Plane"), [""])
        sketch.MapMode = "FlatFace"
        sketch.AttachmentOffset = App.Placement(Vector(0, 0, z), App.Rotation())

    base = rectangle_sketch("Base", (doc.getObject("XY_Plane"), [""]), 30, 20)
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile = base
    pad.Length = 8
    doc.recompute()
    pocket_sketch = body.newObject("Sketcher::SketchObject", "PocketSketch")
    on_top(pocket_sketch, 8)
    pocket_sketch.addGeometry(Part.Circle(Vector(8, 10, 0), Vector(0, 0, 1), 3), False)
    pocket = body.newObject("PartDesign::Pocket", "Pocket")
    pocket.Profile = pocket_sketch
    pocket.Length = 5
    doc.recompute()
    hole_sketch = body.newObject("Sketcher::SketchObject", "HoleSketch")
    on_top(hole_sketch, 8)
    hole_sketch.addGeometry(Part.Circle(Vector(22, 10, 0), Vector(0, 0, 1), 2), False)
    hole = body.newObject("PartDesign::Hole", "Hole")
    doc.recompute()
    hole.Profile = hole_sketch
    hole.Diameter = 5
    hole.Depth = 6
    hole.DepthType = "Dimension"
    hole.DrillPoint = "Angled"
    doc.recompute()
    return body


def partdesign_revolution(doc):
    body = doc.addObject("PartDesign::Body", "RevBody")
    sketch = body.newObject("Sketcher::SketchObject", "Profile")
    sketch.Support = (doc.getObject("XZ_Plane001") or body.Origin.OriginFeatures[4], [""])
    sketch.MapMode = "FlatFace"
    pts = [Vector(0, 0, 0), Vector(6, 0, 0), Vector(6, 2, 0), Vector(3, 5, 0), Vector(0, 5, 0)]
    for k in range(len(pts)):
        sketch.addGeometry(Part.LineSegment(pts[k], pts[(k + 1) % len(pts)]), False)
    revolution = body.newObject("PartDesign::Revolution", "Revolution")
    revolution.Profile = sketch
    revolution.ReferenceAxis = (sketch, ["V_Axis"])
    revolution.Angle = 270
    doc.recompute()
    return body


def write(name, shape):
    solids = shape.Solids
    if not solids or not shape.isValid():
        raise RuntimeError(f"{name}: FreeCAD made no valid solid ({len(solids)} solids, valid={shape.isValid()})")
    shape.exportStep(os.path.join(OUT, name + ".step"))
    shape.exportBrep(os.path.join(OUT, name + ".brep"))
    print(f"{name}: {len(solids)} solid(s), {len(shape.Faces)} faces, volume {shape.Volume:.6g}")


def shipped_models():
    """The solids of the .fcstd files FreeCAD ships, one compound per document (file order)."""
    for file in sorted(os.listdir(SHIPPED)):
        if not file.lower().endswith(".fcstd"):
            continue
        doc = App.openDocument(os.path.join(SHIPPED, file), True)
        try:
            solids = []
            for obj in doc.Objects:
                shape = getattr(obj, "Shape", None)
                if shape is None or shape.isNull() or not obj.TypeId.startswith(("Part::", "PartDesign::Body")):
                    continue
                if obj.InList and any(parent.TypeId.startswith(("Part::", "PartDesign::")) for parent in obj.InList):
                    continue  # used by a boolean or a body: its result is the solid the user sees
                solids.extend(s for s in shape.Solids if s.isValid())
            if solids:
                yield "shipped_" + os.path.splitext(file)[0].lower().replace("-", "_"), Part.makeCompound(solids)
        finally:
            App.closeDocument(doc.Name)


def main():
    os.makedirs(OUT, exist_ok=True)
    made = {
        "part_cylinder": Part.makeCylinder(5, 20),
        "part_cone": Part.makeCone(5, 2, 8),
        "part_sphere": Part.makeSphere(6),
        "part_torus": Part.makeTorus(8, 2),
        "half_sphere": Part.makeSphere(5, Vector(0, 0, 0), Vector(0, 0, 1), 0, 90, 360),
        "wedge_sphere": Part.makeSphere(5, Vector(0, 0, 0), Vector(0, 0, 1), -90, 90, 120),
        "box_with_hole": box_with_hole(),
        "filleted_box": filleted_box(),
        "chamfered_box": chamfered_box(),
        "box_minus_sphere": box_minus_sphere(),
        "sphere_minus_box": sphere_minus_box(),
        "sphere_minus_box_off_axis": sphere_minus_box_off_axis(),
        "box_with_void": box_with_void(),
        "fused_cylinders": fused_cylinders(),
        "cylinder_cut_cylinder": cylinder_cut_cylinder(),
        "torus_cut": torus_cut(),
        "cone_fillet": cone_fillet(),
        "loft_solid": loft_solid(),
        "sweep_solid": sweep_solid(),
        "revolved_spline": revolved_spline(),
        "extruded_spline": extruded_spline(),
        "two_solids": two_solids(),
    }
    doc = App.newDocument("corpus")
    made["partdesign_pocket_hole"] = partdesign_body(doc).Shape
    made["partdesign_revolution"] = partdesign_revolution(doc).Shape
    # RATBEZ_CORPUS_ONLY=name,name writes only those (the others' files stay byte for byte).
    only = [name for name in os.environ.get("RATBEZ_CORPUS_ONLY", "").split(",") if name]
    failures = 0
    for name, shape in made.items():
        if only and name not in only:
            continue
        try:
            write(name, shape)
        except Exception:
            traceback.print_exc()
            failures += 1
    for name, shape in shipped_models():
        if only and name not in only:
            continue
        try:
            write(name, shape)
        except Exception:
            traceback.print_exc()
            failures += 1
    return failures


try:
    sys.exit(1 if main() else 0)
except SystemExit:
    raise
except BaseException:
    traceback.print_exc()
    sys.exit(1)

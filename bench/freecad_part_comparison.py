"""RatBez solids beside Part's own (issue 25): what FreeCAD gets from the workbench (conversion.shape_from_solid:
Part's analytic primitive for a cylinder, cone, sphere or torus by default, else ratbez.brep_string, the natural
conversion), the kernel's B-spline form of the primitives (the preference off) and Part's primitive of the same
shape — faces and edges, FreeCAD's Shape.Volume error, FreeCAD's BOP check, and the time of a Part Cut with a box
through the middle (median of 5). The examples (examples/*.json), which Part has no primitive for, stand beside
Part's Revolution, Extrusion, Loft or Sweep of the same input (the profiles' lines, arcs and circles as Part's
own, other pieces as the same B-splines), with "-" in the B-spline column; the Shape.Volume error is RatBez's.

    freecadcmd bench/freecad_part_comparison.py            (with build/kernel/python on the path)

Prints a Markdown table; timings are measurements, never pass/fail.
"""

import glob
import math
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "build", "kernel", "python"), os.path.join(HERE, "..", "tests", "freecad"),
                os.path.join(HERE, "..", "freecad_workbench", "RatBez")]

import FreeCAD as App  # noqa: E402
import Part  # noqa: E402

import exact  # noqa: E402
from ratbez_wb import conversion  # noqa: E402


def bop_findings(shape):
    """FreeCAD's "Run BOP check": its complaints, "-" when it passes."""
    try:
        shape.check(True)
    except Exception as error:  # FreeCAD raises a plain Exception listing the problems
        return ", ".join(sorted({line.split(": ", 1)[-1] for line in str(error).splitlines() if "BOPAlgo" in line}))
    return "-"


def cut_ms(shape):
    box = shape.BoundBox
    tool = Part.makeBox(box.XLength, box.YLength, box.ZLength / 2,
                        App.Vector(box.XMin + box.XLength / 2, box.YMin - 1, box.ZMin - 1))
    times = []
    for _ in range(5):
        start = time.perf_counter()
        shape.cut(tool)
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def _place(spec):
    return App.Vector(*spec.get("center", (0, 0, 0))), App.Vector(*spec.get("axis", (0, 0, 1)))


PART = {
    "sphere": lambda s: Part.makeSphere(s["radius"], _place(s)[0]),
    "cylinder": lambda s: Part.makeCylinder(s["radius"], s["height"], *_place(s)),
    "cone": lambda s: Part.makeCone(s["radius1"], s["radius2"], s["height"], *_place(s)),
    "torus": lambda s: Part.makeTorus(s["major_radius"], s["minor_radius"], *_place(s)),
}


# Part's features on the same input as the examples: the profile's lines, arcs and circles as Part's own lines and
# circles (as a sketch gives them), every other piece as the same B-spline (poles, weights, knots).
def _part_edge(piece):
    curve = exact._piece(piece)
    start, end = App.Vector(*curve.start_point), App.Vector(*curve.end_point)
    if piece["type"] == "line":
        return Part.makeLine(start, end)
    if piece["type"] in ("circle", "arc"):
        centre = App.Vector(*(list(piece.get("center", (0, 0, 0))) + [0])[:3])
        circle = Part.Circle(centre, App.Vector(*piece.get("normal", (0, 0, 1))), piece["radius"])
        circle.XAxis = start - centre  # starts where ours starts (a loft's seam is there)
        turn = 360.0 if piece["type"] == "circle" else piece["end_deg"] - piece["start_deg"]
        return circle.toShape(0, math.radians(turn))
    knots = list(curve.knots)
    distinct = sorted(set(knots))
    spline = Part.BSplineCurve()
    spline.buildFromPolesMultsKnots([App.Vector(*p) for p in curve.points], [knots.count(k) for k in distinct],
                                    distinct, False, curve.degree, list(curve.weights) if curve.is_rational else None)
    return spline.toShape()


def _part_wire(pieces):
    return Part.Wire([_part_edge(piece) for piece in pieces])


def part_feature_of(spec):
    """Part's Revolution, Extrusion, Loft, ruled Loft or Sweep of the example's input (made as FreeCAD's features
    make them), or None."""
    kind = spec["type"]
    if kind == "revolve":
        face = Part.Face(_part_wire(spec["profile"]))
        axis_point, axis_dir = spec.get("axis_point", (0, 0, 0)), spec.get("axis_dir", (0, 0, 1))
        return face.revolve(App.Vector(*axis_point), App.Vector(*axis_dir), spec.get("angle", 360.0))
    if kind == "extrude":
        face = Part.Face(_part_wire(spec["profile"]))
        return face.extrude(App.Vector(*spec["direction"]).normalize() * spec["distance"])
    if kind in ("loft", "ruled"):
        profiles = spec["profiles"] if kind == "loft" else (spec["profile_a"], spec["profile_b"])
        wires = [_part_wire(p) for p in profiles]
        return Part.makeLoft(wires, True, kind == "ruled" or spec.get("ruled", False))
    if kind == "sweep":
        return Part.Wire(_part_wire(spec["path"])).makePipeShell([_part_wire(spec["profile"])], True, True)
    return None


def main():
    shapes = [("sphere r=3", {"type": "sphere", "radius": 3}),
              ("sphere r=3 at (0, 40, 0)", {"type": "sphere", "radius": 3, "center": [0, 40, 0]}),
              ("cylinder r=2 h=5", {"type": "cylinder", "radius": 2, "height": 5}),
              ("cone 3/1 h=4", {"type": "cone", "radius1": 3, "radius2": 1, "height": 4}),
              ("torus 5/1.5", {"type": "torus", "major_radius": 5, "minor_radius": 1.5})]
    for path in sorted(glob.glob(os.path.join(HERE, "..", "examples", "*.json"))):
        shapes.append(exact.load(path))
    print("| shape | faces / edges (RatBez; B-spline; Part) | Shape.Volume error | BOP check (RatBez; B-spline; Part) "
          "| Cut ms (RatBez; B-spline; Part) |")
    print("|---|---|---|---|---|")
    for name, spec in shapes:
        solid = exact.solid(spec)
        shape = conversion.shape_from_solid(solid, analytic=True)  # the workbench's default
        error = abs(shape.Volume - solid.volume()) / solid.volume()
        forms = [shape]
        if spec["type"] in PART:
            forms += [conversion.shape_from_solid(solid, analytic=False), PART[spec["type"]](spec)]
        else:  # no B-spline form apart from the workbench's own; Part's feature of the same input
            forms += [None, part_feature_of(spec)]
        counts = "; ".join("-" if s is None else "{} / {}".format(len(s.Faces), len(s.Edges)) for s in forms)
        bop = "; ".join("-" if s is None else bop_findings(s) for s in forms)
        ms = "; ".join("-" if s is None else "{:.1f}".format(cut_ms(s)) for s in forms)
        print("| {} | {} | {:.1e} | {} | {} |".format(name, counts, error, bop, ms))
        sys.stdout.flush()

main()

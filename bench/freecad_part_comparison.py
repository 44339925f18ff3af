"""RatBez solids beside Part's own (issue 25): what FreeCAD gets from the workbench (conversion.shape_from_solid:
Part's analytic primitive for a cylinder, cone, sphere or torus by default, else ratbez.brep_string, the natural
conversion), the kernel's B-spline form of the primitives (the preference off) and Part's primitive of the same
shape — faces and edges, FreeCAD's Shape.Volume error, FreeCAD's BOP check, and the time of a Part Cut with a box
through the middle (median of 5). The examples (examples/*.json), which Part has no primitive for, show their
faces and the same measurements.

    freecadcmd bench/freecad_part_comparison.py            (with build/kernel/python on the path)

Prints a Markdown table; timings are measurements, never pass/fail.
"""

import glob
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
        counts = "; ".join("{} / {}".format(len(s.Faces), len(s.Edges)) for s in forms)
        bop = "; ".join(bop_findings(s) for s in forms)
        ms = "; ".join("{:.1f}".format(cut_ms(s)) for s in forms)
        print("| {} | {} | {:.1e} | {} | {} |".format(name, counts, error, bop, ms))
        sys.stdout.flush()

main()

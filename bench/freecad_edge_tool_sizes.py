"""Part Chamfer and Fillet across sizes on ruled solids and lofts: RatBez beside Part's own tools (issue 25).

tests/freecad/test_part_operations.py holds every kind of RatBez solid to Part's result at one size. This measures
how far that carries: each size from 0.02 to 0.98 in steps of 0.02 on every sharp edge at once, on

- the RatBez Ruled and Loft objects of the workbench (RatBez.make_ruled / make_loft of the same Part wires),
- Part Loft of the same sections (Ruled for the ruled solids), and
- for the ruled solids, Part's other tool for them, Ruled Surface: makeRuledSurface of each arc of the circle with
  the side of the polygon it faces, and the two caps, sewn. Its surfaces are Part Loft's to 1e-7 (the same
  volume), in another representation.

A size "works" when the tool returns one valid solid. Part's two tools disagree with each other at some sizes on
the same surfaces, and RatBez's ruled surface is another one (the exact rational arc ruled to the side, where
Part's rules OpenCASCADE's polynomial approximation of the arc by angle: 0.5 % apart in volume), so the sets are
reported side by side, not compared for equality. Nothing here is pass/fail.

    freecadcmd bench/freecad_edge_tool_sizes.py       (with build/kernel/python on the path; about 10 minutes)

Prints a Markdown table: per solid, tool and operation, the number of sizes that work and the sizes that fail.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "build", "kernel", "python"), os.path.join(HERE, "..", "tests", "freecad"),
                os.path.join(HERE, "..", "freecad_workbench", "RatBez")]

import FreeCAD as App  # noqa: E402
import Part  # noqa: E402

import RatBez  # noqa: E402
from sharp_edges import sharp_edges  # noqa: E402  (as tests/freecad/test_part_operations.py picks them)

V = App.Vector
SIZES = [d / 100 for d in range(2, 100, 2)]
RADIUS, HEIGHT = 2.0, 4.0


def polygon_points(sides):
    """The top section: a triangle inscribed in the circle, or the 3 x 3 square of the test's loft."""
    if sides == 3:
        return [V(RADIUS * math.cos(a), RADIUS * math.sin(a), HEIGHT) for a in (0, 2 * math.pi / 3, 4 * math.pi / 3)]
    return [V(-1.5, -1.5, HEIGHT), V(1.5, -1.5, HEIGHT), V(1.5, 1.5, HEIGHT), V(-1.5, 1.5, HEIGHT)]


def feature(doc, name, shape):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    return obj


def part_ruled_surface_solid(points):
    """Part's Ruled Surface of each arc of the circle (cut below the polygon's corners) with the polygon's side
    above it, and the two caps, sewn into a solid."""
    circle = Part.Circle(V(0, 0, 0), V(0, 0, 1), RADIUS)
    angles = [math.atan2(p.y, p.x) for p in points]
    faces = []
    for i, (start, end) in enumerate(zip(points, points[1:] + points[:1])):
        a0, a1 = angles[i], angles[(i + 1) % len(points)]
        while a1 <= a0:
            a1 += 2 * math.pi
        faces.append(Part.makeRuledSurface(Part.Edge(circle, a0, a1), Part.makeLine(start, end)))
    faces.append(Part.Face(Part.Wire(Part.makeCircle(RADIUS))))
    faces.append(Part.Face(Part.makePolygon(points + points[:1])))
    sewn = Part.Compound(faces)
    sewn.sewShape()
    solid = Part.Solid(sewn.Shells[0])
    return solid if solid.Volume > 0 else solid.reversed()


def solids(kind):
    """(name, tool, shape) for one kind: "ruled 3", "ruled 4" (circle to triangle or square) or "loft" (circle,
    square, circle)."""
    for name in list(App.listDocuments()):
        App.closeDocument(name)
    doc = App.newDocument("EdgeToolSizes")
    points = polygon_points(3 if kind == "ruled 3" else 4)
    circle = feature(doc, "Circle", Part.Wire(Part.makeCircle(RADIUS, V(0, 0, 0), V(0, 0, 1))))
    polygon = feature(doc, "Polygon", Part.makePolygon(points + points[:1]))
    if kind == "loft":
        sections = [circle, polygon, feature(doc, "Top", Part.Wire(Part.makeCircle(RADIUS, V(0, 0, 2 * HEIGHT))))]
        ours = RatBez.make_loft(doc, Sections=sections)
    else:
        sections = [circle, polygon]
        ours = RatBez.make_ruled(doc, Profile1=circle, Profile2=polygon)
    loft = doc.addObject("Part::Loft", "Loft")
    loft.Sections, loft.Solid, loft.Ruled = sections, True, kind != "loft"
    doc.recompute()
    found = [("RatBez", ours.Shape), ("Part Loft", loft.Shape)]
    if kind != "loft":
        found.append(("Part Ruled Surface", part_ruled_surface_solid(points)))
    return found


def works(shape, operation, size):
    edges = sharp_edges(shape)
    try:
        result = shape.makeChamfer(size, edges) if operation == "chamfer" else shape.makeFillet(size, edges)
    except Exception:  # OpenCASCADE's "command not done" and the like
        return False
    return result.isValid() and len(result.Solids) == 1


def main():
    print("| solid | tool | volume | operation | sizes that work, of {} | sizes that fail |".format(len(SIZES)))
    print("|---|---|---|---|---|---|")
    for kind in ("ruled 3", "ruled 4", "loft"):
        for tool, shape in solids(kind):
            for operation in ("chamfer", "fillet"):
                failing = [size for size in SIZES if not works(shape, operation, size)]
                print("| {} | {} | {:.4f} | {} | {} | {} |".format(
                    kind, tool, shape.Volume, operation, len(SIZES) - len(failing),
                    ", ".join("{:g}".format(size) for size in failing) or "-"))
                sys.stdout.flush()


main()

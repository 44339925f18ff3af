"""The ruled solids and the loft of issue 25's comparisons with Part, made three ways from the same sections: the
RatBez Ruled / Loft objects of the workbench, Part Loft, and (ruled solids) Part's Ruled Surface. Used by
bench/freecad_edge_tool_sizes.py and bench/freecad_offset_joins.py; needs FreeCAD and build/kernel/python on the
path (the benches set it)."""

import math

import FreeCAD as App
import Part

import RatBez

V = App.Vector
RADIUS, HEIGHT = 2.0, 4.0
KINDS = ("ruled 3", "ruled 4", "loft")  # circle to triangle, circle to square, circle-square-circle


def polygon_points(sides, height=HEIGHT):
    """The top section: a triangle inscribed in the circle, or the 3 x 3 square of the tests' loft."""
    if sides == 3:
        return [V(RADIUS * math.cos(a), RADIUS * math.sin(a), height) for a in (0, 2 * math.pi / 3, 4 * math.pi / 3)]
    return [V(-1.5, -1.5, height), V(1.5, -1.5, height), V(1.5, 1.5, height), V(-1.5, 1.5, height)]


def feature(doc, name, shape):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    return obj


def part_ruled_surface_solid(points):
    """Part's Ruled Surface of each arc of the circle (cut below the polygon's corners) with the polygon's side
    above it, and the two caps, sewn into a solid. Its surfaces are Part Loft's to 1e-7, in another
    representation."""
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


def solids(kind, height=HEIGHT):
    """[(tool, shape)] for one of KINDS, the polygon at `height` (the loft's top circle at twice that): the RatBez
    object, Part Loft of the same sections (ruled for the ruled solids) and, for those, Part's Ruled Surface."""
    for name in list(App.listDocuments()):
        App.closeDocument(name)
    doc = App.newDocument("RuledAndLoftSolids")
    points = polygon_points(3 if kind == "ruled 3" else 4, height)
    circle = feature(doc, "Circle", Part.Wire(Part.makeCircle(RADIUS, V(0, 0, 0), V(0, 0, 1))))
    polygon = feature(doc, "Polygon", Part.makePolygon(points + points[:1]))
    if kind == "loft":
        sections = [circle, polygon, feature(doc, "Top", Part.Wire(Part.makeCircle(RADIUS, V(0, 0, 2 * height))))]
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

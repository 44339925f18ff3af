"""Sketches the FreeCAD tests build their solids from (the same input for RatBez and for Part's tools)."""

import math

import FreeCAD as App
import Part

V = App.Vector
# Sketch y -> global z: the sketch lies in the XZ plane, as a profile revolved about Z.
XZ = App.Placement(V(0, 0, 0), App.Rotation(V(1, 0, 0), 90))


def profile_sketch(doc, placement, name="Profile"):
    """A closed profile off the sketch's y axis: a 2 x 3 rectangle x in [2, 4], y in [0, 3] whose right side is
    a half disc of radius 1.5 bulging outwards (tangent to the top and bottom lines)."""
    sketch = doc.addObject("Sketcher::SketchObject", name)
    sketch.Placement = placement
    sketch.addGeometry(Part.LineSegment(V(2, 0, 0), V(4, 0, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(4, 1.5, 0), V(0, 0, 1), 1.5), -math.pi / 2, math.pi / 2))
    sketch.addGeometry(Part.LineSegment(V(4, 3, 0), V(2, 3, 0)))
    sketch.addGeometry(Part.LineSegment(V(2, 3, 0), V(2, 0, 0)))
    doc.recompute()
    return sketch


def square_sketch(doc, name, half, z):
    """A square of side 2 half about the Z axis at height z, its lines from the south-west corner round."""
    sketch = doc.addObject("Sketcher::SketchObject", name)
    corners = [(-half, -half), (half, -half), (half, half), (-half, half)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(V(*a, 0), V(*b, 0)))
    sketch.Placement.Base = V(0, 0, z)
    doc.recompute()
    return sketch

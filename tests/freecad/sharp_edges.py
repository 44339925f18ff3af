"""The edges Part's Chamfer and Fillet are tried on, picked the same way on RatBez's solids and Part's
(tests/freecad/test_part_operations.py, bench/freecad_edge_tool_sizes.py)."""

import math

import Part


def sharp_edges(shape):
    """Edges that are neither seams nor degenerated and whose two faces meet at more than 1 degree at the
    edge's middle (a chamfer or fillet along a tangent edge fails on Part's solids too)."""
    edges = []
    for edge in shape.Edges:
        if edge.Degenerated:
            continue
        faces = shape.ancestorsOfType(edge, Part.Face)
        if len(faces) != 2 or any(edge.isSeam(face) for face in faces):
            continue
        point = edge.valueAt(0.5 * (edge.FirstParameter + edge.LastParameter))
        normals = [face.normalAt(*face.Surface.parameter(point)) for face in faces]
        if math.degrees(normals[0].getAngle(normals[1])) > 1.0:
            edges.append(edge)
    return edges

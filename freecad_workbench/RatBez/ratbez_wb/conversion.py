"""Conversions between FreeCAD geometry and the ratbez kernel.

FreeCAD -> ratbez: the edges of a profile (an edge, a wire, a face's outer wire or a whole sketch) are
converted exactly with edge.toNurbs() (lines, circles, arcs, ellipses, B-splines and Bézier curves all
have an exact rational B-spline form), trimmed to the edge's range, chained end to end and oriented
consistently, and passed to the kernel as ratbez.NurbsCurve pieces.

ratbez -> FreeCAD: a solid is handed over as OpenCASCADE's .brep text of its exact B-spline B-rep
(ratbez.brep_string), never as a mesh.
"""

import FreeCAD as App
import Part

from . import kernel


class ProfileError(ValueError):
    """The linked profile cannot be used (nothing linked, no edges, not one connected chain, ...)."""


# ---------------------------------------------------------------------------------------------------
# FreeCAD edges -> NURBS data

def _as_tuple(vector):
    return (vector.x, vector.y, vector.z)


def edge_nurbs_data(edge):
    """The exact NURBS form of an edge in global coordinates, in the edge's parameter direction.

    Returns a dict with degree, knots (flat, multiplicities expanded), points and weights.
    """
    nurbs_shape = edge.toNurbs()
    if not nurbs_shape.Edges:
        raise ProfileError("edge cannot be converted to a NURBS curve")
    nurbs_edge = nurbs_shape.Edges[0]
    curve = nurbs_edge.Curve
    if not isinstance(curve, Part.BSplineCurve):
        raise ProfileError("edge of type {} cannot be converted to a NURBS curve".format(
            type(curve).__name__))
    curve = curve.copy()
    first, last = nurbs_edge.FirstParameter, nurbs_edge.LastParameter
    if curve.isPeriodic():
        # Unperiodized curves keep unclamped end knots; Segment below clamps them.
        curve.setNotPeriodic()
    degree = curve.Degree
    knots = list(curve.KnotSequence)
    scale = max(1.0, abs(last - first))
    clamped = (all(k == knots[0] for k in knots[:degree + 1])
               and all(k == knots[-1] for k in knots[-degree - 1:]))
    if (not clamped or abs(first - knots[0]) > 1e-12 * scale or abs(last - knots[-1]) > 1e-12 * scale):
        # Geom_BSplineCurve::Segment trims to the edge's range and clamps both ends.
        curve.segment(first, last)
        knots = list(curve.KnotSequence)
    points = [_as_tuple(p) for p in curve.getPoles()]
    weights = list(curve.getWeights())
    if len(knots) != len(points) + degree + 1:
        raise ProfileError("edge gives an inconsistent B-spline ({} knots for {} poles of degree {})".format(
            len(knots), len(points), degree))
    return {"degree": degree, "knots": knots, "points": points, "weights": weights}


def reversed_nurbs_data(data):
    """The same curve traversed backwards: u -> a + b - u."""
    knots = data["knots"]
    a, b = knots[0], knots[-1]
    return {"degree": data["degree"],
            "knots": [a + b - k for k in reversed(knots)],
            "points": list(reversed(data["points"])),
            "weights": list(reversed(data["weights"]))}


def _distance(p, q):
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2) ** 0.5


def chain_nurbs_data(edges):
    """NURBS data of edges joined end to end: one connected chain, each piece oriented so that it
    starts where the previous one ends. Raises ProfileError when the edges do not form one chain."""
    edges = [e for e in edges if not e.isNull() and e.Length > 0]
    if not edges:
        raise ProfileError("the profile has no edges")
    groups = Part.sortEdges(edges)
    if len(groups) != 1:
        raise ProfileError("the profile's {} edges form {} separate chains; it must be one connected "
                           "chain".format(len(edges), len(groups)))
    pieces = [edge_nurbs_data(e) for e in groups[0]]
    if len(pieces) > 1:
        # Orient the first piece towards the second, then every piece from the previous one's end.
        first, second = pieces[0], pieces[1]
        ends_of_second = (second["points"][0], second["points"][-1])
        if (min(_distance(first["points"][0], p) for p in ends_of_second)
                < min(_distance(first["points"][-1], p) for p in ends_of_second)):
            pieces[0] = reversed_nurbs_data(first)
        for k in range(1, len(pieces)):
            end = pieces[k - 1]["points"][-1]
            piece = pieces[k]
            if _distance(piece["points"][-1], end) < _distance(piece["points"][0], end):
                pieces[k] = reversed_nurbs_data(piece)
    return pieces


def nurbs_curve(data):
    """A ratbez.NurbsCurve from NURBS data (weights omitted when they are all 1)."""
    rb = kernel.ratbez()
    weights = data["weights"]
    if all(abs(w - 1.0) <= 1e-15 for w in weights):
        weights = None
    return rb.NurbsCurve(data["degree"], data["knots"], data["points"], weights)


# ---------------------------------------------------------------------------------------------------
# Profile links

def link_edges(link):
    """The edges a PropertyLinkSub value designates: the named sub-elements (edges, or the outer wire
    of faces), or every edge of the object when no sub-element is named (a sketch, a wire)."""
    if link is None:
        raise ProfileError("no profile is linked")
    obj, subs = link
    if obj is None:
        raise ProfileError("no profile is linked")
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull():
        raise ProfileError("the profile '{}' has no shape".format(obj.Label))
    if isinstance(subs, str):
        subs = [subs]
    subs = [s for s in (subs or []) if s]
    if not subs:
        if len(shape.Faces) == 1:
            return list(shape.Faces[0].OuterWire.Edges)
        return list(shape.Edges)
    edges = []
    for name in subs:
        try:
            element = shape.getElement(name)
        except Exception as error:
            raise ProfileError("the profile '{}' has no element {} ({})".format(obj.Label, name, error))
        if element.ShapeType == "Edge":
            edges.append(element)
        elif element.ShapeType == "Face":
            edges.extend(element.OuterWire.Edges)
        elif element.ShapeType == "Wire":
            edges.extend(element.Edges)
        else:
            raise ProfileError("element {} of '{}' is a {}, not an edge, wire or face".format(
                name, obj.Label, element.ShapeType))
    return edges


def profile_from_link(link):
    """A list of ratbez.NurbsCurve pieces from a profile link (what ratbez.revolve/extrude take)."""
    return [nurbs_curve(d) for d in chain_nurbs_data(link_edges(link))]


def profile_plane(edges):
    """The plane (a Part.Plane) the edges lie in, or None when they are not planar."""
    for make in (lambda: Part.Wire(Part.__sortEdges__(edges)), lambda: Part.Compound(edges)):
        try:
            plane = make().findPlane()
        except Exception:
            plane = None
        if plane is not None:
            return plane
    return None


def profile_plane_normal(edges):
    """The unit normal of the plane the edges lie in, or None when they are not planar."""
    plane = profile_plane(edges)
    if plane is None or plane.Axis.Length == 0:
        return None
    return App.Vector(plane.Axis).normalize()


def default_revolve_axis(link):
    """A sensible axis for revolving a profile: the global Z direction through the point of the
    profile's plane nearest the origin when Z lies in that plane, else the vertical (local Y) axis of
    a sketch, else the in-plane direction closest to Z. Returns (axis_point, axis_direction)."""
    z = App.Vector(0, 0, 1)
    obj = link[0]
    try:
        plane = profile_plane(link_edges(link))
    except ProfileError:
        plane = None
    if plane is None or plane.Axis.Length == 0:
        return App.Vector(0, 0, 0), z
    normal = App.Vector(plane.Axis).normalize()
    # The point of the plane nearest the global origin.
    origin = normal * normal.dot(App.Vector(plane.Position))
    if abs(normal.dot(z)) < 1e-9:
        return origin, z
    if obj.isDerivedFrom("Sketcher::SketchObject") or obj.isDerivedFrom("Part::Part2DObject"):
        placement = obj.getGlobalPlacement()
        return placement.Base, placement.Rotation.multVec(App.Vector(0, 1, 0))
    in_plane = z - normal * z.dot(normal)
    return origin, in_plane.normalize()


# ---------------------------------------------------------------------------------------------------
# ratbez -> FreeCAD

def shape_from_solid(solid):
    """The exact B-spline B-rep of a ratbez solid as a valid Part.Solid."""
    text = kernel.ratbez().brep_string(solid)
    shape = Part.Shape()
    shape.importBrepFromString(text, False)
    if shape.isNull():
        raise ValueError("the kernel's B-rep could not be read by OpenCASCADE")
    if shape.ShapeType != "Solid":
        if len(shape.Solids) != 1:
            raise ValueError("the kernel's B-rep holds {} solids instead of one".format(len(shape.Solids)))
        shape = shape.Solids[0]
    if not shape.isValid():
        raise ValueError("the kernel's B-rep is not a valid OpenCASCADE solid")
    return shape


def vector_tuple(vector):
    return (float(vector.x), float(vector.y), float(vector.z))

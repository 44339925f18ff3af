"""Conversions between FreeCAD geometry and the ratbez kernel.

FreeCAD -> ratbez: a profile (a sketch, a Draft or Part 2D object, a wire, edges, or one face) becomes
closed or open loops of edges. Every edge is converted exactly with edge.toNurbs() (lines, circles,
arcs, ellipses, B-splines and Bézier curves all have an exact rational B-spline form), trimmed to the
edge's range, chained end to end and oriented consistently, and passed to the kernel as
ratbez.NurbsCurve pieces. Several closed loops (a face's wires, or a sketch with a hole) are sorted into
an outer loop and holes by FreeCAD's own face maker (Part::FaceMakerBullseye), as Part Extrude does.

ratbez -> FreeCAD: a solid is handed over as OpenCASCADE's .brep text of its exact B-spline B-rep
(ratbez.brep_string: one face per face of the kernel, as Part makes them, with every arc in its exact one-span
form so that FreeCAD's Shape.Volume, Area and CenterOfMass read the exact values and "Run BOP check" passes;
only a face with a crease goes over as Bézier patches), never as a mesh. A cylinder, cone, sphere or torus goes
over, by default, as Part's own primitive on the analytic surface its construction record names (the same exact
shape): OpenCASCADE's booleans, fillets and BOP check treat those specially, and no B-spline form of a sphere
passes the BOP check everywhere (see shape_from_solid).
"""

import FreeCAD as App
import Part

from . import kernel, preferences
from .errors import Failure
from .i18n import translate

V = App.Vector


class ProfileError(Failure):
    """The linked profile (or path) cannot be used; the message names its property (Profile by default)."""

    def __init__(self, reason, prop="Profile"):
        super().__init__(prop, reason)


def _as_tuple(vector):
    return (vector.x, vector.y, vector.z)


def vector_tuple(vector):
    return (float(vector.x), float(vector.y), float(vector.z))


# ---------------------------------------------------------------------------------------------------
# FreeCAD edges -> NURBS data

def edge_nurbs_data(edge):
    """The exact NURBS form of an edge in global coordinates, in the edge's parameter direction.

    Returns a dict with degree, knots (flat, multiplicities expanded), points and weights.
    """
    nurbs_shape = edge.toNurbs()
    if not nurbs_shape.Edges:
        raise ProfileError(translate("an edge cannot be converted to a NURBS curve"))
    nurbs_edge = nurbs_shape.Edges[0]
    curve = nurbs_edge.Curve
    if isinstance(curve, Part.BezierCurve):
        # toNurbs keeps a Bézier curve (a Part Bézier, a Draft BezCurve): the same poles and weights on the knots
        # 0 and 1 are the same curve with the same parameter, trimmed to the edge's range below.
        degree = curve.Degree
        bezier = curve
        curve = Part.BSplineCurve()
        curve.buildFromPolesMultsKnots(bezier.getPoles(), [degree + 1, degree + 1], [0.0, 1.0], False, degree,
                                       bezier.getWeights())
    if not isinstance(curve, Part.BSplineCurve):
        raise ProfileError(translate("an edge of type {} cannot be converted to a NURBS curve").format(
            type(curve).__name__))
    curve = curve.copy()
    first, last = nurbs_edge.FirstParameter, nurbs_edge.LastParameter
    if curve.isPeriodic():
        # Unperiodized curves keep unclamped end knots; segment below clamps them.
        curve.setNotPeriodic()
    degree = curve.Degree
    knots = list(curve.KnotSequence)
    scale = max(1.0, abs(last - first))
    clamped = (all(k == knots[0] for k in knots[:degree + 1])
               and all(k == knots[-1] for k in knots[-degree - 1:]))
    if not clamped or abs(first - knots[0]) > 1e-12 * scale or abs(last - knots[-1]) > 1e-12 * scale:
        # Geom_BSplineCurve::Segment trims to the edge's range and clamps both ends.
        curve.segment(first, last)
        knots = list(curve.KnotSequence)
    points = [_as_tuple(p) for p in curve.getPoles()]
    weights = list(curve.getWeights())
    if len(knots) != len(points) + degree + 1:
        raise ProfileError(translate("an edge gives an inconsistent B-spline ({} knots for {} poles of degree {})")
                           .format(len(knots), len(points), degree))
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
    """NURBS data of edges that form one chain, in chain order, each piece oriented to start where the
    previous one ends. Returns (pieces, edges in that order)."""
    pieces = [edge_nurbs_data(e) for e in edges]
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

def link_object(link):
    if not link or link[0] is None:
        return None
    return link[0]


def _sub_names(link):
    subs = link[1] if len(link) > 1 else []
    if isinstance(subs, str):
        subs = [subs]
    return [s for s in (subs or []) if s]


def link_label(link):
    """What a link designates, for people: "Sketch", "Box: Face6", "(none)"."""
    obj = link_object(link)
    if obj is None:
        return translate("(none)")
    subs = _sub_names(link)
    return "{}: {}".format(obj.Label, ", ".join(subs)) if subs else obj.Label


def is_whole_profile_object(link):
    """True when the link is a whole object that is nothing but a profile (a sketch, a 2D object, a wire):
    the object a feature may hide. A face or edges of a solid are not (the solid stays visible)."""
    obj = link_object(link)
    if obj is None or _sub_names(link):
        return False
    shape = getattr(obj, "Shape", None)
    return shape is not None and not shape.isNull() and not shape.Solids and not shape.Shells


def _profile_shape(link):
    """The shape the link designates: one face, or a compound of edges (all in global coordinates)."""
    obj = link_object(link)
    if obj is None:
        raise ProfileError(translate("nothing is linked"))
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull():
        raise ProfileError(translate("'{}' has no shape").format(obj.Label))
    subs = _sub_names(link)
    if not subs:
        if shape.Solids or len(shape.Faces) > 1:
            raise ProfileError(translate("'{}' is a solid or has several faces; select one face or its edges")
                               .format(obj.Label))
        if len(shape.Faces) == 1:
            return shape.Faces[0]
        if not shape.Edges:
            raise ProfileError(translate("'{}' has no edges").format(obj.Label))
        return Part.Compound(shape.Edges)
    faces, edges = [], []
    for name in subs:
        try:
            element = shape.getElement(name)
        except Exception as error:  # FreeCAD raises several types for a bad name
            raise ProfileError(translate("'{}' has no element {} ({})").format(obj.Label, name, error))
        if element.ShapeType == "Face":
            faces.append(element)
        elif element.ShapeType in ("Edge", "Wire"):
            edges.extend(element.Edges)
        else:
            raise ProfileError(translate("element {} of '{}' is a {}, not an edge or a face").format(
                name, obj.Label, element.ShapeType))
    if faces and (edges or len(faces) > 1):
        raise ProfileError(translate("select one face, or edges, not both"))
    return faces[0] if faces else Part.Compound(edges)


def _edge_names(link, edges):
    """'Edge3' for each edge: its name in the linked object's shape (the names the user sees)."""
    obj = link_object(link)
    all_edges = obj.Shape.Edges if obj is not None else []
    names = []
    for k, edge in enumerate(edges):
        index = next((i for i, e in enumerate(all_edges) if e.isSame(edge)), None)
        names.append("Edge{}".format(index + 1) if index is not None else translate("edge {}").format(k + 1))
    return names


class Profile:
    """A profile resolved from a link: loops[0] the outer loop (open or closed), loops[1:] holes; each
    loop a list of NURBS data pieces, and names[l][k] the FreeCAD name of the edge piece k came from."""

    def __init__(self, loops, names, plane):
        self.loops, self.names, self.plane = loops, names, plane

    def curves(self, loop=0):
        return [nurbs_curve(d) for d in self.loops[loop]]

    def moved(self, placement):
        """The same profile moved by a FreeCAD Placement: its poles mapped (exact for a rigid motion, the
        weights unchanged), as Revolve and Extrude Symmetric need."""
        def move(data):
            points = [_as_tuple(placement.multVec(V(*p))) for p in data["points"]]
            return dict(data, points=points)
        return Profile([[move(d) for d in loop] for loop in self.loops], self.names, self.plane)

    @property
    def hole_count(self):
        return len(self.loops) - 1


def _loops_of_face(face):
    wires = [face.OuterWire] + [w for w in face.Wires if not w.isSame(face.OuterWire)]
    return [list(w.OrderedEdges) for w in wires]


def resolve_profile(link, prop="Profile"):
    """The Profile a link designates (see Profile). Failures name `prop` (the property holding the link)."""
    try:
        return _resolve_profile(link)
    except ProfileError as error:
        failure = error
    raise ProfileError(failure.reason, prop)


def _resolve_profile(link):
    shape = _profile_shape(link)
    edges = [e for e in shape.Edges if not e.isNull() and e.Length > 0 and not e.Degenerated]
    if not edges:
        raise ProfileError(translate("the profile has no edges"))
    if shape.ShapeType == "Face":
        loops = _loops_of_face(shape)
    else:
        chains = Part.sortEdges(edges)
        if len(chains) == 1:
            loops = chains
        else:
            if any(not Part.Wire(c).isClosed() for c in chains):
                raise ProfileError(translate("its {} edges form {} separate chains; a profile is one chain, or "
                                             "closed loops that nest").format(len(edges), len(chains)))
            try:
                made = Part.makeFace([Part.Wire(c) for c in chains], "Part::FaceMakerBullseye")
            except Exception as error:  # Part raises Part.OCCError / ValueError / RuntimeError
                raise ProfileError(translate("its {} closed loops do not make a face ({})").format(len(chains), error))
            if len(made.Faces) != 1:
                raise ProfileError(translate("its loops make {} separate regions; make one feature per region")
                                   .format(len(made.Faces)))
            loops = _loops_of_face(made.Faces[0])
    plane = profile_plane([e for loop in loops for e in loop])
    return Profile([chain_nurbs_data(loop) for loop in loops], [_edge_names(link, loop) for loop in loops], plane)


def resolve_path(link, prop="Path"):
    """The NURBS pieces, end to end, of the one chain of edges a link designates (a sketch, a wire, edges):
    the path a profile is swept along. Failures name `prop`."""
    try:
        shape = _profile_shape(link)
    except ProfileError as error:
        failure = error
    else:
        failure = None
    if failure is not None:
        raise ProfileError(failure.reason, prop)
    if shape.ShapeType == "Face":
        raise ProfileError(translate("is a face; a path is a sketch, a wire or edges"), prop)
    edges = [e for e in shape.Edges if not e.isNull() and e.Length > 0 and not e.Degenerated]
    chains = Part.sortEdges(edges) if edges else []
    if len(chains) != 1:
        raise ProfileError(translate("its {} edges form {} separate chains; a path is one chain").format(
            len(edges), len(chains)), prop)
    return [nurbs_curve(d) for d in chain_nurbs_data(chains[0])]


def profile_plane(edges):
    """The plane (a Part.Plane) the edges lie in, or None when they are not planar (or a single line)."""
    for make in (lambda: Part.Wire(Part.__sortEdges__(edges)), lambda: Part.Compound(edges)):
        try:
            plane = make().findPlane()
        except Exception:  # findPlane raises on degenerate input in some versions
            plane = None
        if plane is not None and plane.Axis.Length > 0:
            return plane
    return None


def _is_sketch(obj):
    return obj is not None and obj.isDerivedFrom("Sketcher::SketchObject")


def _plane_frame(link):
    """(origin, normal, vertical, horizontal) of the profile's plane. A sketch: its own placement (the
    sketch's V and H axes, as Sketcher, Part Revolve and PartDesign use them). Anything else: the plane
    through the profile, its origin the point nearest the global origin, vertical the global Z projected
    into it, or the global Y for a horizontal plane (so the XY plane has vertical Y, the XZ and YZ planes
    vertical Z, as for sketches on them), horizontal = vertical x normal."""
    obj = link_object(link)
    if _is_sketch(obj):
        placement = obj.getGlobalPlacement()
        rotation = placement.Rotation
        return (placement.Base, rotation.multVec(V(0, 0, 1)), rotation.multVec(V(0, 1, 0)),
                rotation.multVec(V(1, 0, 0)))
    shape = _profile_shape(link)
    edges = shape.Edges
    plane = shape.Surface if shape.ShapeType == "Face" and isinstance(shape.Surface, Part.Plane) else profile_plane(edges)
    if plane is None:
        raise ProfileError(translate("is not planar"))
    normal = V(plane.Axis).normalize()
    origin = normal * normal.dot(V(plane.Position))
    vertical = None
    for up in (V(0, 0, 1), V(0, 1, 0)):
        candidate = up - normal * up.dot(normal)
        if candidate.Length > 1e-9:
            vertical = candidate.normalize()
            break
    return origin, normal, vertical, vertical.cross(normal).normalize()


def revolve_axis(link, which="Vertical"):
    """(point, direction) of the profile plane's vertical or horizontal axis (see _plane_frame): the axis a
    sketch's profile revolves about by default. A Part circle of radius 2 at (5, 0, 0) in the XY plane
    revolves about the global Y axis into a ring."""
    origin, _, vertical, horizontal = _plane_frame(link)
    return V(origin), V(vertical if which == "Vertical" else horizontal)


def profile_normal(link):
    """The extrusion direction of a profile: a sketch's normal, a face's normal (outward for a solid's
    face), else the plane's normal turned towards +Z (then +Y, +X), so that it does not depend on how the
    edges happen to run."""
    obj = link_object(link)
    if _is_sketch(obj):
        return obj.getGlobalPlacement().Rotation.multVec(V(0, 0, 1))
    shape = _profile_shape(link)
    if shape.ShapeType == "Face":
        u0, u1, v0, v1 = shape.ParameterRange
        return V(shape.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1))).normalize()
    _, normal, _, _ = _plane_frame(link)
    for axis in (V(0, 0, 1), V(0, 1, 0), V(1, 0, 0)):
        side = normal.dot(axis)
        if abs(side) > 1e-12:
            return normal if side > 0 else normal * -1
    return normal


def straight_line(link, prop):
    """(point, unit direction) of a straight edge or a datum line a link designates; Failure naming
    `prop` otherwise."""
    obj = link_object(link)
    if obj is None:
        raise Failure(prop, translate("nothing is linked"))
    subs = _sub_names(link)
    if not subs and obj.isDerivedFrom("App::Line"):
        placement = obj.getGlobalPlacement()
        return V(placement.Base), placement.Rotation.multVec(V(1, 0, 0))
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull():
        raise Failure(prop, translate("'{}' has no shape").format(obj.Label))
    edges = [shape.getElement(s) for s in subs] if subs else shape.Edges
    if len(edges) != 1 or edges[0].ShapeType != "Edge":
        raise Failure(prop, translate("select one straight edge or a datum line"))
    edge = edges[0]
    if not isinstance(edge.Curve, (Part.Line, Part.LineSegment)):
        raise Failure(prop, translate("{} of '{}' is not straight").format(subs[0] if subs else "the edge", obj.Label))
    start, end = edge.valueAt(edge.FirstParameter), edge.valueAt(edge.LastParameter)
    if (end - start).Length <= 1e-12:
        raise Failure(prop, translate("the edge has no length"))
    return V(start), (end - start).normalize()


# ---------------------------------------------------------------------------------------------------
# ratbez -> FreeCAD

def shape_from_solid(solid, analytic=None):
    """The solid as a valid Part.Solid, through the kernel's one conversion to OpenCASCADE (ratbez.brep_string,
    as STEP and BREP files get it): when `analytic` (None: the workbench preference,
    preferences.analytic_primitives), a cylinder, cone, sphere or torus as OpenCASCADE's own primitive on its
    analytic surfaces, an extrusion or revolution as its prism or revolution of the profile and a sweep along
    lines and arcs as its pipe, as Part makes them; else, and for every other solid, the exact B-spline B-rep, one face per face of the kernel.

    Why analytic by default: OpenCASCADE exempts its analytic surfaces from the BOP check's face
    self-intersection search, which flags a B-spline sphere (OpenCASCADE's own toNurbs() sphere too) at some
    placements because of its poles, and cuts them several times faster (a sphere minus a box through its
    seams and a pole: 1.8 s as a B-spline, 9 ms analytic). Both are the same exact shape; the kernel's own
    solid stays behind the object for ExactVolume and the exports."""
    # OpenCASCADE takes coordinates from 1e100 on as infinite (Precision::Infinite is 2e100): the kernel
    # builds such a solid (up to its own limit of 1e100), FreeCAD's shape cannot hold it.
    (low, high) = solid.bounding_box()
    reach = max(abs(c) for c in low + high)
    if reach > 1e99:
        raise Failure("", translate("the solid reaches {:.3g} from the origin, more than OpenCASCADE can hold "
                                    "(1e99)").format(reach))
    if analytic is None:
        analytic = preferences.analytic_primitives()
    shape = _occt_shape(solid, analytic)
    if not shape.isValid():
        raise Failure("", translate("the kernel's B-rep is not a valid OpenCASCADE solid"))
    return shape


def _occt_shape(solid, analytic):
    text = kernel.ratbez().brep_string(solid, analytic_primitives=analytic)
    shape = Part.Shape()
    try:
        shape.importBrepFromString(text, False)
    except Exception as error:  # OCCT's own failure, as one line
        raise Failure("", translate("OpenCASCADE could not read the kernel's B-rep ({})").format(error))
    if shape.isNull():
        raise Failure("", translate("the kernel's B-rep could not be read by OpenCASCADE"))
    if len(shape.Solids) != 1:
        raise Failure("", translate("the kernel's B-rep holds {} solids instead of one").format(len(shape.Solids)))
    return shape.Solids[0]  # a Part.Solid (the imported Part.Shape lacks Volume's siblings: CenterOfMass)

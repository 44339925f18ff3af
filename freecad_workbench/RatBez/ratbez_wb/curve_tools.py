"""The Interpolate feature (issue 26): the B-spline curve through points (ratbez.interpolate, The NURBS Book
A9.1), from selected vertices (in the order selected), a Draft wire's or B-spline's points, any object's
vertices, or its own Points. The edge handed to FreeCAD is the kernel's curve itself (poles, knots), checked
point by point against the kernel. Importing this module registers the feature (features.FEATURES)."""

import math

import FreeCAD as App
import Part

from . import conversion, features, kernel
from .errors import Failure
from .i18n import translate

V = App.Vector
_tip = features._tip  # noqa: SLF001 (the workbench's one tooltip marker)

PARAMETERIZATIONS = ["chord", "centripetal", "uniform"]
MAX_DEGREE = 25


def _default_points():
    return [V(0, 0, 0), V(4, 3, 0), V(8, -1, 0), V(12, 4, 0), V(16, 0, 0)]


def source_points(links):
    """The points the Source links designate, in order: each selected vertex; a whole Draft wire or B-spline
    its Points (its Placement applied); any other whole object its vertices along its edges."""
    points = []
    for obj, subs in links:
        subs = [s for s in (subs or []) if s]
        shape = getattr(obj, "Shape", None)
        if subs:
            for sub in subs:
                if not sub.startswith("Vertex"):
                    raise Failure("Source", translate("{}: {} is not a vertex").format(obj.Label, sub))
                points.append(shape.getElement(sub).Point)
        elif hasattr(obj, "Points") and isinstance(getattr(obj, "Points"), list) and obj.Points:
            placement = obj.Placement
            points.extend(placement.multVec(p) for p in obj.Points)
        elif shape is not None and not shape.isNull() and shape.Vertexes:
            edges = shape.Edges
            vertices = shape.Vertexes
            try:
                chains = Part.sortEdges(edges) if edges else []
                if len(chains) == 1:
                    vertices = Part.Wire(chains[0]).OrderedVertexes
            except Exception:  # Part.OCCError: edges that make no wire; their vertices as the shape lists them
                pass
            points.extend(v.Point for v in vertices)
        else:
            raise Failure("Source", translate("{} has no points to interpolate").format(obj.Label))
    return points


class Interpolate(features.RatBezFeature):
    TYPE = "RatBez::Interpolate"
    PROPERTIES = (
        ("App::PropertyLinkSubList", "Source",
         _tip("Where the points come from, in order: selected vertices, or a Draft wire or B-spline (its points), "
              "or any object (its vertices). Empty: the Points list"), lambda: []),
        ("App::PropertyVectorList", "Points",
         _tip("The points to pass through, in order (used when Source is empty)"), _default_points),
        ("App::PropertyIntegerConstraint", "Degree",
         _tip("Degree of the curve (needs at least Degree + 1 points, fewer with end tangents)"), (3, 1, MAX_DEGREE, 1)),
        ("App::PropertyEnumeration", "Parameterization",
         _tip("Where along the curve each point falls: chord (steps as long as the distances, Eq. 9.5), "
              "centripetal (their square roots, Eq. 9.6: no overshoot at sharp turns) or uniform (Eq. 9.3)"),
         lambda: list(PARAMETERIZATIONS)),
        ("App::PropertyBool", "Closed",
         _tip("Close the curve smoothly back to the first point (a periodic B-spline, smooth at the first point "
              "too)"), False),
        ("App::PropertyBool", "EndTangents",
         _tip("Give the curve's direction at its ends (StartTangent, EndTangent); open curves only"), False),
        ("App::PropertyVector", "StartTangent", _tip("The direction the curve leaves its first point in"), V(1, 0, 0)),
        ("App::PropertyVector", "EndTangent", _tip("The direction the curve arrives at its last point in"), V(1, 0, 0)),
    )

    # Kernel argument -> property.
    _PROPERTIES = {"degree": "Degree", "parameterization": "Parameterization", "tangents": "StartTangent",
                   "tangents[0]": "StartTangent", "tangents[1]": "EndTangent"}

    def points(self, obj):
        links = [(o, subs) for o, subs in obj.Source if o is not None]
        points = source_points(links) if links else list(obj.Points)
        return [conversion.vector_tuple(p) for p in points]

    def curve(self, obj):
        """The ratbez.NurbsCurve of the feature (global coordinates, Placement not applied)."""
        rb = kernel.ratbez()
        points = self.points(obj)
        tangents = None
        if obj.EndTangents:
            tangents = (conversion.vector_tuple(obj.StartTangent), conversion.vector_tuple(obj.EndTangent))
        try:
            return rb.interpolate(points, obj.Degree, obj.Parameterization, tangents, obj.Closed)
        except kernel.error_types() as error:
            argument, reason = kernel.error_parts(error)
            points_property = "Source" if any(o is not None for o, _ in obj.Source) else "Points"
            raise Failure(self._PROPERTIES.get(argument, points_property), reason)

    def build_shape(self, obj):
        curve = self.curve(obj)
        knots, mults = [], []
        for k in curve.knots:
            if knots and k == knots[-1]:
                mults[-1] += 1
            else:
                knots.append(k)
                mults.append(1)
        occt = Part.BSplineCurve()
        occt.buildFromPolesMultsKnots([V(*p) for p in curve.points], mults, knots, False, curve.degree)
        size = max((math.dist(curve.points[0], p) for p in curve.points), default=1.0)
        features._check_against_kernel(curve.point, occt.value, [(k / 32.0,) for k in range(33)], size,  # noqa: SLF001
                                       "Points")
        return occt.toShape()


features.FEATURES["interpolate"] = Interpolate

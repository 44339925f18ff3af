"""The Part::FeaturePython proxies of the RatBez workbench.

Every feature rebuilds its shape from the ratbez kernel on each recompute. Solids are handed to FreeCAD
as the exact B-spline B-rep (see conversion.shape_from_solid); Bézier curves and surfaces, which
OpenCASCADE represents exactly, become Part.BezierCurve / Part.BezierSurface built from the same
poles and weights the kernel validated, cross-checked point by point against the kernel.

Bad input (a zero radius, a weight <= 0, a profile crossing the axis, ...) makes execute() raise:
FreeCAD then marks the object invalid ("Recompute failed"), keeps its last good shape, and the
kernel's message is printed to the report view.
"""

import math
import traceback

import FreeCAD as App
import Part

from . import conversion, kernel

V = App.Vector

# addProperty status bits (App::Property::Status): read-only and output (does not touch the object).
_READ_ONLY_OUTPUT = 1 | 8


class RatBezFeature:
    """Base of every RatBez proxy: declarative properties, execute with error reporting, persistence."""

    TYPE = "RatBez::Feature"
    GROUP = "RatBez"
    # (property type, name, tooltip, default); defaults may be callables (fresh lists) or None.
    PROPERTIES = ()

    def __init__(self, obj):
        self.Type = self.TYPE
        obj.Proxy = self
        self.ensure_properties(obj)

    # -- properties -------------------------------------------------------------------------------

    @classmethod
    def property_names(cls):
        return [p[1] for p in cls.PROPERTIES]

    def ensure_properties(self, obj):
        """Add the properties this version declares (also to objects saved by an older version)."""
        for type_name, name, tooltip, default in self.PROPERTIES:
            if name in obj.PropertiesList:
                continue
            obj.addProperty(type_name, name, self.GROUP, tooltip)
            if default is not None:
                setattr(obj, name, default() if callable(default) else default)

    # -- recompute --------------------------------------------------------------------------------

    def build_shape(self, obj):
        raise NotImplementedError

    def execute(self, obj):
        try:
            shape = self.build_shape(obj)
        except kernel.error_types() as error:
            App.Console.PrintError("RatBez: {} ({}): {}\n".format(obj.Label, obj.Name, error))
            raise
        except Exception as error:
            App.Console.PrintError("RatBez: {} ({}): internal error: {}\n{}".format(
                obj.Label, obj.Name, error, traceback.format_exc()))
            raise
        placement = obj.Placement
        shape.Placement = placement.multiply(shape.Placement)
        obj.Shape = shape

    def onChanged(self, obj, prop):
        pass

    def onDocumentRestored(self, obj):
        self.Type = self.TYPE
        self.ensure_properties(obj)

    # -- persistence (FreeCAD 0.20 under Python 3.11 calls either pair) ---------------------------

    def dumps(self):
        return {"Type": self.TYPE}

    def loads(self, state):
        self.Type = self.TYPE
        return None

    def __getstate__(self):
        return self.dumps()

    def __setstate__(self, state):
        self.loads(state)


def _finite_vector(name, vector):
    values = conversion.vector_tuple(vector)
    if not all(math.isfinite(c) for c in values):
        raise ValueError("{} must have finite coordinates, got {}".format(name, values))
    return values


# ---------------------------------------------------------------------------------------------------
# Solids

class SolidFeature(RatBezFeature):
    """A feature whose shape is a closed ratbez solid."""

    KERNEL_PROPERTIES = (
        ("App::PropertyFloat", "ExactVolume",
         "Volume of the exact solid computed by the ratbez kernel (Gauss quadrature on the exact "
         "surfaces), in mm^3, before the Placement is applied"),
    )

    def ensure_properties(self, obj):
        super().ensure_properties(obj)
        for type_name, name, tooltip in self.KERNEL_PROPERTIES:
            if name not in obj.PropertiesList:
                obj.addProperty(type_name, name, "Kernel", tooltip, _READ_ONLY_OUTPUT)

    def build_solid(self, obj):
        """The ratbez.Solid this feature describes (in the object's local coordinates)."""
        raise NotImplementedError

    def build_shape(self, obj):
        solid = self.build_solid(obj)
        shape = conversion.shape_from_solid(solid)
        obj.ExactVolume = solid.volume()
        return shape


class Cylinder(SolidFeature):
    TYPE = "RatBez::Cylinder"
    PROPERTIES = (
        ("App::PropertyLength", "Radius", "Radius of the cylinder", 2.0),
        ("App::PropertyLength", "Height", "Height of the cylinder along its axis", 10.0),
        ("App::PropertyVector", "Center", "Center of the base circle", lambda: V(0, 0, 0)),
        ("App::PropertyVector", "Axis", "Direction of the cylinder's axis (any non-zero length)",
         lambda: V(0, 0, 1)),
    )

    def build_solid(self, obj):
        return kernel.ratbez().cylinder(obj.Radius.Value, obj.Height.Value,
                                        _finite_vector("Center", obj.Center),
                                        _finite_vector("Axis", obj.Axis))


class Cone(SolidFeature):
    TYPE = "RatBez::Cone"
    PROPERTIES = (
        ("App::PropertyLength", "Radius1", "Radius of the base circle (at Center)", 2.0),
        ("App::PropertyLength", "Radius2", "Radius of the top circle (0 for a pointed cone)", 4.0),
        ("App::PropertyLength", "Height", "Height of the cone along its axis", 10.0),
        ("App::PropertyVector", "Center", "Center of the base circle", lambda: V(0, 0, 0)),
        ("App::PropertyVector", "Axis", "Direction of the cone's axis (any non-zero length)",
         lambda: V(0, 0, 1)),
    )

    def build_solid(self, obj):
        return kernel.ratbez().cone(obj.Radius1.Value, obj.Radius2.Value, obj.Height.Value,
                                    _finite_vector("Center", obj.Center),
                                    _finite_vector("Axis", obj.Axis))


class Sphere(SolidFeature):
    TYPE = "RatBez::Sphere"
    PROPERTIES = (
        ("App::PropertyLength", "Radius", "Radius of the sphere", 5.0),
        ("App::PropertyVector", "Center", "Center of the sphere", lambda: V(0, 0, 0)),
    )

    def build_solid(self, obj):
        return kernel.ratbez().sphere(obj.Radius.Value, _finite_vector("Center", obj.Center))


class Torus(SolidFeature):
    TYPE = "RatBez::Torus"
    PROPERTIES = (
        ("App::PropertyLength", "MajorRadius",
         "Distance from the axis to the center of the tube (must exceed MinorRadius)", 10.0),
        ("App::PropertyLength", "MinorRadius", "Radius of the tube", 2.0),
        ("App::PropertyVector", "Center", "Center of the torus", lambda: V(0, 0, 0)),
        ("App::PropertyVector", "Axis", "Direction of the torus' axis (any non-zero length)",
         lambda: V(0, 0, 1)),
    )

    def build_solid(self, obj):
        return kernel.ratbez().torus(obj.MajorRadius.Value, obj.MinorRadius.Value,
                                     _finite_vector("Center", obj.Center),
                                     _finite_vector("Axis", obj.Axis))


class Revolve(SolidFeature):
    TYPE = "RatBez::Revolve"
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile",
         "Profile to revolve: a sketch, a wire, or edges/faces of a shape. It must be closed, or open "
         "with both ends on the axis, and must not cross the axis", None),
        ("App::PropertyVector", "AxisPoint", "A point on the axis of revolution", lambda: V(0, 0, 0)),
        ("App::PropertyVector", "AxisDirection", "Direction of the axis of revolution",
         lambda: V(0, 0, 1)),
        ("App::PropertyAngle", "Angle",
         "Angle of revolution in degrees, in (0, 360]; the profile turns counterclockwise about "
         "AxisDirection", 360.0),
    )

    def build_solid(self, obj):
        profile = conversion.profile_from_link(obj.Profile)
        return kernel.ratbez().revolve(profile, _finite_vector("AxisPoint", obj.AxisPoint),
                                       _finite_vector("AxisDirection", obj.AxisDirection),
                                       float(obj.Angle.Value))


class Extrude(SolidFeature):
    TYPE = "RatBez::Extrude"
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile",
         "Closed planar profile to extrude: a sketch, a wire, or edges/faces of a shape", None),
        ("App::PropertyVector", "Direction",
         "Direction of the extrusion; the zero vector means the normal of the profile's plane",
         lambda: V(0, 0, 0)),
        ("App::PropertyDistance", "Distance",
         "Length of the extrusion along Direction (negative: the opposite way)", 10.0),
    )

    def build_solid(self, obj):
        profile = conversion.profile_from_link(obj.Profile)
        direction = V(*_finite_vector("Direction", obj.Direction))
        if direction.Length <= 1e-12:
            normal = conversion.profile_plane_normal(conversion.link_edges(obj.Profile))
            if normal is None:
                raise conversion.ProfileError("the profile is not planar, so Direction must be given")
            direction = normal
        distance = float(obj.Distance.Value)
        return kernel.ratbez().extrude(profile, conversion.vector_tuple(direction.normalize()), distance)


# ---------------------------------------------------------------------------------------------------
# Curves and surfaces (not solids)

# OpenCASCADE's Geom_BezierCurve / Geom_BezierSurface support degrees up to 25.
MAX_OCCT_BEZIER_DEGREE = 25


def _weights_or_none(obj):
    weights = [float(w) for w in obj.Weights]
    return weights if weights else None


def _check_against_kernel(kernel_point, occt_point, parameters, size, what):
    """Raise when OpenCASCADE's evaluation of the converted geometry departs from the kernel's."""
    worst = 0.0
    for params in parameters:
        p = kernel_point(*params)
        q = occt_point(*params)
        worst = max(worst, math.dist(p, (q.x, q.y, q.z)))
    if worst > 1e-9 * max(1.0, size):
        raise ValueError("{}: OpenCASCADE's geometry departs from the kernel's by {:.3g}".format(what, worst))


class BezierCurve(RatBezFeature):
    TYPE = "RatBez::BezierCurve"
    PROPERTIES = (
        ("App::PropertyVectorList", "Poles",
         "Control points; the degree is their number minus one", 
         lambda: [V(0, 0, 0), V(3, 6, 0), V(7, -3, 0), V(10, 3, 0)]),
        ("App::PropertyFloatList", "Weights",
         "One weight > 0 per pole for a rational curve; empty for a polynomial curve", lambda: []),
    )

    def build_shape(self, obj):
        points = [conversion.vector_tuple(p) for p in obj.Poles]
        weights = _weights_or_none(obj)
        curve = kernel.ratbez().BezierCurve(points, weights)
        if curve.degree > MAX_OCCT_BEZIER_DEGREE:
            raise ValueError("Poles: OpenCASCADE Bézier curves have at most {} poles, got {}".format(
                MAX_OCCT_BEZIER_DEGREE + 1, len(points)))
        occt = Part.BezierCurve()
        occt.setPoles([V(*p) for p in points])
        for index, weight in enumerate(weights or []):
            occt.setWeight(index + 1, weight)
        size = max((math.dist(points[0], p) for p in points), default=1.0)
        _check_against_kernel(curve.point, occt.value, [(k / 16.0,) for k in range(17)], size, "Poles")
        return occt.toShape()


class BezierSurface(RatBezFeature):
    TYPE = "RatBez::BezierSurface"
    PROPERTIES = (
        ("App::PropertyIntegerConstraint", "DegreeU",
         "Degree in u: the net has DegreeU + 1 rows of poles", (3, 1, MAX_OCCT_BEZIER_DEGREE, 1)),
        ("App::PropertyIntegerConstraint", "DegreeV",
         "Degree in v: every row has DegreeV + 1 poles", (3, 1, MAX_OCCT_BEZIER_DEGREE, 1)),
        ("App::PropertyVectorList", "Poles",
         "Control net, row by row: (DegreeU + 1) rows along u of (DegreeV + 1) poles along v. "
         "Changing a degree regenerates a flat net over the same extent", lambda: default_net(3, 3)),
        ("App::PropertyFloatList", "Weights",
         "One weight > 0 per pole, in the order of Poles, for a rational surface; empty for a "
         "polynomial surface", lambda: []),
    )

    def onChanged(self, obj, prop):
        if prop not in ("DegreeU", "DegreeV") or "Restore" in obj.State:
            return
        if not all(name in obj.PropertiesList for name in ("DegreeU", "DegreeV", "Poles", "Weights")):
            return
        rows, columns = obj.DegreeU + 1, obj.DegreeV + 1
        if len(obj.Poles) != rows * columns:
            obj.Poles = default_net(obj.DegreeU, obj.DegreeV, bounds_of(obj.Poles))
            if obj.Weights:
                obj.Weights = []

    def build_shape(self, obj):
        rows, columns = obj.DegreeU + 1, obj.DegreeV + 1
        poles = [conversion.vector_tuple(p) for p in obj.Poles]
        if len(poles) != rows * columns:
            raise ValueError("Poles: the net needs (DegreeU + 1) * (DegreeV + 1) = {} poles, got {}".format(
                rows * columns, len(poles)))
        net = [poles[i * columns:(i + 1) * columns] for i in range(rows)]
        flat_weights = _weights_or_none(obj)
        weights = None
        if flat_weights is not None:
            if len(flat_weights) != rows * columns:
                raise ValueError("Weights: one weight per pole is needed ({}), got {}".format(
                    rows * columns, len(flat_weights)))
            weights = [flat_weights[i * columns:(i + 1) * columns] for i in range(rows)]
        surface = kernel.ratbez().BezierSurface(net, weights)
        occt = Part.BezierSurface()
        occt.increase(obj.DegreeU, obj.DegreeV)
        for i in range(rows):
            for j in range(columns):
                if weights is None:
                    occt.setPole(i + 1, j + 1, V(*net[i][j]))
                else:
                    occt.setPole(i + 1, j + 1, V(*net[i][j]), weights[i][j])
        size = max((math.dist(poles[0], p) for p in poles), default=1.0)
        grid = [(a / 8.0, b / 8.0) for a in range(9) for b in range(9)]
        _check_against_kernel(surface.point, occt.value, grid, size, "Poles")
        face = Part.Face(occt)
        if not face.isValid():
            raise ValueError("the Bézier surface does not give a valid face")
        return face


def bounds_of(poles):
    """(xmin, xmax, ymin, ymax) of a list of vectors, or None."""
    if not poles:
        return None
    xs = [p.x for p in poles]
    ys = [p.y for p in poles]
    return min(xs), max(xs), min(ys), max(ys)


def default_net(degree_u, degree_v, bounds=None):
    """A control net of (degree_u + 1) x (degree_v + 1) poles over a rectangle, with the inner poles
    raised so that the surface is visibly curved."""
    xmin, xmax, ymin, ymax = bounds if bounds and bounds[1] > bounds[0] and bounds[3] > bounds[2] \
        else (0.0, 10.0, 0.0, 10.0)
    height = 0.3 * max(xmax - xmin, ymax - ymin)
    net = []
    for i in range(degree_u + 1):
        for j in range(degree_v + 1):
            inner = 0 < i < degree_u and 0 < j < degree_v
            net.append(V(xmin + (xmax - xmin) * i / degree_u, ymin + (ymax - ymin) * j / degree_v,
                         height if inner else 0.0))
    return net


# ---------------------------------------------------------------------------------------------------

FEATURES = {
    "bezier_curve": BezierCurve,
    "bezier_surface": BezierSurface,
    "cylinder": Cylinder,
    "cone": Cone,
    "sphere": Sphere,
    "torus": Torus,
    "revolve": Revolve,
    "extrude": Extrude,
}


def proxy_of(obj):
    proxy = getattr(obj, "Proxy", None) if obj is not None else None
    return proxy if isinstance(proxy, RatBezFeature) else None


def is_solid_feature(obj):
    return isinstance(proxy_of(obj), SolidFeature)

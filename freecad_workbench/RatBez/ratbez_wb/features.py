"""The Part::FeaturePython proxies of the RatBez workbench.

Every feature rebuilds its shape from the ratbez kernel on each recompute. Solids are handed to FreeCAD
as the exact B-spline B-rep, one face per face of the kernel, and cylinders, cones, spheres and tori as Part's
analytic primitives unless the preferences say otherwise (see conversion.shape_from_solid); Bézier curves
and surfaces, which OpenCASCADE represents exactly, become Part.BezierCurve / Part.BezierSurface built
from the same poles and weights the kernel validated, cross-checked point by point against the kernel.

Bad input (a zero radius, a weight <= 0, a profile crossing the axis, ...) fails the recompute:
FreeCAD marks the object invalid and keeps its last good shape, and one line in the property editor's
words goes to the report view (errors.py).
"""

import math
import traceback

import FreeCAD as App
import Part

from . import conversion, errors, kernel
from .errors import Failure, MessageContext
from .i18n import QT_TRANSLATE_NOOP, translate

V = App.Vector

# addProperty status bits (App::Property::Status): read-only and output (does not touch the object).
_READ_ONLY_OUTPUT = 1 | 8


def _tip(text):
    # Property tooltips are translated by FreeCAD in the "App::Property" context.
    return QT_TRANSLATE_NOOP("App::Property", text)


class RatBezFeature:
    """Base of every RatBez proxy: declarative properties, execute with error reporting, persistence."""

    TYPE = "RatBez::Feature"
    GROUP = "RatBez"
    # Links the feature cannot be built without; make_* does not recompute an object that lacks one.
    REQUIRED_LINKS = ()
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
        """Add the properties this version declares (also to objects saved by an older version), and
        change the type of those an older version declared differently (keeping their values)."""
        for type_name, name, tooltip, default in self.PROPERTIES:
            if _ensure_property(obj, type_name, name, self.GROUP, tooltip) and default is not None:
                setattr(obj, name, default() if callable(default) else default)

    # -- recompute --------------------------------------------------------------------------------

    def build_shape(self, obj):
        raise NotImplementedError

    def message_context(self, obj):
        """What errors.property_message needs to say a kernel error in this feature's terms."""
        return MessageContext()

    def execute(self, obj):
        failure = None
        try:
            shape = self.build_shape(obj)
        except Failure as error:
            failure = (str(error), None, error)
        except kernel.error_types() as error:
            argument, reason = kernel.error_parts(error)
            failure = (errors.property_message(argument, reason, self.message_context(obj)), None, error)
        except Exception as error:  # a bug: say so in one line, the traceback with the debug preference
            failure = (translate("internal error: {}").format(error), traceback.format_exc(), error)
        if failure is not None:
            # Outside the except clauses: an exception raised while handling another one gets it as its
            # context, which makes Python build it as an object (errors._raise_reported needs it not to).
            errors.fail(obj, self, *failure)
        errors.succeeded(self)
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


def _ensure_property(obj, type_name, name, group, tooltip, status=0):
    """Give obj the property `name` of type_name: added when missing (True: it holds its type's default), or
    retyped, keeping its value, when an older version declared it with another type."""
    if name not in obj.PropertiesList:
        obj.addProperty(type_name, name, group, tooltip, status)
        return True
    if obj.getTypeIdOfProperty(name) != type_name:
        kept = _plain_value(getattr(obj, name))
        obj.removeProperty(name)
        obj.addProperty(type_name, name, group, tooltip, status)
        setattr(obj, name, kept)
    return False


def _plain_value(value):
    """A property value as something a property of another type accepts (a Quantity's number)."""
    return getattr(value, "Value", value)


def _finite_vector(name, vector):
    values = conversion.vector_tuple(vector)
    if not all(math.isfinite(c) for c in values):
        raise Failure(name, translate("must have finite coordinates, got {}").format(values))
    return values


# ---------------------------------------------------------------------------------------------------
# Solids

class SolidFeature(RatBezFeature):
    """A feature whose shape is a closed ratbez solid."""

    # Quantities, shown with their units as the Length properties are; App::PropertyFloat before (a document
    # saved then gets these types when it loads, ensure_properties).
    KERNEL_PROPERTIES = (
        ("App::PropertyVolume", "ExactVolume",
         _tip("Volume of the exact solid computed by the ratbez kernel (certified Gauss quadrature on the "
              "exact surfaces), in mm^3, Placement not applied. FreeCAD's own Shape.Volume, Part > Check "
              "geometry and Measure read the faces RatBez hands to FreeCAD (a primitive's analytic ones, as "
              "Part's; otherwise B-spline faces, one per face, each arc in an exact form OpenCASCADE's fixed "
              "Gauss rule reads) and agree with this to about 1e-9; within 1e-4 where a profile is a B-spline "
              "the kernel hands over with its own knots (an extruded sketch spline: 1.5e-5)")),
        ("App::PropertyArea", "ExactArea",
         _tip("Surface area of the exact solid computed by the ratbez kernel, in mm^2. FreeCAD's Shape.Area "
              "agrees with it as Shape.Volume does (see ExactVolume)")),
    )

    def ensure_properties(self, obj):
        super().ensure_properties(obj)
        for type_name, name, tooltip in self.KERNEL_PROPERTIES:
            _ensure_property(obj, type_name, name, "Kernel", tooltip, _READ_ONLY_OUTPUT)

    def build_solid(self, obj):
        """The ratbez.Solid this feature describes (in the object's local coordinates)."""
        raise NotImplementedError

    def build_shape(self, obj):
        solid = self.build_solid(obj)
        shape = conversion.shape_from_solid(solid)
        obj.ExactVolume = solid.volume()
        obj.ExactArea = solid.area()
        return shape


def _length(name, tooltip, default):
    return ("App::PropertyLength", name, _tip(tooltip), default)


def _center(tooltip):
    return ("App::PropertyVector", "Center", _tip(tooltip), lambda: V(0, 0, 0))


def _axis(tooltip):
    return ("App::PropertyVector", "Axis", _tip(tooltip), lambda: V(0, 0, 1))


class Cylinder(SolidFeature):
    TYPE = "RatBez::Cylinder"
    PROPERTIES = (
        _length("Radius", "Radius of the cylinder", 2.0),
        _length("Height", "Height of the cylinder along its axis", 10.0),
        _center("Center of the base circle"),
        _axis("Direction of the cylinder's axis (any non-zero length)"),
    )

    def build_solid(self, obj):
        return kernel.ratbez().cylinder(obj.Radius.Value, obj.Height.Value, _finite_vector("Center", obj.Center),
                                        _finite_vector("Axis", obj.Axis))


class Cone(SolidFeature):
    TYPE = "RatBez::Cone"
    PROPERTIES = (
        _length("Radius1", "Radius of the base circle (at Center)", 2.0),
        _length("Radius2", "Radius of the top circle (0 for a pointed cone)", 4.0),
        _length("Height", "Height of the cone along its axis", 10.0),
        _center("Center of the base circle"),
        _axis("Direction of the cone's axis (any non-zero length)"),
    )

    def build_solid(self, obj):
        return kernel.ratbez().cone(obj.Radius1.Value, obj.Radius2.Value, obj.Height.Value,
                                    _finite_vector("Center", obj.Center), _finite_vector("Axis", obj.Axis))


class Sphere(SolidFeature):
    TYPE = "RatBez::Sphere"
    PROPERTIES = (
        _length("Radius", "Radius of the sphere", 5.0),
        _center("Center of the sphere"),
    )

    def build_solid(self, obj):
        return kernel.ratbez().sphere(obj.Radius.Value, _finite_vector("Center", obj.Center))


class Torus(SolidFeature):
    TYPE = "RatBez::Torus"
    PROPERTIES = (
        _length("MajorRadius", "Distance from the axis to the center of the tube (must exceed MinorRadius)", 10.0),
        _length("MinorRadius", "Radius of the tube", 2.0),
        _center("Center of the torus"),
        _axis("Direction of the torus' axis (any non-zero length)"),
    )

    def build_solid(self, obj):
        return kernel.ratbez().torus(obj.MajorRadius.Value, obj.MinorRadius.Value,
                                     _finite_vector("Center", obj.Center), _finite_vector("Axis", obj.Axis))


# The features whose solids go over as OpenCASCADE primitives when the preference asks (conversion.shape_from_solid).
PRIMITIVES = (Cylinder, Cone, Sphere, Torus)


def rebuild_primitives():
    """Recomputes the RatBez cylinders, cones, spheres and tori of every open document, so that they take the
    geometry the preferences now ask for (and whatever depends on them follows)."""
    for doc in App.listDocuments().values():
        primitives = [obj for obj in doc.Objects if isinstance(getattr(obj, "Proxy", None), PRIMITIVES)]
        for obj in primitives:
            obj.touch()
        if primitives:
            doc.recompute()


class ProfileFeature(SolidFeature):
    """A solid built from a linked profile; its error messages name the profile's edges."""

    def message_context(self, obj):
        profile = getattr(self, "profile", None)
        return MessageContext(loops=profile.names if profile else [])


# How a revolution's axis is given: the profile plane's vertical or horizontal axis (recomputed from the
# profile each time, so it follows a sketch that moves, as PartDesign's sketch axes do), a global axis, a
# straight edge or datum line (AxisReference), or AxisPoint and AxisDirection as typed.
REVOLVE_AXIS_MODES = ["Vertical", "Horizontal", "X", "Y", "Z", "Reference", "Custom"]
_GLOBAL_AXES = {"X": (1, 0, 0), "Y": (0, 1, 0), "Z": (0, 0, 1)}


class Revolve(ProfileFeature):
    TYPE = "RatBez::Revolve"
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile",
         _tip("Profile to revolve: a sketch, a 2D object, a wire, edges or one face (without holes). It must be "
              "closed, or open with both ends on the axis, and must not cross the axis"), None),
        ("App::PropertyEnumeration", "AxisMode",
         _tip("Vertical / Horizontal: the profile plane's vertical or horizontal axis (a sketch's V or H axis), "
              "found again at every recompute, so the axis moves with the sketch; X, Y, Z: a global axis; "
              "Reference: AxisReference; Custom: AxisPoint and AxisDirection"), lambda: list(REVOLVE_AXIS_MODES)),
        ("App::PropertyLinkSub", "AxisReference",
         _tip("A straight edge or a datum line to revolve about (AxisMode Reference). AxisPoint and "
              "AxisDirection follow it"), None),
        ("App::PropertyVector", "AxisPoint",
         _tip("A point on the axis of revolution: typed for AxisMode Custom, else the axis used"), lambda: V(0, 0, 0)),
        ("App::PropertyVector", "AxisDirection",
         _tip("Direction of the axis of revolution: typed for AxisMode Custom, else the axis used"), lambda: V(0, 0, 1)),
        ("App::PropertyFloat", "Angle",
         _tip("Angle of revolution in degrees, in (0, 360]; other values are refused. The profile turns "
              "counterclockwise about AxisDirection (clockwise with Reversed)"), 360.0),
        ("App::PropertyBool", "Symmetric",
         _tip("Revolve Angle / 2 to each side of the profile instead of Angle to one side"), False),
        ("App::PropertyBool", "Reversed", _tip("Revolve the other way (clockwise about AxisDirection)"), False),
    )

    def ensure_properties(self, obj):
        restoring = "AxisMode" not in obj.PropertiesList and "AxisPoint" in obj.PropertiesList
        self.updating_axis = True  # the defaults set here are nobody's choice of a custom axis
        try:
            super().ensure_properties(obj)
        finally:
            self.updating_axis = False
        if restoring:
            # Saved before AxisMode existed, the axis was fixed: Reference when one was linked, else Custom (it
            # keeps the stored AxisPoint and AxisDirection; choose Vertical to make it follow the sketch).
            obj.AxisMode = "Reference" if obj.AxisReference else "Custom"

    def onChanged(self, obj, prop):
        # Typed in the property editor (or set by a script), an axis point or direction means a custom axis,
        # and a linked edge a reference axis, as before AxisMode existed; the feature's own updates of them
        # (axis()) and a document being restored change no mode.
        if getattr(self, "updating_axis", False) or "Restore" in obj.State or "AxisMode" not in obj.PropertiesList:
            return
        if prop in ("AxisPoint", "AxisDirection") and obj.AxisMode not in ("Custom", "Reference"):
            obj.AxisMode = "Custom"
        elif prop == "AxisReference" and obj.AxisReference and obj.AxisMode != "Reference":
            obj.AxisMode = "Reference"

    def axis(self, obj):
        """(point, unit direction) of the axis used, by AxisMode; AxisPoint and AxisDirection are set to it
        (they show the axis used in every mode)."""
        mode = obj.AxisMode
        found = None
        if mode == "Reference":
            found = conversion.straight_line(obj.AxisReference, "AxisReference")
        elif mode in ("Vertical", "Horizontal"):
            found = conversion.revolve_axis(obj.Profile, mode)
        elif mode in _GLOBAL_AXES:
            found = V(0, 0, 0), V(*_GLOBAL_AXES[mode])
        if found is not None:
            point, direction = found
            if (obj.AxisPoint - point).Length > 1e-12 or (obj.AxisDirection - direction).Length > 1e-12:
                self.updating_axis = True
                try:
                    obj.AxisPoint, obj.AxisDirection = point, direction
                finally:
                    self.updating_axis = False
        direction = V(*_finite_vector("AxisDirection", obj.AxisDirection))
        if direction.Length <= 1e-12:
            raise Failure("AxisDirection", translate("must not be the zero vector"))
        return V(*_finite_vector("AxisPoint", obj.AxisPoint)), direction.normalize()

    def build_solid(self, obj):
        self.profile = None
        profile = conversion.resolve_profile(obj.Profile)
        self.profile = profile
        require_revolvable(profile)
        angle = float(obj.Angle)
        if not (0 < angle <= 360):
            raise Failure("Angle", translate("must be in (0, 360] degrees, got {:g}").format(angle))
        point, direction = self.axis(obj)
        if obj.Reversed:
            direction = direction * -1
        if obj.Symmetric:
            profile = profile.moved(App.Placement(V(0, 0, 0), App.Rotation(direction, -angle / 2), point))
        return kernel.ratbez().revolve(profile.curves(), conversion.vector_tuple(point),
                                       conversion.vector_tuple(direction), angle)


EXTRUDE_DIRECTION_MODES = ["Normal", "Edge", "Custom"]


class Extrude(ProfileFeature):
    TYPE = "RatBez::Extrude"
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile",
         _tip("Closed planar profile to extrude: a sketch, a 2D object, a wire, edges or one face. Closed loops "
              "inside the outer one (a face's holes, inner loops of a sketch) become holes through the solid"),
         None),
        ("App::PropertyEnumeration", "DirectionMode",
         _tip("Normal: along the profile's normal (a sketch's or face's normal); Edge: along DirectionReference; "
              "Custom: along Direction"), lambda: list(EXTRUDE_DIRECTION_MODES)),
        ("App::PropertyLinkSub", "DirectionReference",
         _tip("A straight edge or datum line giving the direction when DirectionMode is Edge"), None),
        ("App::PropertyVector", "Direction",
         _tip("Direction of the extrusion when DirectionMode is Custom (any non-zero length)"), lambda: V(0, 0, 1)),
        ("App::PropertyDistance", "Distance",
         _tip("Length of the extrusion along the direction; a negative Distance extrudes the other way"), 10.0),
        ("App::PropertyBool", "Reversed", _tip("Extrude the other way"), False),
        ("App::PropertyBool", "Symmetric", _tip("Extrude Distance / 2 to each side of the profile"), False),
    )

    def ensure_properties(self, obj):
        restoring = "DirectionMode" not in obj.PropertiesList and "Direction" in obj.PropertiesList
        super().ensure_properties(obj)
        if restoring:
            # Saved before DirectionMode existed: a zero Direction meant the profile's normal.
            obj.DirectionMode = "Normal" if obj.Direction.Length <= 1e-12 else "Custom"

    def direction(self, obj):
        """The unit extrusion direction before Reversed and the sign of Distance."""
        if obj.DirectionMode == "Edge":
            return conversion.straight_line(obj.DirectionReference, "DirectionReference")[1]
        if obj.DirectionMode == "Custom":
            direction = V(*_finite_vector("Direction", obj.Direction))
            if direction.Length <= 1e-12:
                raise Failure("Direction", translate("must not be the zero vector"))
            return direction.normalize()
        return conversion.profile_normal(obj.Profile)

    def build_solid(self, obj):
        self.profile = None
        profile = conversion.resolve_profile(obj.Profile)
        self.profile = profile
        require_extrudable(profile)
        distance = float(obj.Distance.Value)
        if distance == 0 or not math.isfinite(distance):
            raise Failure("Distance", translate("must be a non-zero length (negative: the other way)"))
        direction = self.direction(obj)
        if obj.Reversed != (distance < 0):
            direction = direction * -1
        length = abs(distance)
        if obj.Symmetric:
            profile = profile.moved(App.Placement(direction * (-length / 2), App.Rotation()))
        holes = [profile.curves(h + 1) for h in range(profile.hole_count)]
        return kernel.ratbez().extrude(profile.curves(), conversion.vector_tuple(direction), length,
                                       holes=holes or None)


def require_revolvable(profile):
    """What Revolve asks of a profile beyond the kernel's checks: no holes (the kernel's solids have one
    shell)."""
    if profile.hole_count:
        raise conversion.ProfileError(translate(
            "the face has {} hole(s); a face with holes cannot be revolved (select its outer edges)")
            .format(profile.hole_count))


def require_one_loop(profile, prop="Profile"):
    """What Ruled, Loft and Sweep ask of a profile beyond the kernel's checks: one loop (their solids are
    capped by the profiles themselves, which the kernel takes without holes)."""
    if profile.hole_count:
        raise conversion.ProfileError(translate(
            "the face has {} hole(s); lofts, ruled solids and sweeps take profiles without holes (select the "
            "outer edges)").format(profile.hole_count), prop)


class SectionsFeature(ProfileFeature):
    """A solid through several profiles (Ruled, Loft): kernel errors about profiles[k] name the section."""

    def section_words(self, obj):
        """For each section, (property, words before the reason): ("Profile2", "") or ("Sections", "section 2
        (Circle001)")."""
        raise NotImplementedError

    def message_context(self, obj):
        sections = getattr(self, "sections", None) or []
        try:
            words = self.section_words(obj)
        except Exception:  # a link that no longer resolves: plain kernel words then
            words = []
        return MessageContext(sections=words, section_loops=[p.names for p in sections])

    def resolve_sections(self, obj, links):
        """The Profiles of the links, in order; a Failure names the section."""
        self.sections = []
        words = self.section_words(obj)
        for (prop, where), link in zip(words, links):
            try:
                profile = conversion.resolve_profile(link, prop)
                require_one_loop(profile, prop)
            except Failure as error:
                failure = error
            else:
                self.sections.append(profile)
                continue
            raise Failure(prop, "{}: {}".format(where, failure.reason) if where else failure.reason)
        return self.sections


# Issue 26: how the sections are matched to one another (Ruled, Loft).
_ALIGN = ("App::PropertyBool", "Align",
          _tip("Match the profiles by arc length: each runs the same way, each starts where the rulings to the one "
               "before it are shortest (least twist), and every corner or joint of one meets the point of the other at "
               "the same fraction of its length; the first profile's start vertex sets the seam. Off: the profiles' "
               "start vertices and parameters are matched as they are"), True)
_START_VERTICES = ("App::PropertyIntegerList", "StartVertices",
                   _tip("The vertex each profile starts at, in profile order, counted from 1 along its edges (0 or "
                        "missing: where the profile starts). With Align only the first profile's matters (the seam); "
                        "without, every profile's start is matched to the others'"), lambda: [])


def start_at_vertex(curves, vertex, prop, where=""):
    """The profile's curves (one closed loop, in order) started at its vertex number `vertex` (1-based, the start
    of curve vertex - 1; 0: as it is)."""
    if vertex == 0:
        return curves
    if not 1 <= vertex <= len(curves):
        raise Failure(prop, "{}{}".format(where + ": " if where else "", translate(
            "start vertex {} does not exist: the profile has {} vertices (0 for its own start)").format(vertex, len(curves))))
    return curves[vertex - 1:] + curves[:vertex - 1]


def matched_sections(obj, profiles, words):
    """The curves of each profile, each started at its StartVertices entry."""
    starts = list(obj.StartVertices) + [0] * len(profiles)
    return [start_at_vertex(p.curves(), starts[k], "StartVertices", words[k][1] or words[k][0])
            for k, p in enumerate(profiles)]


class Ruled(SectionsFeature):
    TYPE = "RatBez::Ruled"
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile1",
         _tip("First closed planar profile: a sketch, a 2D object, a wire, edges or one face (without holes)"),
         None),
        ("App::PropertyLinkSub", "Profile2",
         _tip("Second closed planar profile, entirely in front of the first one's plane; straight rulings join "
              "the two (matched as Align says)"), None),
        _ALIGN,
        _START_VERTICES,
    )

    def section_words(self, obj):
        return [("Profile1", ""), ("Profile2", "")]

    def build_solid(self, obj):
        profiles = self.resolve_sections(obj, [obj.Profile1, obj.Profile2])
        return kernel.ratbez().loft(matched_sections(obj, profiles, self.section_words(obj)), degree=1, ruled=True,
                                    align=obj.Align)


LOFT_MAX_DEGREE = 25


class Loft(SectionsFeature):
    TYPE = "RatBez::Loft"
    PROPERTIES = (
        ("App::PropertyLinkSubList", "Sections",
         _tip("Closed planar profiles to loft through, in order (at least two): sketches, 2D objects, wires, "
              "edges or faces without holes, each entirely in front of the previous one's plane. The solid is "
              "capped by the first and last"), lambda: []),
        ("App::PropertyIntegerConstraint", "Degree",
         _tip("Degree of the surface across the sections (at most the number of sections minus one is used); "
              "the surface passes through every section exactly"), (3, 1, LOFT_MAX_DEGREE, 1)),
        ("App::PropertyBool", "Ruled", _tip("Join consecutive sections by straight rulings (degree 1 across)"),
         False),
        _ALIGN,
        _START_VERTICES,
    )

    def section_links(self, obj):
        """The sections in order, one link each. FreeCAD groups neighbouring entries of one object into one
        (box, ('Face1', 'Face6')): faces of such an entry are separate sections."""
        links = []
        for owner, subs in obj.Sections:
            subs = [s for s in (subs or []) if s]
            if len(subs) > 1 and all(s.startswith("Face") for s in subs):
                links.extend((owner, [s]) for s in subs)
            else:
                links.append((owner, subs))
        return links

    def section_words(self, obj):
        return [("Sections", translate("section {} ({})").format(k + 1, conversion.link_label(link)))
                for k, link in enumerate(self.section_links(obj))]

    def build_solid(self, obj):
        links = self.section_links(obj)
        if len(links) < 2:
            raise Failure("Sections", translate("a loft needs at least 2 sections, got {}").format(len(links)))
        sections = self.resolve_sections(obj, links)
        return kernel.ratbez().loft(matched_sections(obj, sections, self.section_words(obj)), degree=obj.Degree,
                                    ruled=obj.Ruled, align=obj.Align)


class Sweep(ProfileFeature):
    TYPE = "RatBez::Sweep"
    REQUIRED_LINKS = ("Path",)
    PROPERTIES = (
        ("App::PropertyLinkSub", "Profile",
         _tip("Closed planar profile to sweep: a sketch, a 2D object, a wire, edges or one face (without holes), "
              "crossing the path (not in a plane containing the path's starting tangent)"), None),
        ("App::PropertyLinkSub", "Path",
         _tip("Path to sweep along: a sketch, a wire or edges making one tangent-continuous chain. The profile "
              "is carried with a rotation-minimising frame; a closed path closes the solid on itself"), None),
        # PropertyPrecision, as Part's own tolerances: the property editor shows and takes small numbers (a Float
        # showed 1e-6 as "0.00", and Enter in its field stored 0).
        ("App::PropertyPrecision", "Tolerance",
         _tip("Largest distance in mm from the true sweep where it is not rational (paths of lines and circular "
              "arcs give the exact solid); > 0"), 1e-6),
    )

    def build_solid(self, obj):
        self.profile = None
        profile = conversion.resolve_profile(obj.Profile)
        self.profile = profile
        require_one_loop(profile)
        path = conversion.resolve_path(obj.Path)
        tolerance = float(obj.Tolerance)
        if not (tolerance > 0 and math.isfinite(tolerance)):
            raise Failure("Tolerance", translate("must be a length > 0 (mm), got {:g}").format(tolerance))
        return kernel.ratbez().sweep(profile.curves(), path, tolerance)


def linked_objects(obj):
    """The objects a RatBez feature is built from (its profiles, sections and path), in order, each once."""
    found = []
    for prop in ("Profile", "Profile1", "Profile2", "Path"):
        link = getattr(obj, prop, None) if obj is not None else None
        if link and link[0] is not None:
            found.append(link[0])
    for owner, _ in (getattr(obj, "Sections", None) or []) if obj is not None else []:
        found.append(owner)
    unique = []
    for item in found:
        if all(item is not other for other in unique):
            unique.append(item)
    return unique


def require_extrudable(profile):
    """What Extrude asks first: a closed outer loop (to 1e-9 of its size, the kernel's joint tolerance).
    Checked before planarity, so a single straight edge is told it is not closed."""
    loop = profile.loops[0]
    points = [p for piece in loop for p in piece["points"]]
    size = math.dist([min(c) for c in zip(*points)], [max(c) for c in zip(*points)])
    if math.dist(loop[0]["points"][0], loop[-1]["points"][-1]) > 1e-9 * size:
        raise conversion.ProfileError(translate("is not closed; an extrusion needs a closed profile"))


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
        raise Failure(what, translate("OpenCASCADE's geometry departs from the kernel's by {:.3g}").format(worst))


# The kernel's bound on a solid's coordinates (limits.hpp: max_solid_coordinate), held for the curve and surface
# features too: OpenCASCADE's display measures the curve's length, which overflows to infinity near 1e300 and
# froze FreeCAD's GUI in a loop (a pole typed as -1e300).
MAX_COORDINATE = 1e100


def _require_coordinates_within_limit(points, what="Poles"):
    for index, point in enumerate(points):
        if any(abs(c) > MAX_COORDINATE for c in point):
            raise Failure(what, translate("pole {} of {} has a coordinate beyond {:g}").format(
                index + 1, len(points), MAX_COORDINATE))


class BezierCurve(RatBezFeature):
    TYPE = "RatBez::BezierCurve"
    PROPERTIES = (
        ("App::PropertyVectorList", "Poles", _tip("Control points; the degree is their number minus one"),
         lambda: [V(0, 0, 0), V(3, 6, 0), V(7, -3, 0), V(10, 3, 0)]),
        ("App::PropertyFloatList", "Weights",
         _tip("One weight > 0 per pole for a rational curve; empty for a polynomial curve"), lambda: []),
    )

    def message_context(self, obj):
        return MessageContext(counts={"Weights": len(obj.Weights), "Poles": len(obj.Poles)})

    def build_shape(self, obj):
        points = [conversion.vector_tuple(p) for p in obj.Poles]
        weights = _weights_or_none(obj)
        curve = kernel.ratbez().BezierCurve(points, weights)
        _require_coordinates_within_limit(points)
        if curve.degree > MAX_OCCT_BEZIER_DEGREE:
            raise Failure("Poles", translate("OpenCASCADE Bézier curves have at most {} poles, got {}").format(
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
        ("App::PropertyIntegerConstraint", "DegreeU", _tip("Degree in u: the net has DegreeU + 1 rows of poles"),
         (3, 1, MAX_OCCT_BEZIER_DEGREE, 1)),
        ("App::PropertyIntegerConstraint", "DegreeV", _tip("Degree in v: every row has DegreeV + 1 poles"),
         (3, 1, MAX_OCCT_BEZIER_DEGREE, 1)),
        ("App::PropertyVectorList", "Poles",
         _tip("Control net, row by row: (DegreeU + 1) rows along u of (DegreeV + 1) poles along v. Changing a "
              "degree regenerates a flat net over the same extent"), lambda: default_net(3, 3)),
        ("App::PropertyFloatList", "Weights",
         _tip("One weight > 0 per pole, in the order of Poles, for a rational surface; empty for a polynomial "
              "surface"), lambda: []),
    )

    def message_context(self, obj):
        return MessageContext(counts={"Weights": len(obj.Weights), "Poles": len(obj.Poles)},
                              net_columns=obj.DegreeV + 1)

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
            raise Failure("Poles", translate("the net needs (DegreeU + 1) x (DegreeV + 1) = {} poles, got {}")
                          .format(rows * columns, len(poles)))
        net = [poles[i * columns:(i + 1) * columns] for i in range(rows)]
        _require_coordinates_within_limit(poles)
        flat_weights = _weights_or_none(obj)
        weights = None
        if flat_weights is not None:
            if len(flat_weights) != rows * columns:
                raise Failure("Weights", translate("one weight per pole is needed ({}), got {}").format(
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
            raise Failure("Poles", translate("the Bézier surface does not give a valid face"))
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
    "ruled": Ruled,
    "loft": Loft,
    "sweep": Sweep,
}


def proxy_of(obj):
    proxy = getattr(obj, "Proxy", None) if obj is not None else None
    return proxy if isinstance(proxy, RatBezFeature) else None


def is_solid_feature(obj):
    return isinstance(proxy_of(obj), SolidFeature)

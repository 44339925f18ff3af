"""RatBez: exact rational Bézier / NURBS solids as parametric FreeCAD objects.

Scripting interface (works in freecadcmd, without the GUI):

    import RatBez
    cyl = RatBez.make_cylinder(Radius=2, Height=5)
    rev = RatBez.make_revolve(Profile=sketch, Angle=270)
    loft = RatBez.make_loft(Sections=[bottom, middle, top])
    spline = RatBez.make_interpolate(Source=[(sketch, ["Vertex1", "Vertex3", "Vertex2"])], Closed=True)
    swept = RatBez.make_sweep(Profile=circle, Path=(sketch, ["Edge1", "Edge2"]))
    RatBez.export_openscad(cyl, "/tmp/cyl.scad", tolerance=0.01)
    print(RatBez.check_occt(cyl))

Every make_<thing>(doc=None, **properties) adds a Part::FeaturePython to `doc` (default: the active
document, or a new one), sets the given FreeCAD-style properties, recomputes and returns the object.
Bad property values do not raise here: the object is marked invalid and the kernel's message goes to
the report view, exactly as when the value is typed into the property editor.
"""


import FreeCAD as App
import Part

from ratbez_wb import conversion, curve_tools, features, kernel  # noqa: F401 (curve_tools registers Interpolate)
from ratbez_wb import text as text_tools

__all__ = ["make_bezier_curve", "make_bezier_surface", "make_cylinder", "make_cone", "make_sphere",
           "make_torus", "make_revolve", "make_extrude", "make_ruled", "make_loft", "make_sweep", "make_interpolate", "is_solid",
           "solid_of", "export_openscad", "check_occt", "format_check_report", "check_passed", "safe_label",
           "export"]

_DEFAULT_NAMES = {
    "bezier_curve": "BezierCurve", "bezier_surface": "BezierSurface", "cylinder": "Cylinder",
    "cone": "Cone", "sphere": "Sphere", "torus": "Torus", "revolve": "Revolve", "extrude": "Extrude",
    "ruled": "Ruled", "loft": "Loft", "sweep": "Sweep", "interpolate": "Interpolate",
}
# Properties that link a profile (or a path): each takes what _profile_link accepts.
_LINK_PROPERTIES = ("Profile", "Profile1", "Profile2", "Path")
# Properties every Part::FeaturePython has that make_* also accepts.
_COMMON_PROPERTIES = ("Label", "Placement")


def _profile_link(doc, value, prop="Profile"):
    """A PropertyLinkSub value from what a script naturally passes as a profile: a document object
    (a sketch, a wire feature), (object, "Edge1") or (object, ["Edge1", ...]), or a bare Part shape
    (an edge, wire or face, which is added to the document as a Part::Feature)."""
    if value is None:
        return None
    if isinstance(value, Part.Shape):
        holder = doc.addObject("Part::Feature", prop)
        holder.Shape = value
        return (holder, [])
    if isinstance(value, (tuple, list)):
        if len(value) != 2:
            raise TypeError("{}: expected an object or (object, sub-element names), got {!r}".format(prop, value))
        obj, subs = value
        return (obj, [subs] if isinstance(subs, str) else list(subs))
    return (value, [])


def _make(kind, doc, properties):
    cls = features.FEATURES[kind]
    allowed = set(cls.property_names()) | set(_COMMON_PROPERTIES)
    unknown = sorted(set(properties) - allowed)
    if unknown:
        raise TypeError("make_{}: unknown propert{} {}; valid: {}".format(
            kind, "y" if len(unknown) == 1 else "ies", ", ".join(unknown),
            ", ".join(sorted(allowed))))
    if doc is None:
        doc = App.ActiveDocument or App.newDocument()
    properties = dict(properties)
    for prop in _LINK_PROPERTIES:
        if prop in properties:
            properties[prop] = _profile_link(doc, properties[prop], prop)
    if "Sections" in properties:
        # PropertyLinkSubList keeps the order only given sub-element lists: (obj, [""]) for a whole object.
        properties["Sections"] = [(link[0], link[1] or [""]) for link in
                                  (_profile_link(doc, value, "Sections") for value in properties["Sections"])]
    _complete(kind, properties)
    obj = doc.addObject("Part::FeaturePython", _DEFAULT_NAMES[kind])
    cls(obj)
    if App.GuiUp:
        from ratbez_wb import view_providers
        view_providers.ViewProviderRatBez(obj.ViewObject)
    # Degrees first, so that a net given together with them is not replaced by a default net.
    ordered = sorted(properties.items(), key=lambda item: item[0] not in ("DegreeU", "DegreeV"))
    for name, value in ordered:
        setattr(obj, name, value)
    if App.GuiUp:
        for link in _links_of(properties):
            if conversion.is_whole_profile_object(link):
                link[0].ViewObject.Visibility = False
    doc.recompute()
    return obj


def _links_of(properties):
    """The profile, section and path links among make_* properties."""
    links = [properties[prop] for prop in _LINK_PROPERTIES if properties.get(prop) is not None]
    return links + [(obj, [s for s in subs if s]) for obj, subs in properties.get("Sections") or []]


def _complete(kind, properties):
    """Defaults that depend on other properties: a revolve's axis is the profile's vertical axis (as for a
    sketch in Sketcher and PartDesign) unless one is given; an extrusion given a Direction or a
    DirectionReference goes along it."""
    if kind == "revolve" and properties.get("Profile") and not (
            {"AxisPoint", "AxisDirection", "AxisReference"} & set(properties)):
        try:
            point, direction = conversion.revolve_axis(properties["Profile"])
        except conversion.ProfileError:
            return  # not planar: the recompute says so
        properties["AxisPoint"], properties["AxisDirection"] = point, direction
    if kind == "extrude" and "DirectionMode" not in properties:
        if properties.get("DirectionReference"):
            properties["DirectionMode"] = "Edge"
        elif "Direction" in properties:
            properties["DirectionMode"] = "Custom"


def make_bezier_curve(doc=None, **properties):
    """A rational Bézier curve. Properties: Poles (list of vectors), Weights (empty: polynomial)."""
    return _make("bezier_curve", doc, properties)


def make_bezier_surface(doc=None, **properties):
    """A rational Bézier surface patch. Properties: DegreeU, DegreeV, Poles (row by row), Weights."""
    return _make("bezier_surface", doc, properties)


def make_cylinder(doc=None, **properties):
    """A solid cylinder. Properties: Radius, Height, Center (base center), Axis."""
    return _make("cylinder", doc, properties)


def make_cone(doc=None, **properties):
    """A solid (truncated) cone. Properties: Radius1, Radius2, Height, Center, Axis."""
    return _make("cone", doc, properties)


def make_sphere(doc=None, **properties):
    """A solid sphere. Properties: Radius, Center."""
    return _make("sphere", doc, properties)


def make_torus(doc=None, **properties):
    """A solid torus. Properties: MajorRadius, MinorRadius, Center, Axis."""
    return _make("torus", doc, properties)


def make_revolve(doc=None, **properties):
    """A solid of revolution. Properties: Profile (sketch, wire, edge, face, (object, subnames) or a Part
    shape), AxisReference (a straight edge or datum line) or AxisPoint and AxisDirection (default: the
    profile's vertical axis, as a sketch revolves), Angle (degrees, in (0, 360]), Symmetric, Reversed."""
    return _make("revolve", doc, properties)


def make_extrude(doc=None, **properties):
    """A prism. Properties: Profile (closed and planar; inner loops are holes), DirectionMode ("Normal",
    "Edge" along DirectionReference, "Custom" along Direction; given a Direction, Custom), Distance
    (negative: the other way), Reversed, Symmetric."""
    return _make("extrude", doc, properties)


def make_ruled(doc=None, **properties):
    """A ruled solid: straight rulings between two closed planar profiles (without holes), capped by them.
    Properties: Profile1, Profile2 (each as make_revolve's Profile), the second entirely in front of the
    first one's plane."""
    return _make("ruled", doc, properties)


def make_loft(doc=None, **properties):
    """A solid lofted through closed planar profiles, capped by the first and last. Properties: Sections (a
    list, in order, of what make_revolve takes as Profile), Degree (across the sections, default 3), Ruled
    (straight rulings between consecutive sections)."""
    return _make("loft", doc, properties)


def make_sweep(doc=None, **properties):
    """A closed planar profile swept along a path with a rotation-minimising frame. Properties: Profile (as
    make_revolve's), Path (a sketch, wire, edges, (object, subnames) or a Part shape: one tangent-continuous
    chain), Tolerance (mm, where the sweep is not rational; default 1e-6)."""
    return _make("sweep", doc, properties)


def make_interpolate(doc=None, **properties):
    """The B-spline curve through points (ratbez.interpolate, The NURBS Book A9.1). Properties: Source (a list,
    in order, of (object, "VertexN") or (object, ["Vertex1", ...]) picks, or whole objects: a Draft wire or
    B-spline gives its points, any other object its vertices), or Points (a list of vectors) when Source is
    empty; Degree (default 3), Parameterization ("chord", "centripetal" or "uniform"), Closed (periodic
    through the first point), EndTangents with StartTangent and EndTangent."""
    if "Source" in properties:
        links = []
        for value in properties["Source"] or []:
            obj, subs = value if isinstance(value, (tuple, list)) else (value, [])
            links.append((obj, [subs] if isinstance(subs, str) else (list(subs) or [""])))
        properties["Source"] = links
    return _make("interpolate", doc, properties)


# ---------------------------------------------------------------------------------------------------

def is_solid(obj):
    """True when obj is a RatBez solid feature (cylinder, cone, sphere, torus, revolve, extrude, ruled, loft,
    sweep)."""
    return features.is_solid_feature(obj)


def solid_of(obj):
    """The ratbez.Solid of a RatBez solid feature, rebuilt from its current properties, in the object's
    local coordinates (its Placement not applied). Raises ratbez.Error / ValueError on bad input."""
    if not is_solid(obj):
        raise TypeError("'{}' is not a RatBez solid".format(getattr(obj, "Label", obj)))
    return features.proxy_of(obj).build_solid(obj)


def _placement_matrix_rows(placement):
    m = placement.toMatrix()
    return [[m.A11, m.A12, m.A13, m.A14], [m.A21, m.A22, m.A23, m.A24],
            [m.A31, m.A32, m.A33, m.A34], [0.0, 0.0, 0.0, 1.0]]


def safe_label(text):
    """A Label fit for one line of a file or message (text.one_line: control characters escaped)."""
    return text_tools.one_line(text)


def export_openscad(obj, path, tolerance=None, module=None):
    """Write the solid of a RatBez feature to `path` as an OpenSCAD library file (ratbez.export_openscad:
    `module NAME() { polyhedron(...); }` then `NAME();`, a watertight mesh within `tolerance` of the exact
    surfaces; None: the kernel's default). NAME is `module`, else the file's stem made an identifier. A
    non-identity Placement is applied to the solid (on its control points) before tessellating,
    so `use <file>` imports the solid where FreeCAD shows it."""
    solid = solid_of(obj)
    rb = kernel.ratbez()
    placement = obj.Placement
    if not placement.isIdentity():
        solid = solid.transformed(_placement_matrix_rows(placement))
    # The kernel's writer (a new file renamed over the target, the rules of every ratbez export) writes the
    # library file, named after the target's stem; write_text_file then adds the Label in a comment line of
    # its own, escaped, by the same rules.
    rb.export_openscad(solid, path, tolerance, module=module)
    with open(path) as source:
        body = source.read()
    rb.write_text_file(path, "// RatBez '{}' from FreeCAD, its Placement applied\n{}".format(safe_label(obj.Label), body))
    return path


def check_occt(obj):
    """ratbez.occt_check of the object's solid in the representation FreeCAD gets (bezier_faces): a dict
    with at least valid, max_deviation, volume and occt_volume."""
    return dict(kernel.ratbez().occt_check(solid_of(obj), bezier_faces=True))


_REPORT_ROWS = (
    ("valid", "BRepCheck valid"), ("closed", "shell closed"), ("max_deviation", "max |ours - OCCT| (mm)"),
    ("max_analytic_deviation", "max distance to the analytic surface (mm)"), ("volume", "volume, exact (mm^3)"),
    ("occt_volume", "volume, OCCT (mm^3)"), ("closed_form_volume", "volume, closed form (mm^3)"),
    ("area", "area, exact (mm^2)"), ("occt_area", "area, OCCT (mm^2)"), ("passed", "passed"),
)


def format_check_report(obj, report):
    """A readable, multi-line text of a check_occt report: each quantity once, none that does not apply."""
    lines = ["RatBez OpenCASCADE check of '{}' ({}):".format(safe_label(obj.Label), obj.Name)]
    width = max(len(title) for _, title in _REPORT_ROWS)
    for key, title in _REPORT_ROWS:
        value = report.get(key)
        if value is None:
            continue
        text = "{:.9g}".format(value) if isinstance(value, float) else ("yes" if value is True else
                                                                       "no" if value is False else str(value))
        lines.append("  {:<{}}  {}".format(title, width, text))
    for failure in report.get("failures") or []:
        lines.append("  FAILED: {}".format(failure))
    return "\n".join(lines) + "\n"


def check_passed(report):
    """Whether a check_occt report says the solid passed (valid, and 'passed' when present)."""
    return bool(report.get("valid", False)) and bool(report.get("passed", True))


def export(objects, filename):
    """File > Export handler for *.scad (registered in Init.py): the first RatBez solid."""
    solids = [o for o in objects if is_solid(o)]
    if not solids:
        App.Console.PrintError("RatBez: select a RatBez solid to export to OpenSCAD\n")
        return
    if len(solids) > 1:
        App.Console.PrintWarning("RatBez: exporting only '{}'; export one solid per file\n".format(
            solids[0].Label))
    try:
        export_openscad(solids[0], filename)
        App.Console.PrintMessage("RatBez: wrote {}\n".format(filename))
    except kernel.error_types() as error:
        App.Console.PrintError("RatBez: export of '{}' failed: {}\n".format(solids[0].Label, error))

"""RatBez: exact rational Bézier / NURBS solids as parametric FreeCAD objects.

Scripting interface (works in freecadcmd, without the GUI):

    import RatBez
    cyl = RatBez.make_cylinder(Radius=2, Height=5)
    rev = RatBez.make_revolve(Profile=sketch, Angle=270)
    loft = RatBez.make_loft(Sections=[bottom, middle, top])
    spline = RatBez.make_interpolate(Source=[(sketch, ["Vertex1", "Vertex3", "Vertex2"])], Closed=True)
    swept = RatBez.make_sweep(Profile=circle, Path=(sketch, ["Edge1", "Edge2"]))
    RatBez.export_openscad(cyl, "/tmp/cyl.scad", tolerance=0.01)
    RatBez.export_openscad([cyl, sphere], "/tmp/parts.scad")   # a library: one module per solid, coloured
    RatBez.export_3mf([cyl, sphere], "/tmp/parts.3mf")          # one 3MF object per solid, named and coloured
    RatBez.export_stl([cyl, sphere], "/tmp/parts.stl")          # binary STL, the solids side by side
    print(RatBez.check_occt(cyl))
    for name, report in RatBez.check_occt_all(part_cut): ...   # any solid: Part, PartDesign, imported STEP

Every make_<thing>(doc=None, **properties) adds a Part::FeaturePython to `doc` (default: the active
document, or a new one), sets the given FreeCAD-style properties, recomputes and returns the object (a
sweep without its Path is not recomputed until the path is linked).
Bad property values do not raise here: the object is marked invalid and the kernel's message goes to
the report view, exactly as when the value is typed into the property editor.
"""


import os
import re
import tempfile
import warnings

import FreeCAD as App
import Part

from ratbez_wb import conversion, curve_tools, features, kernel  # noqa: F401 (curve_tools registers Interpolate)
from ratbez_wb import text as text_tools

__all__ = ["make_bezier_curve", "make_bezier_surface", "make_cylinder", "make_cone", "make_sphere",
           "make_torus", "make_revolve", "make_extrude", "make_ruled", "make_loft", "make_sweep", "make_interpolate",
           "is_solid", "solid_of", "export_openscad", "export_3mf", "export_stl", "exportable", "check_occt", "check_occt_all",
           "format_check_report",
           "check_passed", "safe_label", "export"]

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
    # An object still missing a link it cannot do without (a sweep's Path, picked in its task panel next) is
    # not recomputed: that could only fail. Link it, then recompute.
    if all(getattr(obj, prop) for prop in cls.REQUIRED_LINKS):
        doc.recompute()
    return obj


def _links_of(properties):
    """The profile, section and path links among make_* properties."""
    links = [properties[prop] for prop in _LINK_PROPERTIES if properties.get(prop) is not None]
    return links + [(obj, [s for s in subs if s]) for obj, subs in properties.get("Sections") or []]


def _complete(kind, properties):
    """Defaults that depend on other properties: a revolve's axis is the profile's vertical axis (as for a
    sketch in Sketcher and PartDesign, and following the sketch when it moves) unless one is given: an
    AxisReference (AxisMode Reference) or AxisPoint / AxisDirection (Custom); an extrusion given a Direction
    or a DirectionReference goes along it."""
    if kind == "revolve" and "AxisMode" not in properties:
        if properties.get("AxisReference"):
            properties["AxisMode"] = "Reference"
        elif {"AxisPoint", "AxisDirection"} & set(properties):
            properties["AxisMode"] = "Custom"
        else:
            properties["AxisMode"] = "Vertical"
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
    shape), AxisMode ("Vertical" (default: the profile's vertical axis, as a sketch revolves, following the
    sketch when it moves), "Horizontal", "X", "Y", "Z", "Reference", "Custom"), AxisReference (a straight edge
    or datum line) or AxisPoint and AxisDirection (given, they set the mode), Angle (degrees, in (0, 360]),
    Symmetric, Reversed."""
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
    empty; Degree (default 3, or what fewer points allow: a line through 2, a parabola through 3),
    Parameterization ("chord", "centripetal" or "uniform"), Closed (periodic through the first point),
    EndTangents with StartTangent and EndTangent."""
    if "Source" in properties:
        links = []
        for value in properties["Source"] or []:
            obj, subs = value if isinstance(value, (tuple, list)) else (value, [])
            links.append((obj, [subs] if isinstance(subs, str) else (list(subs) or [""])))
        properties["Source"] = links
    if "Degree" not in properties:
        links = [(obj, subs) for obj, subs in properties.get("Source") or [] if obj is not None]
        try:
            given = curve_tools.source_points(links) if links else properties.get("Points")
        except Exception:  # noqa: BLE001 (a Failure, or FreeCAD's for a missing vertex)
            given = None  # a source without points: the object reports it, as for any bad property
        conditions = (len(given) if given is not None else 4) + (2 if properties.get("EndTangents") else 0)
        if given is not None and len(given) >= 2 and conditions < 4:
            properties["Degree"] = conditions - 1
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


def exportable(obj):
    """Whether `obj` can be offered for export: a RatBez solid feature, or any object whose shape holds a
    solid (the kernel reads it through ratbez.read_brep; what it cannot read yet is refused at export with
    the kernel's reason)."""
    if is_solid(obj):
        return True
    if features.proxy_of(obj) is not None:
        return False  # a RatBez curve or surface
    shape = getattr(obj, "Shape", None)
    return shape is not None and not shape.isNull() and bool(shape.Solids)


def _global_placement(obj):
    """Where the 3D view shows `obj`: its Placement within those of the App::Part containers (and other
    geometry groups) around it."""
    if hasattr(obj, "getGlobalPlacement"):
        return obj.getGlobalPlacement()
    return obj.Placement


def _placed_solid(obj):
    """The ratbez.Solid of a RatBez feature where the 3D view shows it: its Placement and its containers'
    applied (on its control points: exact)."""
    solid = solid_of(obj)
    placement = _global_placement(obj)
    if not placement.isIdentity():
        solid = solid.transformed(_placement_matrix_rows(placement))
    return solid


def _without_path(reason, path):
    """A reader's words about the temporary .brep file `path` said about the object's shape."""
    return reason.replace("'{}': ".format(path), "").replace(path, "its shape")


def _solid_occurrences(shape):
    """The solids of `shape` as the kernel's reader counts them: every occurrence in its compounds (Shape.Solids
    counts a solid placed twice once)."""
    if shape.ShapeType == "Solid":
        return 1
    if shape.ShapeType in ("Compound", "CompSolid"):
        return sum(_solid_occurrences(child) for child in shape.childShapes(False, False))
    return 0


def _read_solids(obj):
    """The solids of another object's shape where the 3D view shows it (its Placement, in its containers'),
    read by the kernel from a .brep of it: every solid where the module reads several (read_brep_all), else
    the one."""
    rb = kernel.ratbez()
    handle, path = tempfile.mkstemp(prefix="ratbez-", suffix=".brep")
    os.close(handle)
    try:
        shape = obj.Shape
        # The shape carries the object's own Placement; the containers' goes on top of it.
        containers = _global_placement(obj).multiply(obj.Placement.inverse()) if hasattr(obj, "Placement") else None
        if containers is not None and not containers.isIdentity():
            shape = shape.copy()
            shape.Placement = containers.multiply(shape.Placement)
        shape.exportBrep(path)
        cannot = "'{}': the ratbez kernel cannot read this solid yet: {}"
        try:
            if not hasattr(rb, "read_brep_all"):
                return [rb.read_brep(path)]
            # The reader leaves out a solid it cannot read when others read (a ReadWarning says which); an export
            # of the object the user picked holds every solid of it, or none.
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", rb.ReadWarning)
                solids = list(rb.read_brep_all(path))
        except rb.Error as error:
            _, reason = kernel.error_parts(error)
            raise ValueError(cannot.format(safe_label(obj.Label), _without_path(reason, path)))
        said = [_without_path(str(w.message), path) for w in caught if issubclass(w.category, rb.ReadWarning)]
        if len(solids) < _solid_occurrences(shape):
            raise ValueError(cannot.format(safe_label(obj.Label), "; ".join(said)))
        for text in said:
            warnings.warn("'{}': {}".format(safe_label(obj.Label), text), rb.ReadWarning)
        return solids
    finally:
        os.remove(path)


def _color_of(obj):
    """The object's ShapeColor with its Transparency as "#rrggbbaa", or None without a view (freecadcmd)."""
    view = getattr(obj, "ViewObject", None)
    color = getattr(view, "ShapeColor", None) if view is not None else None
    if color is None:
        return None
    opacity = 1.0 - max(0.0, min(100.0, float(getattr(view, "Transparency", 0)))) / 100.0
    return "#" + "".join("{:02x}".format(int(round(max(0.0, min(1.0, c)) * 255))) for c in tuple(color[:3]) + (opacity,))


def _identifier(text):
    """`text` made an OpenSCAD identifier (as the kernel makes one of a file's stem): other characters
    become _, a leading digit gets a _ in front."""
    name = re.sub(r"[^A-Za-z0-9_]", "_", text) or "solid"
    return "_" + name if name[0].isdigit() else name


def _named_solids(objects, identifiers):
    """[(name, ratbez.Solid, colour)] of the objects, in order: one per RatBez feature, one per solid of
    another object; names from the Labels (identifiers for OpenSCAD modules when `identifiers`), made
    unique with _2, _3, ..."""
    if not isinstance(objects, (list, tuple)):
        objects = [objects]
    named = []
    for obj in objects:
        if features.proxy_of(obj) is not None and not is_solid(obj):
            raise TypeError("'{}' is not a RatBez solid".format(safe_label(obj.Label)))
        solids = [_placed_solid(obj)] if is_solid(obj) else _read_solids(obj)
        color = _color_of(obj)
        for k, solid in enumerate(solids):
            base = obj.Label if len(solids) == 1 else "{}_{}".format(obj.Label, k + 1)
            named.append((_identifier(base) if identifiers else base, solid, color))
    taken, unique = set(), []
    for name, solid, color in named:
        candidate, count = name, 1
        while candidate in taken:
            count += 1
            candidate = "{}_{}".format(name, count)
        taken.add(candidate)
        unique.append((candidate, solid, color))
    return unique


def _refused_builtin(error, names):
    """The module name of `names` that export_openscad refused as an OpenSCAD built-in, or None."""
    argument, reason = kernel.error_parts(error)
    match = re.fullmatch(r"solids\['(.*)'\]", argument or "")
    if match and "built-in" in reason and match.group(1) in names:
        return match.group(1)
    return None


def export_openscad(objects, path, tolerance=None, module=None, color=True):
    """Write RatBez solids (and other solids the kernel can read) to `path` as an OpenSCAD library file
    (ratbez.export_openscad), a watertight mesh within `tolerance` of the exact surfaces (None: the kernel's
    default). One object: `module NAME() { polyhedron(...); }` then `NAME();`, NAME being `module`, else the
    file's stem made an identifier. A list: one module per solid, named after its Label, and the module NAME
    placing them all. With `color`, each module's body is wrapped in color() of the object's ShapeColor (and
    Transparency). The Placement, within those of the App::Part containers around the object, is applied to the
    solid (on its control points) before tessellating, so `use <file>` imports the solids where FreeCAD shows
    them."""
    rb = kernel.ratbez()
    named = _named_solids(objects, identifiers=True)
    # One object holding several solids (a compound, an imported assembly) is a library too: a module per solid
    # and the placing one, named as the single solid's module would be.
    several = isinstance(objects, (list, tuple)) or len(named) > 1
    if not several:
        name, solid, shape_color = named[0]
        rb.export_openscad(solid, path, tolerance, module=module, color=shape_color if color else None)
        labels = [objects.Label]
    else:
        names = [name for name, _, _ in named]
        while True:
            solids = {name: solid for name, solid, _ in named}
            colors = {name: c for name, _, c in named if c is not None} if color else None
            try:
                rb.export_openscad(solids, path, tolerance, module=module, color=colors or None)
                break
            except rb.Error as error:
                # A Label such as "cube" would shadow OpenSCAD's own cube(): that module gets _solid behind it,
                # as the kernel names a file's stem.
                refused = _refused_builtin(error, names)
                if refused is None:
                    raise
                named = [(n + "_solid" if n == refused else n, s, c) for n, s, c in named]
                names = [n for n, _, _ in named]
        labels = [obj.Label for obj in (objects if isinstance(objects, (list, tuple)) else [objects])]
    # The kernel's writer (a new file renamed over the target, the rules of every ratbez export) writes the
    # library file; write_text_file then adds the Labels in comment lines of their own, escaped, by the same
    # rules.
    with open(path, encoding="utf-8") as source:
        body = source.read()
    header = "".join("// RatBez '{}' from FreeCAD, its Placement applied\n".format(safe_label(label)) for label in labels)
    rb.write_text_file(path, header + body)
    return path


def export_3mf(objects, path, tolerance=None, color=True):
    """Write RatBez solids (and other solids the kernel can read) to `path` as a 3MF file (ratbez.write_3mf):
    one object per solid named after its Label, with the object's ShapeColor (and Transparency) as its
    colour when `color`, each a watertight mesh within `tolerance` of the exact surfaces, Placements
    applied."""
    rb = kernel.ratbez()
    named = _named_solids(objects, identifiers=False)
    if len(named) == 1:
        name, solid, shape_color = named[0]
        rb.write_3mf(solid, path, tolerance, name=name, color=shape_color if color else None)
    else:
        colors = {name: c for name, _, c in named if c is not None} if color else None
        rb.write_3mf({name: solid for name, solid, _ in named}, path, tolerance, color=colors or None)
    return path


def export_stl(objects, path, tolerance=None):
    """Write RatBez solids (and other solids the kernel can read) to `path` as binary STL (ratbez.write_stl): one
    watertight mesh within `tolerance` of the exact surfaces per solid, checked as its readers get it (float32
    coordinates), several solids side by side in one file, Placements applied."""
    rb = kernel.ratbez()
    named = _named_solids(objects, identifiers=False)
    if len(named) == 1:
        rb.write_stl(named[0][1], path, tolerance)
    else:
        rb.write_stl({name: solid for name, solid, _ in named}, path, tolerance)
    return path


def check_occt(obj):
    """ratbez.occt_check of the object's solid: a dict with at least valid, max_deviation, volume and
    occt_volume. A RatBez feature is checked in the representation FreeCAD gets (the natural one); any other
    solid (Part, PartDesign, an imported STEP) as the kernel reads it. An object holding several solids is
    refused: check_occt_all reports each."""
    reports = check_occt_all(obj)
    if len(reports) != 1:
        raise ValueError("'{}' holds {} solids: check_occt_all reports each".format(safe_label(obj.Label),
                                                                                  len(reports)))
    return reports[0][1]


def check_occt_all(obj, progress=None):
    """[(name, report)] of ratbez.occt_check for every solid of the object, in order: the object's Label, or
    Label_1, Label_2, ... when it holds several (a compound, an imported assembly). progress:
    callable(name, fraction), the solid being checked and the fraction done of all of them (as occt_check's, it
    may raise to stop the check)."""
    rb = kernel.ratbez()
    if is_solid(obj):
        named = [(obj.Label, solid_of(obj))]
    elif not exportable(obj):
        raise TypeError("'{}' holds no solid".format(safe_label(obj.Label)))
    else:
        named = [(name, solid) for name, solid, _ in _named_solids(obj, identifiers=False)]
    reports = []
    for index, (name, solid) in enumerate(named):
        told = None if progress is None else (
            lambda fraction: progress(name, (index + fraction) / len(named)))
        reports.append((name, dict(rb.occt_check(solid, progress=told))))
    return reports


_REPORT_ROWS = (
    ("valid", "BRepCheck valid"), ("closed", "shell closed"), ("max_deviation", "max |ours - OCCT| (mm)"),
    ("max_analytic_deviation", "max distance to the analytic surface (mm)"), ("volume", "volume, exact (mm^3)"),
    ("occt_volume", "volume, OCCT (mm^3)"), ("closed_form_volume", "volume, closed form (mm^3)"),
    ("area", "area, exact (mm^2)"), ("occt_area", "area, OCCT (mm^2)"), ("bop_clean", "BOP check clean"),
    ("self_intersections", "self-intersections (BOP check)"), ("small_edges", "small edges (BOP check)"),
    ("passed", "passed"),
)


def format_check_report(obj, report, name=None):
    """A readable, multi-line text of a check_occt report: each quantity once, none that does not apply.
    `name`: the solid's name among several of the object (check_occt_all)."""
    title = safe_label(obj.Label) if name is None or name == obj.Label else "{}' solid '{}".format(
        safe_label(obj.Label), safe_label(name))
    lines = ["RatBez OpenCASCADE check of '{}' ({}):".format(title, obj.Name)]
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
    """File > Export handler for *.scad and *.3mf (registered in Init.py): every exportable solid among the
    objects, in one file (one module or 3MF object each)."""
    solids = [o for o in objects if exportable(o)]
    if not solids:
        App.Console.PrintError("RatBez: select a RatBez solid (or another solid) to export\n")
        return
    try:
        if filename.lower().endswith(".3mf"):
            export_3mf(solids if len(solids) > 1 else solids[0], filename)
        else:
            export_openscad(solids if len(solids) > 1 else solids[0], filename)
        App.Console.PrintMessage("RatBez: wrote {}\n".format(filename))
    except kernel.error_types() + (OSError,) as error:
        App.Console.PrintError("RatBez: export to {} failed: {}\n".format(filename, text_tools.one_line(error)))

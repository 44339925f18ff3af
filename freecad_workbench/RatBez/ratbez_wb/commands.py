"""The GUI commands RatBez_*.

Creating commands go through Gui.doCommand, so what they do appears in the Python console and is
recorded by the macro recorder, as with FreeCAD's own Part primitives, and then open the new object's
task panel (setEdit): FreeCAD keeps the command's transaction open while the edit lasts, so OK commits
it as one undo step and Cancel removes the object. Revolve and Extrude are enabled only for a selection
they can use, check it before they create anything, and say in one line why they refuse it.
"""

import FreeCAD as App
import FreeCADGui as Gui
import Part

from . import conversion, features, kernel, resources
from .errors import Failure
from .i18n import QT_TRANSLATE_NOOP, translate
from .text import one_line


def _selected_profile():
    """(object, sub-element names) of a selection that can be a profile, or None. Structural only (cheap
    enough for IsActive): one object, not a RatBez feature; one face, or edges; a whole object that is
    a profile (no solid, at most one face)."""
    selection = Gui.Selection.getSelectionEx()
    if len(selection) != 1:
        return None
    sel = selection[0]
    obj = sel.Object
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull() or not shape.Edges:
        return None
    subs = [s for s in sel.SubElementNames if s]
    if subs:
        faces = [s for s in subs if s.startswith("Face")]
        edges = [s for s in subs if s.startswith("Edge")]
        if len(faces) + len(edges) != len(subs) or (faces and (edges or len(faces) > 1)):
            return None
    elif features.proxy_of(obj) is not None or not conversion.is_whole_profile_object((obj, [])):
        return None
    elif len(shape.Faces) > 1:
        return None
    return obj, subs


def _closed(link):
    """Whether the linked face or edges are closed loops (what Extrude needs)."""
    obj, subs = link
    shape = obj.Shape
    elements = [shape.getElement(s) for s in subs] if subs else ([shape] if shape.Faces else shape.Edges)
    if len(elements) == 1 and elements[0].ShapeType in ("Face", "Solid", "Shell", "Compound") and elements[0].Faces:
        return True
    edges = [e for element in elements for e in element.Edges]
    try:
        return all(Part.Wire(chain).isClosed() for chain in Part.sortEdges(edges))
    except Exception:  # Part.OCCError for edges that do not make a wire
        return False


class _CreateCommand:
    kind = ""
    menu = ""
    tooltip = ""

    def GetResources(self):
        name = self.command_name()
        return {"Pixmap": resources.icon(name),
                "MenuText": QT_TRANSLATE_NOOP(name, self.menu),
                "ToolTip": QT_TRANSLATE_NOOP(name, self.tooltip)}

    @classmethod
    def command_name(cls):
        return "RatBez_" + "".join(part.capitalize() for part in cls.kind.split("_"))

    def IsActive(self):
        return App.ActiveDocument is not None

    def arguments(self):
        return ""

    def Activated(self):
        # The creation and the task panel session are one transaction: the panel's OK commits it, Cancel
        # aborts it (removing the object). FreeCAD keeps a transaction open while an edit it started lasts.
        App.ActiveDocument.openTransaction(translate("Create {}").format(translate(self.menu)))
        Gui.addModule("RatBez")
        Gui.doCommand("obj = RatBez.make_{}(App.ActiveDocument{})".format(self.kind, self.arguments()))
        Gui.doCommand("Gui.ActiveDocument.setEdit(obj.Name, 0)")


class BezierCurveCommand(_CreateCommand):
    kind = "bezier_curve"
    menu = "Bézier curve"
    tooltip = "Create a rational Bézier curve; its poles and weights are edited in a table"


class BezierSurfaceCommand(_CreateCommand):
    kind = "bezier_surface"
    menu = "Bézier surface"
    tooltip = "Create a rational Bézier surface patch; its degrees, poles and weights are edited in a table"


class CylinderCommand(_CreateCommand):
    kind = "cylinder"
    menu = "Cylinder"
    tooltip = "Create an exact rational cylinder solid"


class ConeCommand(_CreateCommand):
    kind = "cone"
    menu = "Cone"
    tooltip = "Create an exact rational (truncated) cone solid"


class SphereCommand(_CreateCommand):
    kind = "sphere"
    menu = "Sphere"
    tooltip = "Create an exact rational sphere solid"


class TorusCommand(_CreateCommand):
    kind = "torus"
    menu = "Torus"
    tooltip = "Create an exact rational torus solid"


class _ProfileCommand(_CreateCommand):
    def IsActive(self):
        return App.ActiveDocument is not None and self.usable(_selected_profile())

    def usable(self, link):
        return link is not None

    def refusal(self, link):
        """Why the kernel cannot use the profile (in property words), or None."""
        try:
            profile = conversion.resolve_profile(link)
            self.check(link, profile)
        except Failure as failure:
            return str(failure)
        except kernel.error_types() as error:
            return str(error)
        return None

    def check(self, link, profile):
        pass

    def Activated(self):
        link = _selected_profile()
        reason = translate("select a sketch, a wire, edges or one face first") if link is None else self.refusal(link)
        if reason:
            App.Console.PrintError("RatBez: {}: {}\n".format(translate(self.menu), one_line(reason)))
            return
        obj, subs = link
        self.profile_argument = ", Profile=(App.ActiveDocument.getObject({!r}), {!r})".format(obj.Name, subs)
        super().Activated()

    def arguments(self):
        return self.profile_argument


class RevolveCommand(_ProfileCommand):
    kind = "revolve"
    menu = "Revolve"
    tooltip = ("Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile's "
               "vertical axis to start with, as a sketch's V axis), the angle and a symmetric revolution are "
               "set in the task panel")

    def check(self, link, profile):
        features.require_revolvable(profile)


class ExtrudeCommand(_ProfileCommand):
    kind = "extrude"
    menu = "Extrude"
    tooltip = ("Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner "
               "loops become holes. Direction (the profile's normal to start with), distance, reversed and "
               "symmetric are set in the task panel")

    def usable(self, link):
        return link is not None and _closed(link)

    def check(self, link, profile):
        features.require_extrudable(profile)


class ExportOpenSCADCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_ExportOpenSCAD"),
                "MenuText": QT_TRANSLATE_NOOP("RatBez_ExportOpenSCAD", "Export to OpenSCAD..."),
                "ToolTip": QT_TRANSLATE_NOOP("RatBez_ExportOpenSCAD",
                                             "Write the selected RatBez solid as an OpenSCAD polyhedron (.scad), "
                                             "a watertight mesh within a chosen tolerance of the exact surfaces")}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_solids()) == 1

    def Activated(self):
        import RatBez
        from . import dialogs
        solids = _selected_solids()
        if len(solids) != 1:
            App.Console.PrintError(translate("RatBez: select one RatBez solid to export\n"))
            return
        obj = solids[0]
        options = dialogs.ask_export_options(obj)
        if options is None:
            return
        path, tolerance = options
        try:
            RatBez.export_openscad(obj, path, tolerance)
        except kernel.error_types() + (OSError,) as error:
            App.Console.PrintError(translate("RatBez: export of '{}' failed: {}\n").format(
                one_line(obj.Label), one_line(error)))
            return
        App.Console.PrintMessage(translate("RatBez: wrote '{}' to {}\n").format(one_line(obj.Label), path))


class CheckOCCTCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_CheckOCCT"),
                "MenuText": QT_TRANSLATE_NOOP("RatBez_CheckOCCT", "Check against OpenCASCADE"),
                "ToolTip": QT_TRANSLATE_NOOP("RatBez_CheckOCCT",
                                             "Check the selected RatBez solids against OpenCASCADE (B-rep "
                                             "validity, deviation of the evaluations, volumes) and print the "
                                             "report to the report view")}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_solids()) > 0

    def Activated(self):
        import RatBez
        for obj in _selected_solids():
            try:
                report = RatBez.check_occt(obj)
            except kernel.error_types() as error:
                App.Console.PrintError(translate("RatBez: cannot check '{}': {}\n").format(
                    one_line(obj.Label), one_line(error)))
                continue
            text = RatBez.format_check_report(obj, report)
            if RatBez.check_passed(report):
                App.Console.PrintMessage(text)
            else:
                App.Console.PrintWarning(text)


def _selected_solids():
    return [o for o in Gui.Selection.getSelection() if features.is_solid_feature(o)]


CREATE_COMMANDS = [BezierCurveCommand, BezierSurfaceCommand, CylinderCommand, ConeCommand,
                   SphereCommand, TorusCommand, RevolveCommand, ExtrudeCommand]
CREATE_COMMAND_NAMES = [c.command_name() for c in CREATE_COMMANDS]
TOOL_COMMAND_NAMES = ["RatBez_ExportOpenSCAD", "RatBez_CheckOCCT"]

_registered = False


def register():
    """Add every RatBez command to FreeCAD (once)."""
    global _registered
    if _registered:
        return
    for cls in CREATE_COMMANDS:
        Gui.addCommand(cls.command_name(), cls())
    Gui.addCommand("RatBez_ExportOpenSCAD", ExportOpenSCADCommand())
    Gui.addCommand("RatBez_CheckOCCT", CheckOCCTCommand())
    _registered = True

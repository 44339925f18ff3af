"""The GUI commands RatBez_*.

Creation commands go through Gui.doCommand, so what they do appears in the Python console and is
recorded by the macro recorder, as with FreeCAD's own Part primitives.
"""

import FreeCAD as App
import FreeCADGui as Gui

from . import features, kernel, resources


def _selected_profile():
    """(object, sub-element names) of the single selected edge(s) / wire / face / sketch, or None."""
    selection = Gui.Selection.getSelectionEx()
    if len(selection) != 1:
        return None
    sel = selection[0]
    obj = sel.Object
    if features.proxy_of(obj) is not None:
        return None
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull() or not shape.Edges:
        return None
    subs = [s for s in sel.SubElementNames if s]
    if any(not (s.startswith("Edge") or s.startswith("Face")) for s in subs):
        return None
    return obj, subs


def _selected_solids():
    return [o for o in Gui.Selection.getSelection() if features.is_solid_feature(o)]


def _run(lines, transaction):
    doc = App.ActiveDocument
    doc.openTransaction(transaction)
    try:
        Gui.addModule("RatBez")
        for line in lines:
            Gui.doCommand(line)
    finally:
        doc.commitTransaction()


class _CreateCommand:
    kind = ""
    menu = ""
    tooltip = ""

    def GetResources(self):
        return {"Pixmap": resources.icon(self.command_name()),
                "MenuText": self.menu,
                "ToolTip": self.tooltip}

    @classmethod
    def command_name(cls):
        return "RatBez_" + "".join(part.capitalize() for part in cls.kind.split("_"))

    def IsActive(self):
        return App.ActiveDocument is not None

    def Activated(self):
        _run(["RatBez.make_{}(App.ActiveDocument)".format(self.kind),
              "Gui.SendMsgToActiveView('ViewFit')"], "Create RatBez " + self.menu)


class BezierCurveCommand(_CreateCommand):
    kind = "bezier_curve"
    menu = "Bézier curve"
    tooltip = "Create a rational Bézier curve (edit its Poles and Weights in the property editor)"


class BezierSurfaceCommand(_CreateCommand):
    kind = "bezier_surface"
    menu = "Bézier surface"
    tooltip = "Create a rational Bézier surface patch (DegreeU, DegreeV, Poles, Weights)"


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
        return App.ActiveDocument is not None and _selected_profile() is not None

    def extra_arguments(self, obj, subs):
        return ""

    def Activated(self):
        profile = _selected_profile()
        if profile is None:
            App.Console.PrintError("RatBez: select an edge, wire, face or sketch first\n")
            return
        obj, subs = profile
        link = "(App.ActiveDocument.getObject({!r}), {!r})".format(obj.Name, subs)
        _run(["RatBez.make_{}(App.ActiveDocument, Profile={}{})".format(
            self.kind, link, self.extra_arguments(obj, subs)),
              "Gui.SendMsgToActiveView('ViewFit')"], "Create RatBez " + self.menu)


class RevolveCommand(_ProfileCommand):
    kind = "revolve"
    menu = "Revolve"
    tooltip = ("Revolve the selected sketch, wire or edges about an axis into an exact solid "
               "(select the profile first; set AxisPoint, AxisDirection and Angle afterwards)")

    def extra_arguments(self, obj, subs):
        from . import conversion
        point, direction = conversion.default_revolve_axis((obj, subs))
        return ", AxisPoint=App.Vector({!r}, {!r}, {!r}), AxisDirection=App.Vector({!r}, {!r}, {!r})".format(
            point.x, point.y, point.z, direction.x, direction.y, direction.z)


class ExtrudeCommand(_ProfileCommand):
    kind = "extrude"
    menu = "Extrude"
    tooltip = ("Extrude the selected closed planar sketch, wire or face into an exact prism "
               "(select the profile first; set Direction and Distance afterwards)")


class ExportOpenSCADCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_ExportOpenSCAD"),
                "MenuText": "Export to OpenSCAD...",
                "ToolTip": "Write the selected RatBez solid as an OpenSCAD polyhedron (.scad), "
                           "a watertight mesh within a chosen tolerance of the exact surfaces"}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_solids()) == 1

    def Activated(self):
        import RatBez
        from . import dialogs
        solids = _selected_solids()
        if len(solids) != 1:
            App.Console.PrintError("RatBez: select one RatBez solid to export\n")
            return
        obj = solids[0]
        options = dialogs.ask_export_options(obj)
        if options is None:
            return
        path, tolerance = options
        try:
            RatBez.export_openscad(obj, path, tolerance)
        except kernel.error_types() + (OSError,) as error:
            App.Console.PrintError("RatBez: export of '{}' failed: {}\n".format(obj.Label, error))
            return
        App.Console.PrintMessage("RatBez: wrote '{}' to {}\n".format(obj.Label, path))


class CheckOCCTCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_CheckOCCT"),
                "MenuText": "Check against OpenCASCADE",
                "ToolTip": "Check the selected RatBez solids against OpenCASCADE (B-rep validity, "
                           "deviation of the evaluations, volumes) and print the report to the "
                           "report view"}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_solids()) > 0

    def Activated(self):
        import RatBez
        for obj in _selected_solids():
            try:
                report = RatBez.check_occt(obj)
            except kernel.error_types() as error:
                App.Console.PrintError("RatBez: cannot check '{}': {}\n".format(obj.Label, error))
                continue
            text = RatBez.format_check_report(obj, report)
            if RatBez.check_passed(report):
                App.Console.PrintMessage(text)
            else:
                App.Console.PrintWarning(text)


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

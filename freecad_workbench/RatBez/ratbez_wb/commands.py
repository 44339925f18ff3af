"""The GUI commands RatBez_*.

Creating commands go through Gui.doCommand, so what they do appears in the Python console and is
recorded by the macro recorder, as with FreeCAD's own Part primitives, and then open the new object's
task panel (setEdit): FreeCAD keeps the command's transaction open while the edit lasts, so OK commits
it as one undo step and Cancel removes the object. Revolve, Extrude, Ruled, Loft and Sweep are enabled only
for a selection they can use, check it before they create anything, and say in one line why they refuse it.
While a task panel is open, the creating commands are disabled (as Part's Revolve, Extrude, Loft, Sweep and
Primitives are): a second command must not replace the open panel and leave its object behind.
"""

import contextlib

import FreeCAD as App
import FreeCADGui as Gui
import Part

from . import conversion, features, kernel, resources
from .errors import Failure
from .i18n import QT_TRANSLATE_NOOP, translate
from .text import one_line


def _selected_links():
    """The selection as profile links, in selection order, or None where some of it cannot be a profile or
    path. Structural only (cheap enough for IsActive): no RatBez feature; of an object, each selected face
    is one link and its selected edges together one (not both); a whole object only when it is a profile
    (no solid, at most one face)."""
    links = []
    for sel in Gui.Selection.getSelectionEx():
        obj = sel.Object
        shape = getattr(obj, "Shape", None)
        if shape is None or shape.isNull() or not shape.Edges:
            return None
        subs = [s for s in sel.SubElementNames if s]
        if subs:
            faces = [s for s in subs if s.startswith("Face")]
            edges = [s for s in subs if s.startswith("Edge")]
            if len(faces) + len(edges) != len(subs) or (faces and edges):
                return None
            links.extend([(obj, [f]) for f in faces] if faces else [(obj, edges)])
        elif features.proxy_of(obj) is not None or not conversion.is_whole_profile_object((obj, [])):
            return None
        elif len(shape.Faces) > 1:
            return None
        else:
            links.append((obj, []))
    return links


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
        return App.ActiveDocument is not None and not Gui.Control.activeDialog()

    def arguments(self):
        return ""

    def refused_for_open_dialog(self):
        """True (and one line in the report view) when a task panel is open: run from the console or a macro,
        the command does nothing rather than replace it."""
        if not Gui.Control.activeDialog():
            return False
        App.Console.PrintError("RatBez: {}: {}\n".format(translate(self.menu), translate("close the open task panel first")))
        return True

    def Activated(self):
        if self.refused_for_open_dialog():
            return
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
    """A command built on selected profiles (and a path): enabled only for a selection it can use, which it
    checks before it creates anything, saying in one line why it refuses it."""

    hint = QT_TRANSLATE_NOOP("RatBez", "select a sketch, a wire, edges or one face first")

    def IsActive(self):
        return App.ActiveDocument is not None and not Gui.Control.activeDialog() and self.roles() is not None

    def roles(self):
        """[(property, link), ...] the selection gives, or None when it does not fit."""
        links = _selected_links()
        return None if links is None else self.assign(links)

    def assign(self, links):
        return [("Profile", links[0])] if len(links) == 1 and self.usable(links[0]) else None

    def usable(self, link):
        return True

    def refusal(self, roles):
        """Why the kernel cannot use the selection (in property words), or None."""
        try:
            for prop, link in roles:
                if prop == "Path":
                    conversion.resolve_path(link)
                else:
                    self.check(link, conversion.resolve_profile(link, prop), prop)
        except Failure as failure:
            return str(failure)
        except kernel.error_types() as error:
            return str(error)
        return None

    def check(self, link, profile, prop):
        pass

    def Activated(self):
        if self.refused_for_open_dialog():
            return
        roles = self.roles()
        reason = translate(self.hint) if roles is None else self.refusal(roles)
        if reason:
            App.Console.PrintError("RatBez: {}: {}\n".format(translate(self.menu), one_line(reason)))
            return
        code = {}
        for prop, (obj, subs) in roles:
            code.setdefault(prop, []).append("(App.ActiveDocument.getObject({!r}), {!r})".format(obj.Name, subs))
        self.link_arguments = "".join(
            ", {}=[{}]".format(prop, ", ".join(values)) if prop == "Sections" else ", {}={}".format(prop, values[0])
            for prop, values in code.items())
        super().Activated()

    def arguments(self):
        return self.link_arguments


class RevolveCommand(_ProfileCommand):
    kind = "revolve"
    menu = "Revolve"
    tooltip = ("Revolve the selected sketch, wire, edges or face into an exact solid; the axis (the profile's "
               "vertical axis to start with, as a sketch's V axis), the angle and a symmetric revolution are "
               "set in the task panel")

    def check(self, link, profile, prop):
        features.require_revolvable(profile)


class ExtrudeCommand(_ProfileCommand):
    kind = "extrude"
    menu = "Extrude"
    tooltip = ("Extrude the selected closed planar sketch, wire, edges or face into an exact prism; inner "
               "loops become holes. Direction (the profile's normal to start with), distance, reversed and "
               "symmetric are set in the task panel")

    def usable(self, link):
        return _closed(link)

    def check(self, link, profile, prop):
        features.require_extrudable(profile)


class _CappedCommand(_ProfileCommand):
    """Ruled, Loft and Sweep: solids capped by their closed planar profiles, which have no holes."""

    def check(self, link, profile, prop):
        features.require_one_loop(profile, prop)


class RuledCommand(_CappedCommand):
    kind = "ruled"
    menu = "Ruled solid"
    tooltip = ("Join the two selected closed planar profiles (sketches, wires, edges or faces without holes) by "
               "straight rulings into an exact solid capped by them; the profiles can be changed in the task "
               "panel")
    hint = QT_TRANSLATE_NOOP("RatBez", "select two closed planar profiles first")

    def assign(self, links):
        if len(links) != 2 or not all(_closed(link) for link in links):
            return None
        return [("Profile1", links[0]), ("Profile2", links[1])]


class LoftCommand(_CappedCommand):
    kind = "loft"
    menu = "Loft"
    tooltip = ("Loft an exact solid through the selected closed planar profiles, in the order selected, passing "
               "through each exactly and capped by the first and last; the sections, their order, the degree "
               "across them and ruled lofting are set in the task panel")
    hint = QT_TRANSLATE_NOOP("RatBez", "select at least two closed planar profiles, in order, first")

    def assign(self, links):
        if len(links) < 2 or not all(_closed(link) for link in links):
            return None
        return [("Sections", link) for link in links]


class SweepCommand(_CappedCommand):
    kind = "sweep"
    menu = "Sweep"
    tooltip = ("Sweep the selected closed planar profile along a path (selected second, or picked in the task "
               "panel) into a solid: exact along straight lines and circular arcs, within a tolerance "
               "elsewhere; the profile keeps its attitude to the path (rotation-minimising frame)")
    hint = QT_TRANSLATE_NOOP("RatBez",
                             "select a closed planar profile first (and then the path, or pick it in the task panel)")

    def assign(self, links):
        if not 1 <= len(links) <= 2 or not _closed(links[0]):
            return None
        return [("Profile", links[0])] + [("Path", link) for link in links[1:]]


class ExportOpenSCADCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_ExportOpenSCAD"),
                "MenuText": QT_TRANSLATE_NOOP("RatBez_ExportOpenSCAD", "Export to OpenSCAD or 3MF..."),
                "ToolTip": QT_TRANSLATE_NOOP("RatBez_ExportOpenSCAD",
                                             "Write the selected solids as one OpenSCAD library (.scad: a module "
                                             "per solid in its colour, and one placing them all) or one 3MF file "
                                             "(an object per solid, named and coloured): watertight meshes within "
                                             "a chosen tolerance of the exact surfaces")}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_exportable()) > 0

    def Activated(self):
        import RatBez
        from . import dialogs
        objects = _selected_exportable()
        if not objects:
            App.Console.PrintError(translate("RatBez: select the solids to export\n"))
            return
        options = dialogs.ask_export_options(objects)
        if options is None:
            return
        path, tolerance = options
        target = objects if len(objects) > 1 else objects[0]
        labels = ", ".join("'{}'".format(one_line(o.Label)) for o in objects)
        try:
            if path.lower().endswith(".3mf"):
                RatBez.export_3mf(target, path, tolerance)
            elif path.lower().endswith(".stl"):
                RatBez.export_stl(target, path, tolerance)
            else:
                RatBez.export_openscad(target, path, tolerance)
        except kernel.error_types() + (OSError,) as error:
            App.Console.PrintError(translate("RatBez: export of {} failed: {}\n").format(labels, one_line(error)))
            return
        App.Console.PrintMessage(translate("RatBez: wrote {} to {}\n").format(labels, path))


class CheckOCCTCommand:
    def GetResources(self):
        return {"Pixmap": resources.icon("RatBez_CheckOCCT"),
                "MenuText": QT_TRANSLATE_NOOP("RatBez_CheckOCCT", "Check against OpenCASCADE"),
                "ToolTip": QT_TRANSLATE_NOOP("RatBez_CheckOCCT",
                                             "Check the selected solids (RatBez, Part, PartDesign, imported) "
                                             "against OpenCASCADE: B-rep validity, deviation of the "
                                             "evaluations, volumes and areas; the report goes to the report "
                                             "view")}

    def IsActive(self):
        return App.ActiveDocument is not None and len(_selected_exportable()) > 0

    def Activated(self):
        import RatBez
        for obj in _selected_exportable():
            label = one_line(obj.Label)
            try:
                with _busy(translate("Checking '{}' against OpenCASCADE...").format(label)) as tell:
                    def progress(name, fraction):
                        # The solid's name only where the object holds several (Label_1, Label_2, ...).
                        tell(fraction, "" if name == obj.Label else one_line(name))
                    reports = RatBez.check_occt_all(obj, progress)
            except _Stopped:
                App.Console.PrintWarning(translate("RatBez: the check of '{}' was stopped\n").format(label))
                return  # the user stops the command, not only this object's check
            except kernel.error_types() as error:
                App.Console.PrintError(translate("RatBez: cannot check '{}': {}\n").format(label, one_line(error)))
                continue
            if not RatBez.is_solid(obj):
                # Another object's shape is read by the kernel (as for an export) and that solid is checked: it
                # can pass where FreeCAD's own shape has faults.
                App.Console.PrintMessage(translate(
                    "Checked: RatBez's reading of '{}' (the solid RatBez exports and hands back), not FreeCAD's "
                    "shape itself; Part > Check geometry checks that.\n").format(label))
            for name, report in reports:
                text = RatBez.format_check_report(obj, report, name)
                if RatBez.check_passed(report):
                    App.Console.PrintMessage(text)
                else:
                    App.Console.PrintWarning(text)


class _Stopped(Exception):
    """The user stopped a long call from its progress bar (Esc, then Yes)."""


@contextlib.contextmanager
def _busy(message):
    """While a long call runs in the GUI thread (a large part's check takes half a minute): FreeCAD's own progress
    bar, the one its STEP import and mesh tools show, with its wait cursor and its Esc key, which asks "Do you
    really want to abort the operation?"; and `message` in the status bar. Yields tell(fraction, detail), which
    shows them and raises _Stopped once the user has stopped the call. All of it goes when the call ends,
    however it ends."""
    from PySide import QtCore, QtGui
    bar = Gui.getMainWindow().statusBar()
    indicator = App.Base.ProgressIndicator()
    steps = 100
    done = 0

    def tell(fraction=0.0, detail=""):
        nonlocal done
        text = translate("{} (Esc stops it)").format(" ".join(part for part in (message, detail) if part))
        if text != bar.currentMessage():
            # No repaint here: FreeCAD's bar lets the events through (this one too) every 0.1 s, and a repaint
            # per report (hundreds in a BOP analysis) tripled the check's time.
            bar.showMessage(text)
        try:
            # Each step lets FreeCAD's bar handle the events (Esc among them) and ask whether to stop.
            while done < min(steps, int(fraction * steps)):
                done += 1
                indicator.next(True)
        except RuntimeError:  # FreeCAD's "abort progress indicator": the user said Yes
            raise _Stopped() from None

    indicator.start(message, steps)
    try:
        # The cursor shows, and the report view's last lines reach the status bar before the message, not over it.
        QtGui.QApplication.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
        tell()
        bar.repaint()  # once, now: the first report may be seconds away
        yield tell
    finally:
        indicator.stop()
        bar.clearMessage()


def _selected_exportable():
    """The selected objects that can be exported, in selection order: RatBez solids and other solids."""
    import RatBez
    return [o for o in Gui.Selection.getSelection() if RatBez.exportable(o)]

from .interpolate_command import InterpolateCommand  # noqa: E402 (it builds on _CreateCommand above)



CREATE_COMMANDS = [BezierCurveCommand, BezierSurfaceCommand, CylinderCommand, ConeCommand,
                   SphereCommand, TorusCommand, RevolveCommand, ExtrudeCommand, RuledCommand, LoftCommand,
                   SweepCommand, InterpolateCommand]
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

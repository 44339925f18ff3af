"""GUI smoke test of the RatBez workbench, run as `xvfb-run ... freecad test_gui.py` by run_freecad.py.

Activates the workbench, checks the commands' IsActive rules, runs every command on a fresh document
(selecting what Revolve, Extrude, Export and Check need first), saves a screenshot of the 3D view to
$RATBEZ_TEST_OUT/ratbez_gui.png, checks it is not blank, and checks that no Python exception reached
the report view. A watchdog ends FreeCAD if anything hangs (a modal dialog, a crash in the loop).
"""

import math
import os
import sys
import threading

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

import FreeCAD as App  # noqa: E402
import FreeCADGui as Gui  # noqa: E402
import Part  # noqa: E402
from PySide import QtCore, QtGui  # noqa: E402

from harness import Suite, check, say  # noqa: E402

OUT = os.environ.get("RATBEZ_TEST_OUT", "/tmp")
SCREENSHOT = os.path.join(OUT, "ratbez_gui.png")
V = App.Vector
PI = math.pi

watchdog = threading.Timer(240, lambda: (say("RATBEZ_TEST_FAILED: watchdog fired"), os._exit(3)))
watchdog.daemon = True
watchdog.start()

# Python errors and output into the report view, so that they can be read back.
_output_params = App.ParamGet("User parameter:BaseApp/Preferences/OutputWindow")
_output_params.SetBool("RedirectPythonErrors", True)
_output_params.SetBool("RedirectPythonOutput", True)
_output_params.SetBool("checkShowReportViewOnError", False)

suite = Suite()
CREATE = ["RatBez_BezierCurve", "RatBez_BezierSurface", "RatBez_Cylinder", "RatBez_Cone",
          "RatBez_Sphere", "RatBez_Torus"]
ALL = CREATE + ["RatBez_Revolve", "RatBez_Extrude", "RatBez_ExportOpenSCAD", "RatBez_CheckOCCT"]


def report_text():
    window = Gui.getMainWindow()
    texts = [w.toPlainText() for w in window.findChildren(QtGui.QTextEdit)
             if "report" in (w.objectName() + w.windowTitle()).lower()]
    return "\n".join(texts)


def report_widget_found():
    return any("report" in (w.objectName() + w.windowTitle()).lower()
               for w in Gui.getMainWindow().findChildren(QtGui.QTextEdit))


def is_active(name):
    command = Gui.Command.get(name)
    check(command is not None, name + " not registered")
    return command.isActive()


def process_events():
    for _ in range(5):
        QtGui.QApplication.processEvents()


def run(name):
    Gui.runCommand(name)
    process_events()


@suite.test
def test_workbench_activates_and_registers_commands():
    Gui.activateWorkbench("RatBezWorkbench")
    process_events()
    check(Gui.activeWorkbench().MenuText == "RatBez", "RatBez workbench active")
    for name in ALL:
        check(Gui.Command.get(name) is not None, name + " not registered")
    check(report_widget_found(), "report view widget not found")
    for name in list(App.listDocuments()):
        App.closeDocument(name)
    process_events()
    for name in ALL:
        check(not is_active(name), name + " active without a document")


@suite.test
def test_every_command_on_a_fresh_document():
    doc = App.newDocument("RatBezGui")
    process_events()
    for name in CREATE:
        check(is_active(name), name + " inactive with a document")
    for name in ("RatBez_Revolve", "RatBez_Extrude", "RatBez_ExportOpenSCAD", "RatBez_CheckOCCT"):
        check(not is_active(name), name + " active with nothing selected")

    spacing = 24.0
    for index, name in enumerate(CREATE):
        before = set(o.Name for o in doc.Objects)
        run(name)
        created = [o for o in doc.Objects if o.Name not in before]
        check(len(created) == 1, "{} created {} objects".format(name, len(created)))
        obj = created[0]
        check(obj.isValid() and obj.Shape.isValid(), name + " made an invalid object")
        check(obj.ViewObject.Proxy is not None, name + ": no view provider proxy")
        obj.Placement = App.Placement(V(spacing * (index % 3), -spacing * (index // 3), 0), App.Rotation())
    doc.recompute()

    # A profile in the XZ plane, revolved (the command picks the Z axis: it lies in the sketch plane).
    sketch = doc.addObject("Sketcher::SketchObject", "RevolveProfile")
    sketch.Placement = App.Placement(V(0, 2 * spacing, 0), App.Rotation(V(1, 0, 0), 90))
    sketch.addGeometry(Part.LineSegment(V(2, 0, 0), V(6, 0, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(6, 3, 0), V(0, 0, 1), 3), -PI / 2, PI / 2))
    sketch.addGeometry(Part.LineSegment(V(6, 6, 0), V(2, 6, 0)))
    sketch.addGeometry(Part.LineSegment(V(2, 6, 0), V(2, 0, 0)))
    circle = doc.addObject("Sketcher::SketchObject", "ExtrudeProfile")
    circle.Placement = App.Placement(V(spacing, 2 * spacing, 0), App.Rotation())
    circle.addGeometry(Part.Circle(V(0, 0, 0), V(0, 0, 1), 4))
    doc.recompute()

    for name, profile in (("RatBez_Revolve", sketch), ("RatBez_Extrude", circle)):
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(profile)
        process_events()
        check(is_active(name), name + " inactive with a sketch selected")
        before = set(o.Name for o in doc.Objects)
        run(name)
        created = [o for o in doc.Objects if o.Name not in before]
        check(len(created) == 1, "{} created {} objects".format(name, len(created)))
        obj = created[0]
        check(obj.isValid() and obj.Shape.isValid() and obj.Shape.isClosed(), name + " made a bad solid")
        check(obj.Profile[0] == profile, name + ": profile not linked")
        check(not profile.ViewObject.Visibility, name + ": profile still shown")
    revolve = doc.getObject("Revolve")
    check(abs(revolve.AxisPoint.y - 2 * spacing) < 1e-9 and abs(revolve.AxisDirection.z - 1) < 1e-9,
          "Revolve's default axis is the Z axis through the sketch origin")

    # A profile is not a valid selection for Export/Check; a RatBez solid is, and not for Revolve.
    check(not is_active("RatBez_ExportOpenSCAD"), "Export active with a sketch selected")
    cylinder = doc.getObject("Cylinder")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(cylinder)
    process_events()
    for name in ("RatBez_ExportOpenSCAD", "RatBez_CheckOCCT"):
        check(is_active(name), name + " inactive with a RatBez solid selected")
    check(not is_active("RatBez_Revolve"), "Revolve active with a RatBez solid selected")

    run("RatBez_CheckOCCT")
    check("OpenCASCADE check of 'Cylinder'" in report_text(), "check report not in the report view")

    from ratbez_wb import dialogs
    path = os.path.join(OUT, "ratbez_gui_cylinder.scad")
    if os.path.exists(path):
        os.remove(path)
    asked = []
    original = dialogs.ask_export_options
    dialogs.ask_export_options = lambda obj: (asked.append(obj.Name), (path, 0.05))[1]
    try:
        run("RatBez_ExportOpenSCAD")
    finally:
        dialogs.ask_export_options = original
    check(asked == ["Cylinder"], "export dialog not asked for the cylinder: {}".format(asked))
    check(os.path.isfile(path) and "polyhedron" in open(path).read(), "export wrote no polyhedron")

    # Undo/redo of a creation command works through the transaction.
    count = len(doc.Objects)
    Gui.Selection.clearSelection()
    run("RatBez_Sphere")
    check(len(doc.Objects) == count + 1, "sphere not created")
    doc.undo()
    process_events()
    check(len(doc.Objects) == count, "undo did not remove the sphere")


@suite.test
def test_screenshot_shows_the_shapes():
    Gui.Selection.clearSelection()
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    process_events()
    if os.path.exists(SCREENSHOT):
        os.remove(SCREENSHOT)
    view.saveImage(SCREENSHOT, 1280, 960, "White")
    check(os.path.isfile(SCREENSHOT), "no screenshot written")
    image = QtGui.QImage(SCREENSHOT)
    check(not image.isNull(), "screenshot unreadable")
    values, coloured = [], 0
    for y in range(0, image.height(), 8):
        for x in range(0, image.width(), 8):
            colour = QtGui.QColor(image.pixel(x, y))
            grey = (colour.red() + colour.green() + colour.blue()) / 3.0
            values.append(grey)
            if colour.red() < 235 or colour.green() < 235 or colour.blue() < 235:
                coloured += 1
    mean = sum(values) / len(values)
    variance = sum((v - mean) ** 2 for v in values) / len(values)
    say("screenshot {}: variance {:.1f}, {:.1%} non-white".format(SCREENSHOT, variance, coloured / len(values)))
    check(variance > 100, "screenshot looks blank (variance {:.1f})".format(variance))
    check(coloured / len(values) > 0.015, "screenshot is almost all white")


@suite.test
def test_no_python_exception_in_the_report_view():
    process_events()
    text = report_text()
    say("---- report view ----\n" + text + "\n---- end of report view ----")
    for marker in ("Traceback", "Exception", "<class '", "RatBez: internal error", "Recompute failed"):
        check(marker not in text, "'{}' in the report view".format(marker))
    check("RatBez:" not in text.replace("RatBez: wrote", ""), "RatBez error in the report view")


def main():
    for name in list(App.listDocuments()):
        App.closeDocument(name)
    suite.run_and_exit()  # os._exit: no "save changes?" dialog can block


QtCore.QTimer.singleShot(500, main)

"""GUI test of issue 26's workbench parts, run as `xvfb-run ... freecad test_gui_curves.py` by run_freecad.py
(its own FreeCAD session, beside test_gui.py's): RatBez_Interpolate from selected vertices through its task
panel (live preview of degree, parameterization, closed, own points), the Ruled panel's Align switch and start
vertices (an unaligned twist refused in the panel's status line, OK refused until it is aligned again) and
the Loft panel's Align switch and the start vertex of the section selected in its list. Screenshots go to
$RATBEZ_TEST_OUT/gui/. A watchdog ends FreeCAD if anything hangs."""

import math
import os
import sys
import threading

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

import FreeCAD as App  # noqa: E402
import FreeCADGui as Gui  # noqa: E402
import Part  # noqa: E402
import Sketcher  # noqa: E402,F401
from PySide import QtCore, QtGui  # noqa: E402

from harness import Suite, check, close, say  # noqa: E402

OUT = os.environ.get("RATBEZ_TEST_OUT", "/tmp")
SHOTS = os.path.join(OUT, "gui")
V = App.Vector
PI = math.pi

watchdog = threading.Timer(260, lambda: (say("RATBEZ_TEST_FAILED: watchdog fired"), os._exit(3)))
watchdog.daemon = True
watchdog.start()

suite = Suite()
doc = None


def process_events():
    for _ in range(5):
        QtGui.QApplication.processEvents()


def new_document(name):
    global doc
    for doc_name in list(App.listDocuments()):
        App.closeDocument(doc_name)
    doc = App.newDocument(name)
    process_events()
    return doc


def run_command(name):
    """Run a creating command; returns (new object, its open panel)."""
    from ratbez_wb import task_panels
    before = set(o.Name for o in doc.Objects)
    Gui.runCommand(name)
    process_events()
    created = [o for o in doc.Objects if o.Name not in before]
    check(len(created) == 1, "{} created {} objects".format(name, len(created)))
    obj = created[0]
    panel = task_panels.panel_of(obj)
    check(Gui.Control.activeDialog() and panel is not None, name + ": no task panel")
    return obj, panel


def screenshot(name):
    os.makedirs(SHOTS, exist_ok=True)
    Gui.ActiveDocument.ActiveView.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    process_events()
    path = os.path.join(SHOTS, name + ".png")
    Gui.getMainWindow().grab().save(path)
    check(not QtGui.QImage(path).isNull(), "screenshot unreadable: " + path)


def accept(panel, name):
    status = panel.status.text()  # before OK: the panel's widgets are gone after it
    check(panel.accept() is True, name + ": OK refused: " + status)
    process_events()
    check(not Gui.Control.activeDialog(), name + ": dialog still open after OK")


def square_sketch(name, half, z):
    sketch = doc.addObject("Sketcher::SketchObject", name)
    corners = [(-half, -half), (half, -half), (half, half), (-half, half)]  # from the SW corner
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(V(*a, 0), V(*b, 0)))
    sketch.Placement.Base = V(0, 0, z)
    doc.recompute()
    return sketch


def circle_object(name, radius, z):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = Part.Wire(Part.makeCircle(radius, V(0, 0, z)))
    doc.recompute()
    return obj


@suite.test
def test_interpolate_command_and_panel():
    Gui.activateWorkbench("RatBezWorkbench")
    process_events()
    check(Gui.Command.get("RatBez_Interpolate") is not None, "RatBez_Interpolate not registered")
    new_document("Interpolate")
    sketch = square_sketch("Square", 2.0, 0.0)
    Gui.Selection.clearSelection()
    for name in ("Vertex1", "Vertex2", "Vertex3", "Vertex4"):
        Gui.Selection.addSelection(sketch, name)
    process_events()
    obj, panel = run_command("RatBez_Interpolate")
    check([s for _, subs in obj.Source for s in subs] == ["Vertex1", "Vertex2", "Vertex3", "Vertex4"],
          "the vertices in the order picked: {}".format(obj.Source))
    check(obj.isValid() and not panel.points.table.isEnabled(), "following the selection: " + obj.getStatusString())
    check(panel.points.table.rowCount() == 4, "the panel shows the 4 points")
    length = obj.Shape.Length
    panel.closed.setChecked(True)
    process_events()
    check(obj.Closed and obj.Shape.Edges[0].isClosed() and obj.Shape.Length > length, "closed in the preview")
    check(not panel.tangents.isEnabled(), "no end tangents for a closed curve")
    panel.degree.setValue(5)
    process_events()
    check(not obj.isValid() and panel.status.text().startswith("Source: "), "status: " + panel.status.text())
    check(panel.accept() is False, "OK refused while the curve does not build")
    panel.degree.setValue(2)
    panel.parameterization.setCurrentIndex(1)
    process_events()
    check(obj.isValid() and obj.Parameterization == "centripetal", "degree 2, centripetal: " + obj.getStatusString())
    # Own points: the table takes over (starting from the selection's points) and can grow.
    panel.own_points()
    process_events()
    check(not obj.Source and panel.points.table.isEnabled() and len(obj.Points) == 4, "own points")
    panel.add_point()
    process_events()
    check(len(obj.Points) == 5 and obj.isValid(), "a fifth point")
    Gui.Selection.clearSelection()
    screenshot("RatBez_Interpolate")
    accept(panel, "Interpolate")


@suite.test
def test_ruled_panel_align_and_start_vertices():
    new_document("Ruled")
    circle = circle_object("Circle", 2.0, 0.0)
    square = square_sketch("Square", 1.5, 4.0)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(circle)
    Gui.Selection.addSelection(square)
    process_events()
    obj, panel = run_command("RatBez_Ruled")
    check(panel.align.isChecked() and obj.isValid(), "aligned by default: " + obj.getStatusString())
    aligned = obj.ExactVolume
    close(aligned, 43.16, 0.01, "the issue's circle -> square")
    check(not panel.starts[1].isEnabled(), "aligned: only the first profile's start vertex matters")
    panel.align.setChecked(False)
    process_events()
    check(not obj.isValid() and "lofted surface" in panel.status.text(), "unaligned: " + panel.status.text())
    check(panel.accept() is False and panel.starts[1].isEnabled(), "OK refused; both start vertices editable")
    panel.align.setChecked(True)
    panel.starts[0].setValue(1)
    process_events()
    check(obj.isValid() and list(obj.StartVertices) == [1, 0], "start vertex stored: {}".format(obj.StartVertices))
    close(obj.ExactVolume, aligned, 1e-9, "a circle has one vertex: the same solid")
    Gui.Selection.clearSelection()
    screenshot("RatBez_Ruled_align")
    accept(panel, "Ruled")


@suite.test
def test_loft_panel_align_and_section_start_vertex():
    new_document("Loft")
    bottom = square_sketch("Bottom", 1.0, 0.0)
    top = square_sketch("Top", 1.0, 2.0)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(bottom)
    Gui.Selection.addSelection(top)
    process_events()
    obj, panel = run_command("RatBez_Loft")
    panel.ruled.setChecked(True)
    process_events()
    close(obj.ExactVolume, 8.0, 1e-9, "square to square: the prism")
    panel.align.setChecked(False)
    panel.list.setCurrentRow(1)
    process_events()
    check(panel.start.isEnabled(), "start vertex of section 2 editable while unaligned")
    panel.start.setValue(3)  # half a turn round: every ruling through the axis
    process_events()
    check(list(obj.StartVertices) == [0, 3] and not obj.isValid(), "twisted: {}".format(panel.status.text()))
    panel.align.setChecked(True)
    process_events()
    close(obj.ExactVolume, 8.0, 1e-9, "aligned again, whatever the start vertex")
    check(not panel.start.isEnabled(), "aligned: section 2's start vertex does not matter")
    panel.list.setCurrentRow(0)
    process_events()
    check(panel.start.isEnabled() and panel.start.value() == 0, "section 1's start vertex shown")
    Gui.Selection.clearSelection()
    screenshot("RatBez_Loft_align")
    accept(panel, "Loft")


def main():
    for name in list(App.listDocuments()):
        App.closeDocument(name)
    suite.run_and_exit()  # os._exit: no "save changes?" dialog can block


QtCore.QTimer.singleShot(500, main)

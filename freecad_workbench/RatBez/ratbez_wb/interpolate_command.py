"""RatBez_Interpolate (issue 26): the curve through the selected vertices (in the order picked), through a
selected Draft wire's or B-spline's points, or through an object's vertices; with nothing selected, through
a few points to edit in the task panel."""

import FreeCAD as App
import FreeCADGui as Gui

from . import features
from .commands import _CreateCommand


def selection_source():
    """The selection as the Source of an Interpolate, or None: vertices picked (two or more in all), or whole
    objects with points (a Draft wire or B-spline) or vertices."""
    source = []
    vertices = 0
    for sel in Gui.Selection.getSelectionEx():
        obj = sel.Object
        if features.proxy_of(obj) is not None and obj.Proxy.TYPE == "RatBez::Interpolate":
            return None
        subs = [s for s in sel.SubElementNames if s]
        if subs:
            if not all(s.startswith("Vertex") for s in subs):
                return None
            source.append((obj, subs))
            vertices += len(subs)
            continue
        shape = getattr(obj, "Shape", None)
        if shape is None or shape.isNull() or len(shape.Vertexes) < 2:
            return None
        source.append((obj, [""]))
        vertices += len(shape.Vertexes)
    return source if vertices >= 2 else None


class InterpolateCommand(_CreateCommand):
    kind = "interpolate"
    menu = "Interpolate points"
    tooltip = ("Create the B-spline curve through the selected vertices (in the order picked), through a selected "
               "Draft wire's or B-spline's points, or through points edited in the task panel (The NURBS Book "
               "A9.1: chord-length, centripetal or uniform parameters; closed curves; end tangents)")

    def arguments(self):
        source = selection_source()
        if not source:
            return ""
        text = ", ".join("(App.ActiveDocument.getObject({!r}), {!r})".format(obj.Name, subs) for obj, subs in source)
        closed = len(source) == 1 and source[0][1] == [""] and bool(getattr(source[0][0], "Closed", False))
        return ", Source=[{}]{}".format(text, ", Closed=True" if closed else "")

    def IsActive(self):
        return App.ActiveDocument is not None

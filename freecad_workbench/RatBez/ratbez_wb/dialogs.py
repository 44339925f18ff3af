"""Qt dialogs of the RatBez commands (GUI only)."""

import os
import re

import FreeCADGui as Gui
from PySide import QtGui

from . import preferences
from .i18n import translate


def file_name_of(label):
    """A file name from an object's Label: path separators and control characters become '_'."""
    name = re.sub(r"[\\/:*?\"<>|]", "_", "".join(c if c.isprintable() else "_" for c in label)).strip(" .")
    return name or "solid"


def tolerance_field(value):
    """The chordal tolerance input shared by the export dialog and the preferences page."""
    spin = QtGui.QDoubleSpinBox()
    spin.setDecimals(5)
    spin.setRange(0.0, 1000.0)
    spin.setSingleStep(0.01)
    spin.setSuffix(" mm")
    spin.setSpecialValueText(translate("Automatic"))
    spin.setValue(value or 0.0)
    spin.setToolTip(translate("Largest distance between the mesh and the exact surfaces (Automatic: the "
                              "kernel's default, 1e-3 of the solid's size, or more for a part read from a file "
                              "whose faces the file gives a larger tolerance)"))
    return spin


FORMATS = (("OpenSCAD library (*.scad)", ".scad"), ("3MF (*.3mf)", ".3mf"), ("STL (*.stl)", ".stl"))


def ask_export_options(objects):
    """Ask where to write the solids `objects` (a list) and with which chordal tolerance; the extension
    chooses the format (.scad: an OpenSCAD library, .3mf: 3MF, .stl: binary STL), the filter chosen when none is
    typed.

    Returns (path, tolerance) with tolerance None for the kernel's automatic choice, or None when
    the user cancels. The folder and tolerance start from the preferences, and the folder used is
    remembered there.
    """
    stem = objects[0].Label if len(objects) == 1 else objects[0].Document.Label
    suggestion = os.path.join(preferences.export_directory(), file_name_of(stem) + ".scad")
    filters = [translate(text) for text, _ in FORMATS]
    title = (translate("Export RatBez solid") if len(objects) == 1
             else translate("Export {} solids").format(len(objects)))
    path, chosen = QtGui.QFileDialog.getSaveFileName(Gui.getMainWindow(), title, suggestion, ";;".join(filters))
    if not path:
        return None
    if not path.lower().endswith(tuple(extension for _, extension in FORMATS)):
        path += FORMATS[filters.index(chosen)][1] if chosen in filters else ".scad"

    dialog = QtGui.QDialog(Gui.getMainWindow())
    dialog.setWindowTitle(translate("Export tolerance"))
    layout = QtGui.QFormLayout(dialog)
    spin = tolerance_field(preferences.default_tolerance())
    layout.addRow(translate("Chordal tolerance:"), spin)
    buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)
    buttons.accepted.connect(dialog.accept)
    buttons.rejected.connect(dialog.reject)
    layout.addRow(buttons)
    if dialog.exec_() != QtGui.QDialog.Accepted:
        return None
    preferences.set_export_directory(os.path.dirname(path))
    tolerance = spin.value()
    return path, (tolerance if tolerance > 0 else None)

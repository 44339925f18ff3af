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
                              "kernel's default, 1e-3 of the solid's size)"))
    return spin


def ask_export_options(obj):
    """Ask where to write the OpenSCAD file of `obj` and with which chordal tolerance.

    Returns (path, tolerance) with tolerance None for the kernel's automatic choice, or None when
    the user cancels. The folder and tolerance start from the preferences, and the folder used is
    remembered there.
    """
    suggestion = os.path.join(preferences.export_directory(), file_name_of(obj.Label) + ".scad")
    path, _ = QtGui.QFileDialog.getSaveFileName(Gui.getMainWindow(), translate("Export RatBez solid to OpenSCAD"),
                                                suggestion, translate("OpenSCAD files (*.scad)"))
    if not path:
        return None
    if not path.lower().endswith(".scad"):
        path += ".scad"

    dialog = QtGui.QDialog(Gui.getMainWindow())
    dialog.setWindowTitle(translate("OpenSCAD export tolerance"))
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

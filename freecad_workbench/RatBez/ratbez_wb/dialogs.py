"""Qt dialogs of the RatBez commands (GUI only)."""

import os

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtGui

_PARAMS = "User parameter:BaseApp/Preferences/Mod/RatBez"


def ask_export_options(obj):
    """Ask where to write the OpenSCAD file of `obj` and with which chordal tolerance.

    Returns (path, tolerance) with tolerance None for the kernel's automatic choice, or None when
    the user cancels. The last directory and tolerance are remembered in the user parameters.
    """
    params = App.ParamGet(_PARAMS)
    directory = params.GetString("ExportDirectory", os.path.expanduser("~"))
    suggestion = os.path.join(directory, obj.Label + ".scad")
    path, _ = QtGui.QFileDialog.getSaveFileName(Gui.getMainWindow(), "Export RatBez solid to OpenSCAD",
                                                suggestion, "OpenSCAD files (*.scad)")
    if not path:
        return None
    if not path.lower().endswith(".scad"):
        path += ".scad"

    dialog = QtGui.QDialog(Gui.getMainWindow())
    dialog.setWindowTitle("OpenSCAD export tolerance")
    layout = QtGui.QFormLayout(dialog)
    spin = QtGui.QDoubleSpinBox(dialog)
    spin.setDecimals(5)
    spin.setRange(0.0, 1000.0)
    spin.setSingleStep(0.01)
    spin.setSuffix(" mm")
    spin.setSpecialValueText("Automatic")
    spin.setValue(params.GetFloat("ExportTolerance", 0.0))
    spin.setToolTip("Largest distance between the mesh and the exact surfaces (Automatic: the "
                    "kernel's default, relative to the solid's size)")
    layout.addRow("Chordal tolerance:", spin)
    buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)
    buttons.accepted.connect(dialog.accept)
    buttons.rejected.connect(dialog.reject)
    layout.addRow(buttons)
    if dialog.exec_() != QtGui.QDialog.Accepted:
        return None
    tolerance = spin.value()
    params.SetString("ExportDirectory", os.path.dirname(path))
    params.SetFloat("ExportTolerance", tolerance)
    return path, (tolerance if tolerance > 0 else None)

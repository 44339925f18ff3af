"""Edit > Preferences > RatBez: default export tolerance, export folder, the geometry of primitives in FreeCAD,
debug tracebacks (GUI only).
FreeCAD instantiates the class and calls loadSettings / saveSettings."""

from PySide import QtGui

from . import dialogs, features, preferences
from .i18n import translate


class PreferencesPage:
    def __init__(self):
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("RatBez"))
        layout = QtGui.QVBoxLayout(self.form)

        export = QtGui.QGroupBox(translate("Export (OpenSCAD, 3MF)"))
        form = QtGui.QFormLayout(export)
        self.tolerance = dialogs.tolerance_field(None)
        form.addRow(translate("Default chordal tolerance"), self.tolerance)
        folder_row = QtGui.QWidget()
        row = QtGui.QHBoxLayout(folder_row)
        row.setContentsMargins(0, 0, 0, 0)
        self.folder = QtGui.QLineEdit()
        self.folder.setToolTip(translate("Folder the export dialog starts in; it remembers the last one used"))
        browse = QtGui.QPushButton(translate("Browse..."))
        browse.clicked.connect(self.browse)
        row.addWidget(self.folder, 1)
        row.addWidget(browse)
        form.addRow(translate("Export folder"), folder_row)
        layout.addWidget(export)

        geometry = QtGui.QGroupBox(translate("Geometry in FreeCAD"))
        form = QtGui.QFormLayout(geometry)
        self.analytic = QtGui.QCheckBox(translate("Primitives, extrusions and revolutions on Part's analytic surfaces"))
        self.analytic.setToolTip(translate(
            "The same exact shape as Part's primitive, which OpenCASCADE's booleans, fillets and BOP check "
            "handle best. Off: the kernel's rational B-spline faces (booleans are slower and the BOP check can "
            "flag a B-spline sphere's poles). Exports always use the kernel's exact solid"))
        form.addRow(self.analytic)
        layout.addWidget(geometry)

        messages = QtGui.QGroupBox(translate("Messages"))
        form = QtGui.QFormLayout(messages)
        self.tracebacks = QtGui.QCheckBox(translate("Print Python tracebacks of failed recomputes"))
        self.tracebacks.setToolTip(translate(
            "For developers: besides the one-line message, a failed recompute prints the Python traceback "
            "(every time), as FreeCAD does for an exception"))
        form.addRow(self.tracebacks)
        layout.addWidget(messages)
        layout.addStretch(1)

    def browse(self):
        path = QtGui.QFileDialog.getExistingDirectory(self.form, translate("Export folder"), self.folder.text())
        if path:
            self.folder.setText(path)

    def loadSettings(self):
        self.tolerance.setValue(preferences.default_tolerance() or 0.0)
        self.folder.setText(preferences.export_directory())
        self.tracebacks.setChecked(preferences.debug_tracebacks())
        self.analytic.setChecked(preferences.analytic_primitives())

    def saveSettings(self):
        preferences.set_default_tolerance(self.tolerance.value())
        preferences.set_export_directory(self.folder.text().strip())
        preferences.set_debug_tracebacks(self.tracebacks.isChecked())
        if self.analytic.isChecked() != preferences.analytic_primitives():
            preferences.set_analytic_primitives(self.analytic.isChecked())
            features.rebuild_primitives()


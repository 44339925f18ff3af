"""Edit > Preferences > RatBez: default export tolerance, export folder, debug tracebacks (GUI only).
FreeCAD instantiates the class and calls loadSettings / saveSettings."""

from PySide import QtGui

from . import dialogs, preferences
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

    def saveSettings(self):
        preferences.set_default_tolerance(self.tolerance.value())
        preferences.set_export_directory(self.folder.text().strip())
        preferences.set_debug_tracebacks(self.tracebacks.isChecked())

"""The task panel of RatBez Interpolate (issue 26), with live preview like every RatBez panel: where the points
come from (the selection: vertices in the order picked, a Draft wire or B-spline, an object's vertices; or
the table of points), the degree, the parameterization, closed, and end tangents. Importing this module
registers the panel (task_panels.PANELS)."""

from PySide import QtGui

from . import conversion, curve_tools, task_panels
from .errors import Failure
from .i18n import translate

V = task_panels.V


class InterpolatePanel(task_panels.TaskPanel):
    TITLE, ICON = "RatBez interpolate", "RatBez_Interpolate"

    def build(self):
        # The picks' names on a row of their own, the buttons below them: beside the buttons, a long sketch name
        # pushed "Own points" past the Combo View's edge.
        self.source_label = QtGui.QLabel()
        self.source_label.setWordWrap(True)
        self.source_label.setToolTip(self.tooltip("Source"))
        self.layout.addRow(translate("Points from"), self.source_label)
        source = QtGui.QWidget()
        row = QtGui.QHBoxLayout(source)
        row.setContentsMargins(0, 0, 0, 0)
        use = QtGui.QPushButton(translate("Use selection"))
        use.setToolTip(translate("Interpolate the selected vertices (in the order picked), or the points of the "
                                 "selected Draft wire or B-spline, or the selected object's vertices"))
        use.clicked.connect(self.use_selection)
        clear = QtGui.QPushButton(translate("Own points"))
        clear.setToolTip(translate("Stop following the selection: interpolate the table of points below"))
        clear.clicked.connect(self.own_points)
        row.addWidget(use)
        row.addWidget(clear)
        self.layout.addRow(source)
        self.points = task_panels.PoleTable(self, lambda r: translate("point {}").format(r + 1))
        self.points.table.setToolTip(self.tooltip("Points"))
        self.layout.addRow(self.points.table)
        buttons = QtGui.QWidget()
        row = QtGui.QHBoxLayout(buttons)
        row.setContentsMargins(0, 0, 0, 0)
        self.add = QtGui.QPushButton(translate("Add point"))
        self.add.clicked.connect(self.add_point)
        self.remove = QtGui.QPushButton(translate("Remove point"))
        self.remove.clicked.connect(self.remove_point)
        row.addWidget(self.add)
        row.addWidget(self.remove)
        self.layout.addRow(buttons)
        self.degree = QtGui.QSpinBox()
        self.degree.setRange(1, curve_tools.MAX_DEGREE)
        self.degree.setToolTip(self.tooltip("Degree"))
        self.degree.valueChanged.connect(self.changed)
        self.layout.addRow(translate("Degree"), self.degree)
        self.parameterization = QtGui.QComboBox()
        self.parameterization.addItems(curve_tools.PARAMETERIZATIONS)
        self.parameterization.setToolTip(self.tooltip("Parameterization"))
        self.parameterization.currentIndexChanged.connect(self.changed)
        self.layout.addRow(translate("Parameterization"), self.parameterization)
        self.closed = self.add_check("Closed", self.tooltip("Closed"))
        self.tangents = self.add_check("End tangents", self.tooltip("EndTangents"))
        self.tangent_columns = self.add_vectors(("Start tangent", "End tangent"), ("", ""),
                                                (self.tooltip("StartTangent"), self.tooltip("EndTangent")))

    def following(self):
        return any(obj is not None for obj, _ in self.obj.Source)

    def load(self):
        links = [(obj, subs) for obj, subs in self.obj.Source if obj is not None]
        self.source_label.setText(", ".join(conversion.link_label(link) for link in links) if links
                                  else translate("the table below"))
        shown = list(self.obj.Points)
        if links:
            try:
                shown = curve_tools.source_points(links)
            except Failure:
                pass
        self.points.fill(shown, [], [translate("point {}").format(k + 1) for k in range(len(shown))])
        for widget in (self.points.table, self.add, self.remove):
            widget.setEnabled(not links)
        self.degree.setValue(self.obj.Degree)
        self.parameterization.setCurrentIndex(curve_tools.PARAMETERIZATIONS.index(self.obj.Parameterization))
        self.closed.setChecked(self.obj.Closed)
        self.tangents.setChecked(self.obj.EndTangents)
        self.tangent_columns[0].set_value(self.obj.StartTangent)
        self.tangent_columns[1].set_value(self.obj.EndTangent)
        self.shown()

    def store(self):
        if not self.following():
            try:
                self.obj.Points = self.points.poles()
            except Failure as failure:
                raise Failure("Points", failure.reason)
        self.obj.Degree = self.degree.value()
        self.obj.Parameterization = self.parameterization.currentText()
        self.obj.Closed = self.closed.isChecked()
        self.obj.EndTangents = self.tangents.isChecked()
        self.obj.StartTangent = self.tangent_columns[0].value()
        self.obj.EndTangent = self.tangent_columns[1].value()

    def shown(self):
        open_curve = not self.closed.isChecked()
        self.tangents.setEnabled(open_curve)
        for column in self.tangent_columns:
            column.set_enabled(open_curve and self.tangents.isChecked())

    def use_selection(self):
        from .interpolate_command import selection_source
        source = selection_source()
        if not source:
            self.tell(translate("Select two or more vertices, a Draft wire or B-spline, or an object first"))
            return
        self.obj.Source = source
        self.reload()

    def own_points(self):
        if self.following():
            # Keep what the selection gave as the table's starting points.
            self.obj.Points = self.points.poles()
        self.obj.Source = []
        self.reload()

    def add_point(self):
        points = list(self.obj.Points)
        step = points[-1] - points[-2] if len(points) > 1 else V(1, 0, 0)
        points.append(points[-1] + step)
        self.obj.Points = points
        self.reload()

    def remove_point(self):
        points = list(self.obj.Points)
        if len(points) <= 2:
            return
        row = self.points.table.currentRow()
        del points[row if 0 <= row < len(points) else len(points) - 1]
        self.obj.Points = points
        self.reload()


task_panels.PANELS[curve_tools.Interpolate.TYPE] = InterpolatePanel

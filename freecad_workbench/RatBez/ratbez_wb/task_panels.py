"""Task panels of the RatBez features (GUI only): opened when a creating command makes an object and on
double-click (the view provider's setEdit), as FreeCAD's Part primitives and PartDesign features do.

Every change in the form is written to the object's properties and recomputed at once (live preview);
a failure shows in the panel (not in the report view while the panel is open). The whole session is one
undo step: the creating command's transaction, or, for an edit (a double-click in the tree or the 3D view,
setEdit from the console), one the panel opens before its first change, since the tree's double-click
leaves none open; OK commits it and Cancel aborts it, so Cancel of a new object removes it and Cancel of
an edit restores the old values. OK is refused while the object does not recompute.

Only one task panel at a time, as in Part and PartDesign: the creating commands are disabled while one is
open, and editing another object asks whether to close the open RatBez panel (Cancel) first.

The panels fit FreeCAD's default Combo View (264 px wide, about 230 px for the form): fields shrink, rows
whose label and field do not fit side by side put the field under the label, button rows are grids of two,
and tables scroll rather than cut their cells.
"""

import contextlib

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

from . import conversion, features, resources
from .errors import Failure
from .i18n import QT_TRANSLATE_NOOP, translate

V = App.Vector
_open = {}  # object name -> its open panel


def may_edit(obj):
    """Before the view provider starts editing obj (a double-click): True when no task dialog is open or obj's
    own is; another RatBez panel is cancelled first if the user agrees, as PartDesign asks ("A dialog is
    already open in the task panel"); a dialog of another workbench must be closed first (False, one line
    in the report view). FreeCAD would otherwise end the open edit without its panel's Cancel."""
    if not Gui.Control.activeDialog() or obj.Name in _open:
        return True
    others = list(_open.values())
    if not others:
        App.Console.PrintWarning(translate("RatBez: close the open task panel first\n"))
        return False
    if not ask_to_close_open_panel():
        return False
    for other in others:
        other.reject()
    process_pending()
    return not Gui.Control.activeDialog()


def process_pending():
    """Let the task view remove a closed dialog before the next one shows."""
    for _ in range(3):
        QtGui.QApplication.processEvents()


def open_for(obj):
    """Show the task panel of a RatBez object (the view provider's setEdit); False if a task dialog is still
    open (may_edit asks first)."""
    proxy = features.proxy_of(obj)
    if proxy is None:
        return False
    if Gui.Control.activeDialog():
        if obj.Name in _open:
            return True
        App.Console.PrintWarning(translate("RatBez: close the open task panel first\n"))
        return False
    panel = PANELS[proxy.TYPE](obj)
    _open[obj.Name] = panel
    Gui.Control.showDialog(panel)
    return True


def ask_to_close_open_panel():
    """PartDesign's question when a dialog is open: True to close it (Yes, the default)."""
    box = QtGui.QMessageBox(Gui.getMainWindow())
    box.setObjectName("RatBezCloseOpenPanel")
    box.setIcon(QtGui.QMessageBox.Question)
    box.setText(translate("A dialog is already open in the task panel"))
    box.setInformativeText(translate("Do you want to close this dialog?"))
    box.setStandardButtons(QtGui.QMessageBox.Yes | QtGui.QMessageBox.No)
    box.setDefaultButton(QtGui.QMessageBox.Yes)
    return box.exec_() == QtGui.QMessageBox.Yes


def close_for(obj):
    """The view provider's unsetEdit: close the dialog. A panel still open here did not end by its OK or
    Cancel (FreeCAD ended the edit: another object's edit started, the document closes): it ends as Cancel,
    so its transaction does not stay open with the changes in it."""
    panel = _open.pop(getattr(obj, "Name", None), None)
    if panel is not None:
        panel.abandon()
    Gui.Control.closeDialog()


def panel_of(obj):
    """The open panel of obj, or None (tests drive it)."""
    return _open.get(obj.Name)


# ---------------------------------------------------------------------------------------------------
# Fields

# The narrowest a number field or combo box gets, beside its label in the form FreeCAD's default Combo View
# leaves (about 230 px). A field gets the width its row leaves, so no two fields share a row (VectorGrid).
FIELD_MINIMUM_WIDTH = 72


def narrow_combo(combo):
    """A combo box whose width does not follow its longest item (the popup still shows it whole)."""
    combo.setSizeAdjustPolicy(QtGui.QComboBox.AdjustToMinimumContentsLengthWithIcon)
    combo.setMinimumContentsLength(8)
    combo.setSizePolicy(QtGui.QSizePolicy.Expanding, QtGui.QSizePolicy.Fixed)
    return combo


class ElidedLabel(QtGui.QLabel):
    """A one-line label that shows as much of its text as fits, with "..." in the middle, and the whole text
    as its tooltip: an object name never widens the panel."""

    def __init__(self, text=""):
        super().__init__()
        self.full_text = ""
        self.setMinimumWidth(40)
        self.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Preferred)
        self.set_full_text(text)

    def set_full_text(self, text):
        self.full_text = text
        self.setToolTip(text)
        self._elide()

    def resizeEvent(self, event):
        super().resizeEvent(event)
        self._elide()

    def _elide(self):
        width = max(self.contentsRect().width() - 2 * max(self.indent(), 0), 40)
        self.setText(self.fontMetrics().elidedText(self.full_text, QtCore.Qt.ElideMiddle, width))


def button_grid(buttons, columns=2):
    """A widget with the buttons (or check boxes) in a grid, `columns` per row."""
    widget = QtGui.QWidget()
    grid = QtGui.QGridLayout(widget)
    grid.setContentsMargins(0, 0, 0, 0)
    for index, button in enumerate(buttons):
        grid.addWidget(button, index // columns, index % columns)
    return widget

class NumberField:
    """A number input with a unit: FreeCAD's Gui::QuantitySpinBox (units, expressions, as in FreeCAD's
    own panels) or, where the UI loader cannot make one, a QDoubleSpinBox."""

    def __init__(self, unit="mm", minimum=-1e9, maximum=1e9, step=1.0):
        widget = Gui.UiLoader().createWidget("Gui::QuantitySpinBox")
        self.quantity = widget is not None
        if self.quantity:
            widget.setProperty("unit", unit)
            widget.setProperty("minimum", float(minimum))
            widget.setProperty("maximum", float(maximum))
            widget.setProperty("singleStep", float(step))
        else:
            widget = QtGui.QDoubleSpinBox()
            widget.setRange(minimum, maximum)
            widget.setDecimals(6)
            widget.setSingleStep(step)
            widget.setSuffix(" " + unit.replace("deg", "°") if unit else "")
        # Narrower than its size hint when the task view is (a spin box's hint fits its longest value).
        widget.setMinimumWidth(FIELD_MINIMUM_WIDTH)
        widget.setSizePolicy(QtGui.QSizePolicy.Expanding, QtGui.QSizePolicy.Fixed)
        self.widget = widget

    def value(self):
        return float(self.widget.property("rawValue")) if self.quantity else self.widget.value()

    def set_value(self, value):
        if self.quantity:
            self.widget.setProperty("rawValue", float(value))
        else:
            self.widget.setValue(float(value))

    def on_change(self, callback):
        if self.quantity:
            # PySide wraps the loader's Gui::QuantitySpinBox as a plain QAbstractSpinBox, whose Python
            # class knows none of its signals: connect by the C++ signature.
            QtCore.QObject.connect(self.widget, QtCore.SIGNAL("valueChanged(double)"), lambda *_: callback())
        else:
            self.widget.valueChanged.connect(lambda *_: callback())


class VectorColumn:
    """One vector (x, y, z) of a VectorGrid: three NumberFields."""

    def __init__(self, fields):
        self.fields = fields

    def value(self):
        return V(*(f.value() for f in self.fields))

    def set_value(self, vector):
        for field, component in zip(self.fields, (vector.x, vector.y, vector.z)):
            field.set_value(component)

    def on_change(self, callback):
        for field in self.fields:
            field.on_change(callback)

    def set_enabled(self, enabled):
        for field in self.fields:
            field.widget.setEnabled(enabled)


class VectorGrid:
    """Vectors one under the other, each its title and rows X, Y, Z whose fields take the whole width. Side by
    side, as Part Revolve's Center and Direction, the default task view left a field about 60 px for its text:
    a Center x of 1234.5 showed as "34.50 mm"."""

    def __init__(self, titles, units):
        self.widget = QtGui.QWidget()
        grid = QtGui.QGridLayout(self.widget)
        grid.setContentsMargins(0, 0, 0, 0)
        self.columns = []
        for index, (title, unit) in enumerate(zip(titles, units)):
            row = 4 * index  # the title, X, Y, Z
            grid.addWidget(QtGui.QLabel(translate(title)), row, 0, 1, 2)
            fields = [NumberField(unit) for _ in range(3)]
            for r, (axis, field) in enumerate(zip("XYZ", fields)):
                grid.addWidget(QtGui.QLabel(axis), row + r + 1, 0)
                grid.addWidget(field.widget, row + r + 1, 1)
            self.columns.append(VectorColumn(fields))
        grid.setColumnStretch(1, 1)


# ---------------------------------------------------------------------------------------------------
# The panel framework

class TaskPanel:
    """Base of every RatBez task panel: form, live preview, status, transaction, OK / Cancel."""

    TITLE = ""
    ICON = "RatBezWorkbench"

    def __init__(self, obj):
        self.obj = obj
        self.name = obj.Name
        self.doc = obj.Document
        self.proxy = obj.Proxy
        self.loading = False
        self.ended = False  # by OK, Cancel or FreeCAD ending the edit (cleanup)
        self.linked_before = features.linked_objects(obj)
        # A creating command's transaction is open now and lasts until OK / Cancel; an edit has none that
        # lasts (the tree's double-click closes its own when the handler returns), so the panel opens one
        # before its first change (editing()).
        self.transaction = App.getActiveTransaction() is not None
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate(self.TITLE))
        self.form.setWindowIcon(QtGui.QIcon(resources.icon(self.ICON)))
        self.layout = QtGui.QFormLayout(self.form)
        # Narrow task view: a field that does not fit beside its label goes under it.
        self.layout.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.layout.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
        self.build()
        self.status = QtGui.QLabel()
        self.status.setWordWrap(True)
        self.status.setStyleSheet("color: #c00000")
        self.layout.addRow(self.status)
        with self.filling():
            self.load()
        self.proxy.quiet = True
        self.show_status()
        self.shown()

    # -- subclasses -------------------------------------------------------------------------------

    def build(self):
        """Add the form's rows (self.layout) and connect their changes to self.changed."""

    def load(self):
        """Properties -> widgets."""

    def store(self):
        """Widgets -> properties; may raise Failure for input the widgets cannot hold."""

    def shown(self):
        """After the form is filled and after each preview (the Revolve axis drawing)."""

    def ready(self):
        """Whether the object can be recomputed yet (a sweep needs its path); else the reason, in the status."""
        return True

    # -- the undo step ----------------------------------------------------------------------------

    def editing(self):
        """Before the panel changes a property: the session's transaction is open (one the panel opens for an
        edit, named "Edit <Label>", unless FreeCAD has one open for it)."""
        if not App.getActiveTransaction():
            self.doc.openTransaction(translate("Edit {}").format(self.obj.Label))
        self.transaction = True

    # -- live preview -----------------------------------------------------------------------------

    @contextlib.contextmanager
    def filling(self):
        """While the panel writes its own widgets: their change signals are not the user's edits."""
        self.loading = True
        try:
            yield
        finally:
            self.loading = False

    def reload(self):
        """Properties -> widgets again (the panel changed properties itself), then the preview."""
        with self.filling():
            self.load()
        self.changed()

    def changed(self, *_):
        # A field that has the focus when Enter accepts (the task view's default button) or Escape cancels
        # reports its value once more as the closing dialog takes the focus from it: no change of an ended
        # panel is the user's, and it would open an undo step of its own or put the old values back after
        # Cancel, and draw the Revolve's axis again.
        if self.loading or self.ended:
            return
        self.editing()
        try:
            self.store()
        except Failure as failure:
            self.tell(str(failure))
            return
        if self.ready() is not True:
            self.tell(self.ready())
            return
        self.doc.recompute()
        self.show_status()
        self.shown()

    def failure(self):
        """The object's failure, or None when it recomputes."""
        if "Invalid" in self.obj.State or "Error" in self.obj.State:
            return getattr(self.proxy, "last_failure", None) or self.obj.getStatusString()
        return None

    def tell(self, text):
        """A hint or a refusal of the panel itself, in the status line."""
        self.status.setText(text)
        self.status.setVisible(True)

    def show_status(self):
        failure = self.failure() or (None if self.ready() is True else self.ready())
        self.status.setText(failure or "")
        self.status.setVisible(bool(failure))

    # -- OK / Cancel ------------------------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        self.editing()
        try:
            self.store()
        except Failure as failure:
            self.tell(str(failure))
            return False
        if self.ready() is not True:
            self.tell(self.ready())
            return False
        self.doc.recompute()
        if self.failure():
            self.show_status()
            return False
        self.doc.commitTransaction()
        self.finish()
        return True

    def reject(self):
        self.undo_session()
        self.finish()
        return True

    def abandon(self):
        """Cancel without ending the edit (FreeCAD is ending it)."""
        self.undo_session()
        self.cleanup()

    def undo_session(self):
        if self.transaction:
            self.doc.abortTransaction()
        if self.doc.getObject(self.name) is None:
            # Cancel of a new object: it is gone, show its profiles again (hiding them was not undoable).
            for linked in self.linked_before:
                linked.ViewObject.Visibility = True
        self.doc.recompute()

    def finish(self):
        self.cleanup()
        if Gui.ActiveDocument is not None and Gui.ActiveDocument.getInEdit() is not None:
            Gui.ActiveDocument.resetEdit()

    def cleanup(self):
        """Undo what the panel set up (quiet reports, observers, drawings); safe to call twice."""
        self.ended = True
        self.proxy.quiet = False
        for name, panel in list(_open.items()):
            if panel is self:
                del _open[name]

    def add_number(self, label, prop_unit="mm", minimum=-1e9, maximum=1e9, tooltip=""):
        field = NumberField(prop_unit, minimum, maximum)
        field.on_change(self.changed)
        field.widget.setToolTip(tooltip)
        self.layout.addRow(translate(label), field.widget)
        return field

    def add_vectors(self, titles, units, tooltips):
        """A VectorGrid row; returns its vectors (VectorColumn), each connected to the live preview."""
        grid = VectorGrid(titles, units)
        for column, tooltip in zip(grid.columns, tooltips):
            column.on_change(self.changed)
            for field in column.fields:
                field.widget.setToolTip(tooltip)
        self.layout.addRow(grid.widget)
        return grid.columns

    def add_check(self, label, tooltip=""):
        box = QtGui.QCheckBox(translate(label))
        box.setToolTip(tooltip)
        box.toggled.connect(self.changed)
        self.layout.addRow(box)
        return box

    def tooltip(self, prop):
        return translate(self.obj.getDocumentationOfProperty(prop), "App::Property")


# ---------------------------------------------------------------------------------------------------
# Primitives: dimensions, then where (Center) and which way (Axis)

class PrimitivePanel(TaskPanel):
    DIMENSIONS = ()        # property names of lengths
    HAS_AXIS = True

    def build(self):
        self.dimensions = {}
        for prop in self.DIMENSIONS:
            minimum = 0.0 if prop in ("Radius2",) else 1e-7
            self.dimensions[prop] = self.add_number(prop, "mm", minimum, 1e9, self.tooltip(prop))
        titles, units, tips = [QT_TRANSLATE_NOOP("RatBez", "Center")], ["mm"], [self.tooltip("Center")]
        if self.HAS_AXIS:
            titles, units, tips = titles + [QT_TRANSLATE_NOOP("RatBez", "Axis")], units + [""], tips + [self.tooltip("Axis")]
        self.layout.addRow(QtGui.QLabel("<b>{}</b>".format(translate("Location"))))
        columns = self.add_vectors(titles, units, tips)
        self.center = columns[0]
        self.axis = columns[1] if self.HAS_AXIS else None

    def load(self):
        for prop, field in self.dimensions.items():
            field.set_value(getattr(self.obj, prop).Value)
        self.center.set_value(self.obj.Center)
        if self.HAS_AXIS:
            self.axis.set_value(self.obj.Axis)

    def store(self):
        for prop, field in self.dimensions.items():
            setattr(self.obj, prop, field.value())
        self.obj.Center = self.center.value()
        if self.HAS_AXIS:
            self.obj.Axis = self.axis.value()


class CylinderPanel(PrimitivePanel):
    TITLE, ICON, DIMENSIONS = "RatBez cylinder", "RatBez_Cylinder", ("Radius", "Height")


class ConePanel(PrimitivePanel):
    TITLE, ICON, DIMENSIONS = "RatBez cone", "RatBez_Cone", ("Radius1", "Radius2", "Height")


class SpherePanel(PrimitivePanel):
    TITLE, ICON, DIMENSIONS, HAS_AXIS = "RatBez sphere", "RatBez_Sphere", ("Radius",), False


class TorusPanel(PrimitivePanel):
    TITLE, ICON, DIMENSIONS = "RatBez torus", "RatBez_Torus", ("MajorRadius", "MinorRadius")


# ---------------------------------------------------------------------------------------------------
# Profile features: the profile, and a line (axis or direction) picked from presets or the 3D view

def selected_link(accept):
    """The current selection as a PropertyLinkSub value if `accept(link)` says it fits, else None."""
    selection = Gui.Selection.getSelectionEx()
    if len(selection) != 1:
        return None
    link = (selection[0].Object, [s for s in selection[0].SubElementNames if s])
    return link if accept(link) else None


class LinkRow:
    """A linked profile or path in a panel: what it designates and a button that relinks it to the selection
    ("Use selection"), or, with picking, a toggle as Part Sweep's "Sweep Path": pressed, the user selects
    the edges or the sketch in the 3D view or the tree, and pressing "Done" links them."""

    def __init__(self, panel, prop, label, tooltip, picking=False):
        self.panel, self.prop, self.picking = panel, prop, picking
        # The row's title, then the linked object's name across the whole panel (elided only past its
        # width), then the button: the narrow task view has no room for the three side by side.
        self.widget = QtGui.QWidget()
        layout = QtGui.QVBoxLayout(self.widget)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        self.label = ElidedLabel()
        self.button = QtGui.QPushButton(translate("Select..." if picking else "Use selection"))
        self.button.setToolTip(tooltip)
        self.button.setCheckable(picking)
        if picking:
            self.button.toggled.connect(self.pick)
        else:
            self.button.clicked.connect(self.use_selection)
        buttons = QtGui.QHBoxLayout()
        buttons.addWidget(self.button)
        buttons.addStretch(1)
        layout.addWidget(self.label)
        layout.addLayout(buttons)
        panel.layout.addRow(QtGui.QLabel(translate(label)))
        panel.layout.addRow(self.widget)

    def load(self):
        self.label.set_full_text(conversion.link_label(getattr(self.panel.obj, self.prop)))

    def pick(self, pressed):
        if pressed:
            Gui.Selection.clearSelection()
            self.button.setText(translate("Done"))
            self.panel.tell("{}: {}".format(self.prop, translate(
                "select its edges or its sketch in the 3D view or the tree, then press Done")))
            return
        self.button.setText(translate("Select..."))
        self.use_selection()

    def use_selection(self):
        link = selected_link(lambda candidate: candidate[0] is not self.panel.obj)
        if link is None:
            self.panel.tell(translate("Select a sketch, a wire, edges or one face first"))
            return
        self.panel.editing()
        setattr(self.panel.obj, self.prop, link)
        self.load()
        self.panel.changed()


class ProfilePanel(TaskPanel):
    """A panel with a Profile row ("Use selection" relinks it) and a line reference picked in the 3D view
    while its mode asks for one (a selection observer, as PartDesign's "Select reference...")."""

    LINE_PROPERTY = ""     # AxisReference / DirectionReference

    def add_profile_row(self):
        self.profile_row = LinkRow(self, "Profile", "Profile",
                                   translate("Make the selected sketch, wire, edges or face the profile"))
        self.reference = None
        Gui.Selection.addObserver(self)

    def add_line_modes(self, label, modes, tooltip):
        """The combo box of the ways to give the axis or direction (modes: (name, text) pairs), and below
        it the label that names the picked edge or datum line when that is the way."""
        combo = narrow_combo(QtGui.QComboBox())
        for _, text in modes:
            combo.addItem(translate(text))
        combo.setToolTip(tooltip)
        combo.currentIndexChanged.connect(self.changed)
        self.layout.addRow(QtGui.QLabel(translate(label)))
        self.layout.addRow(combo)
        self.reference_label = QtGui.QLabel()
        self.reference_label.setWordWrap(True)
        self.layout.addRow(self.reference_label)
        return combo

    def show_reference(self):
        """The picked line's name, or how to pick one, while picking_line()."""
        if self.picking_line():
            self.reference_label.setText(conversion.link_label(self.reference) if self.reference
                                         else translate("Select a straight edge or a datum line"))
        self.reference_label.setVisible(self.picking_line())

    def picking_line(self):
        """Whether a click on a straight edge or datum line in the 3D view or the tree sets the line."""
        return False

    # Gui.Selection observer
    def addSelection(self, document, name, sub, point):
        if not self.picking_line() or document != self.doc.Name:
            return
        obj = self.doc.getObject(name)
        if obj is None or obj is self.obj:
            return
        link = (obj, [sub] if sub else [])
        try:
            conversion.straight_line(link, self.LINE_PROPERTY)
        except Failure:
            return
        self.reference = link
        self.changed()

    def cleanup(self):
        super().cleanup()
        try:
            Gui.Selection.removeObserver(self)
        except Exception:  # already removed
            pass


# The Revolve feature's AxisMode values, in its order, with their words in the panel.
_AXIS_MODES = [
    ("Vertical", "Profile's vertical axis"),
    ("Horizontal", "Profile's horizontal axis"),
    ("X", "X axis"), ("Y", "Y axis"), ("Z", "Z axis"),
    ("Reference", "Picked edge or datum line"),
    ("Custom", "Custom"),
]
assert [mode for mode, _ in _AXIS_MODES] == features.REVOLVE_AXIS_MODES


class RevolvePanel(ProfilePanel):
    TITLE, ICON, LINE_PROPERTY = "RatBez revolve", "RatBez_Revolve", "AxisReference"

    def build(self):
        self.add_profile_row()
        self.axis_mode = self.add_line_modes("Axis", _AXIS_MODES, translate(
            "The axis: the profile plane's vertical or horizontal axis (a sketch's V or H axis), a global "
            "axis through the origin, a straight edge or datum line picked in the 3D view or the tree, or "
            "any point and direction"))
        self.point, self.direction = self.add_vectors(["Axis point", "Axis direction"], ["mm", ""],
                                                      [self.tooltip("AxisPoint"), self.tooltip("AxisDirection")])
        self.angle = self.add_number("Angle", "deg", 1e-6, 360.0, self.tooltip("Angle"))
        self.symmetric = self.add_check("Symmetric to the profile's plane", self.tooltip("Symmetric"))
        self.reversed = self.add_check("Reversed", self.tooltip("Reversed"))
        self.axis_node = None

    def mode(self):
        return _AXIS_MODES[self.axis_mode.currentIndex()][0]

    def load(self):
        obj = self.obj
        self.profile_row.load()
        self.reference = obj.AxisReference if obj.AxisReference else None
        self.axis_mode.setCurrentIndex(features.REVOLVE_AXIS_MODES.index(obj.AxisMode))
        self.point.set_value(obj.AxisPoint)
        self.direction.set_value(obj.AxisDirection)
        self.angle.set_value(obj.Angle)
        self.symmetric.setChecked(obj.Symmetric)
        self.reversed.setChecked(obj.Reversed)
        self.update_fields()

    def picking_line(self):
        return self.mode() == "Reference"

    def update_fields(self):
        custom = self.mode() == "Custom"
        self.point.set_enabled(custom)
        self.direction.set_enabled(custom)
        self.show_reference()

    def store(self):
        # The feature finds the axis of every mode but Custom at each recompute (AxisPoint and AxisDirection
        # then show it): a Vertical axis follows the sketch when it moves.
        obj = self.obj
        mode = self.mode()
        if mode != "Reference" and obj.AxisReference:
            obj.AxisReference = None
        if mode == "Reference":
            if self.reference is None:
                raise Failure("AxisReference", translate("select a straight edge or a datum line"))
            obj.AxisReference = self.reference
        elif mode == "Custom":
            obj.AxisPoint, obj.AxisDirection = self.point.value(), self.direction.value()
        obj.AxisMode = mode
        obj.Angle = self.angle.value()
        obj.Symmetric = self.symmetric.isChecked()
        obj.Reversed = self.reversed.isChecked()

    def shown(self):
        with self.filling():
            if self.mode() != "Custom":
                self.point.set_value(self.obj.AxisPoint)
                self.direction.set_value(self.obj.AxisDirection)
            self.update_fields()
        self.draw_axis()

    def draw_axis(self):
        """The axis as a dashed line through the profile and the solid, in the 3D view."""
        from pivy import coin
        view = Gui.ActiveDocument.ActiveView if Gui.ActiveDocument else None
        if view is None or not hasattr(view, "getSceneGraph"):
            return
        if self.axis_node is None:
            self.axis_node = coin.SoSeparator()
            style = coin.SoDrawStyle()
            style.lineWidth = 3
            style.linePattern = 0xF0F0
            color = coin.SoBaseColor()
            color.rgb = (0.85, 0.15, 0.15)
            self.axis_coordinates = coin.SoCoordinate3()
            self.axis_node.addChild(style)
            self.axis_node.addChild(color)
            self.axis_node.addChild(self.axis_coordinates)
            self.axis_node.addChild(coin.SoLineSet())
            view.getSceneGraph().addChild(self.axis_node)
        box = App.BoundBox()
        for obj in (self.obj, conversion.link_object(self.obj.Profile)):
            shape = getattr(obj, "Shape", None)
            if shape is not None and not shape.isNull():
                box.add(shape.BoundBox)
        direction = V(self.obj.AxisDirection)
        if direction.Length <= 1e-12:
            return
        direction.normalize()
        point = V(self.obj.AxisPoint)
        middle = point + direction * direction.dot((box.Center if box.isValid() else point) - point)
        half = 0.6 * (box.DiagonalLength if box.isValid() and box.DiagonalLength > 0 else 10.0)
        ends = [middle - direction * half, middle + direction * half]
        self.axis_coordinates.point.setValues(0, 2, [[e.x, e.y, e.z] for e in ends])

    def cleanup(self):
        super().cleanup()
        if self.axis_node is not None and Gui.ActiveDocument and hasattr(Gui.ActiveDocument.ActiveView, "getSceneGraph"):
            Gui.ActiveDocument.ActiveView.getSceneGraph().removeChild(self.axis_node)
        self.axis_node = None


_DIRECTION_MODES = [
    ("Normal", "Profile's normal"),
    ("Edge", "Picked edge or datum line"),
    ("Custom", "Custom direction"),
]


class ExtrudePanel(ProfilePanel):
    TITLE, ICON, LINE_PROPERTY = "RatBez extrude", "RatBez_Extrude", "DirectionReference"

    def build(self):
        self.add_profile_row()
        self.direction_mode = self.add_line_modes("Direction", _DIRECTION_MODES, self.tooltip("DirectionMode"))
        self.direction, = self.add_vectors(["Custom direction"], [""], [self.tooltip("Direction")])
        self.distance = self.add_number("Distance", "mm", -1e9, 1e9, self.tooltip("Distance"))
        self.reversed = self.add_check("Reversed", self.tooltip("Reversed"))
        self.symmetric = self.add_check("Symmetric to the profile's plane", self.tooltip("Symmetric"))

    def mode(self):
        return _DIRECTION_MODES[self.direction_mode.currentIndex()][0]

    def picking_line(self):
        return self.mode() == "Edge"

    def load(self):
        obj = self.obj
        self.profile_row.load()
        self.reference = obj.DirectionReference if obj.DirectionReference else None
        self.direction_mode.setCurrentIndex([m for m, _ in _DIRECTION_MODES].index(obj.DirectionMode))
        self.direction.set_value(obj.Direction)
        self.distance.set_value(obj.Distance.Value)
        self.reversed.setChecked(obj.Reversed)
        self.symmetric.setChecked(obj.Symmetric)
        self.update_fields()

    def update_fields(self):
        self.direction.set_enabled(self.mode() == "Custom")
        self.show_reference()

    def store(self):
        obj = self.obj
        mode = self.mode()
        if mode == "Edge":
            if self.reference is None:
                raise Failure("DirectionReference", translate("select a straight edge or a datum line"))
            obj.DirectionReference = self.reference
        elif obj.DirectionReference:
            obj.DirectionReference = None
        obj.DirectionMode = mode
        if mode == "Custom":
            obj.Direction = self.direction.value()
        obj.Distance = self.distance.value()
        obj.Reversed = self.reversed.isChecked()
        obj.Symmetric = self.symmetric.isChecked()

    def shown(self):
        self.update_fields()


# ---------------------------------------------------------------------------------------------------
# Solids through several profiles (ruled, loft) and along a path (sweep)

def start_vertex_spin(panel, tooltip):
    """A spin box for a profile's start vertex (0: the profile's own start), connected to the live preview."""
    spin = QtGui.QSpinBox()
    spin.setRange(0, 999)
    spin.setSpecialValueText(translate("its own start"))
    spin.setToolTip(tooltip)
    spin.valueChanged.connect(panel.changed)
    return spin


class RuledPanel(TaskPanel):
    TITLE, ICON = "RatBez ruled solid", "RatBez_Ruled"

    def build(self):
        self.rows = [LinkRow(self, prop, label, translate("Make the selected sketch, wire, edges or face this profile"))
                     for prop, label in (("Profile1", "First profile"), ("Profile2", "Second profile"))]
        self.align = self.add_check("Align sections (least twist)", self.tooltip("Align"))
        self.starts = []
        for label in ("Start vertex, first", "Start vertex, second"):
            spin = start_vertex_spin(self, self.tooltip("StartVertices"))
            self.layout.addRow(translate(label), spin)
            self.starts.append(spin)

    def load(self):
        for row in self.rows:
            row.load()
        self.align.setChecked(self.obj.Align)
        starts = list(self.obj.StartVertices) + [0, 0]
        for spin, start in zip(self.starts, starts):
            spin.setValue(start)

    def store(self):
        self.obj.Align = self.align.isChecked()
        self.obj.StartVertices = [spin.value() for spin in self.starts]

    def shown(self):
        # Aligned, only the first profile's start matters (the seam).
        self.starts[1].setEnabled(not self.align.isChecked())


class LoftPanel(TaskPanel):
    """The sections as an ordered list (as Part Loft's), with buttons to add the selected profiles, remove
    one and move one up or down; the degree across them, the Ruled and Align switches and the start vertex of
    the section selected in the list."""

    TITLE, ICON = "RatBez loft", "RatBez_Loft"

    def build(self):
        self.layout.addRow(QtGui.QLabel("<b>{}</b>".format(translate("Sections, in order"))))
        self.list = QtGui.QListWidget()
        self.list.setToolTip(self.tooltip("Sections"))
        self.list.setMinimumHeight(120)
        self.layout.addRow(self.list)
        buttons = []
        for text, tip, action in (
                ("Add selection", "Append the selected sketches, wires, edges or faces as sections", self.add_selected),
                ("Remove", "Remove the selected section", self.remove),
                ("Up", "Move the selected section one place earlier", lambda: self.move(-1)),
                ("Down", "Move the selected section one place later", lambda: self.move(1))):
            button = QtGui.QPushButton(translate(text))
            button.setToolTip(translate(tip))
            button.clicked.connect(action)
            buttons.append(button)
        self.layout.addRow(button_grid(buttons))
        self.degree = QtGui.QSpinBox()
        self.degree.setRange(1, features.LOFT_MAX_DEGREE)
        self.degree.setToolTip(self.tooltip("Degree"))
        self.degree.valueChanged.connect(self.changed)
        self.layout.addRow(translate("Degree across"), self.degree)
        self.ruled = self.add_check("Ruled surface", self.tooltip("Ruled"))
        self.align = self.add_check("Align sections (least twist)", self.tooltip("Align"))
        self.start = start_vertex_spin(self, self.tooltip("StartVertices"))
        self.layout.addRow(translate("Start vertex of the selected section"), self.start)
        self.list.currentRowChanged.connect(self.section_picked)
        self.sections = []
        self.starts = []

    def load(self):
        self.sections = self.proxy.section_links(self.obj)
        self.starts = (list(self.obj.StartVertices) + [0] * len(self.sections))[:len(self.sections)]
        self.fill()
        self.degree.setValue(self.obj.Degree)
        self.ruled.setChecked(self.obj.Ruled)
        self.degree.setEnabled(not self.obj.Ruled)
        self.align.setChecked(self.obj.Align)

    def section_picked(self, index):
        # Not filling(): this also runs inside load's filling, whose state it must leave as it was.
        loading, self.loading = self.loading, True
        try:
            self.start.setValue(self.starts[index] if 0 <= index < len(self.starts) else 0)
        finally:
            self.loading = loading
        self.shown()

    def fill(self, current=-1):
        self.list.clear()
        for index, link in enumerate(self.sections):
            self.list.addItem("{}. {}".format(index + 1, conversion.link_label(link)))
        self.list.setCurrentRow(current)

    def add_selected(self):
        links = [(sel.Object, [s for s in sel.SubElementNames if s]) for sel in Gui.Selection.getSelectionEx()
                 if sel.Object is not self.obj]
        if not links:
            self.tell(translate("Select sketches, wires, edges or faces first"))
            return
        for obj, subs in links:
            faces = [s for s in subs if s.startswith("Face")]
            self.sections.extend([(obj, [f]) for f in faces] if faces and len(faces) == len(subs) else [(obj, subs)])
        self.starts += [0] * (len(self.sections) - len(self.starts))
        self.fill(len(self.sections) - 1)
        self.changed()

    def remove(self):
        index = self.list.currentRow()
        if 0 <= index < len(self.sections):
            del self.sections[index]
            del self.starts[index]
            self.fill(min(index, len(self.sections) - 1))
            self.changed()

    def move(self, step):
        index = self.list.currentRow()
        target = index + step
        if 0 <= index < len(self.sections) and 0 <= target < len(self.sections):
            self.sections[index], self.sections[target] = self.sections[target], self.sections[index]
            self.starts[index], self.starts[target] = self.starts[target], self.starts[index]
            self.fill(target)
            self.changed()

    def store(self):
        # Sub-element lists ([""] for a whole object) keep the order in the PropertyLinkSubList.
        self.obj.Sections = [(obj, subs or [""]) for obj, subs in self.sections]
        self.obj.Degree = self.degree.value()
        self.obj.Ruled = self.ruled.isChecked()
        self.obj.Align = self.align.isChecked()
        index = self.list.currentRow()
        if 0 <= index < len(self.starts) and self.start.isEnabled():
            self.starts[index] = self.start.value()
        self.obj.StartVertices = list(self.starts)

    def shown(self):
        self.degree.setEnabled(not self.ruled.isChecked())
        # Aligned, only the first section's start matters (the seam).
        index = self.list.currentRow()
        self.start.setEnabled(0 <= index < len(self.sections) and (index == 0 or not self.align.isChecked()))


class SweepPanel(TaskPanel):
    """The profile ("Use selection"), the path (picked as in Part Sweep: "Select...", the edges or sketch,
    "Done") and the tolerance of the approximation."""

    TITLE, ICON = "RatBez sweep", "RatBez_Sweep"

    def build(self):
        self.profile_row = LinkRow(self, "Profile", "Profile",
                                   translate("Make the selected sketch, wire, edges or face the profile"))
        self.path_row = LinkRow(self, "Path", "Path", translate(
            "Press, select the path's edges or its sketch in the 3D view or the tree, and press Done"), picking=True)
        self.tolerance = QtGui.QLineEdit()
        self.tolerance.setMinimumWidth(FIELD_MINIMUM_WIDTH)
        self.tolerance.setValidator(QtGui.QDoubleValidator(0.0, 1e9, 15))
        self.tolerance.setToolTip(self.tooltip("Tolerance"))
        self.tolerance.editingFinished.connect(self.changed)
        self.layout.addRow(translate("Tolerance (mm)"), self.tolerance)

    def load(self):
        self.profile_row.load()
        self.path_row.load()
        self.tolerance.setText("{:g}".format(self.obj.Tolerance))

    def ready(self):
        if self.obj.Path:
            return True
        return "Path: {}".format(translate("press Select..., select its edges or its sketch in the 3D view or the tree, "
                                           "then press Done"))

    def shown(self):
        # Made with its profile only (the command): the path is picked first, nothing recomputed before.
        if not self.obj.Path and not self.path_row.button.isChecked():
            self.path_row.button.setChecked(True)

    def store(self):
        text = self.tolerance.text().strip().replace(",", ".")
        try:
            self.obj.Tolerance = float(text)
        except ValueError:
            raise Failure("Tolerance", translate("is not a number: '{}'").format(text))


# ---------------------------------------------------------------------------------------------------
# Bézier curve and surface: a table of poles and weights

class PoleTable:
    """A table of poles (X, Y, Z) and weights, with a 'Rational' switch for the weight column."""

    def __init__(self, panel, row_label):
        self.panel, self.row_label = panel, row_label
        self.table = QtGui.QTableWidget(0, 4)
        self.table.setHorizontalHeaderLabels(["X", "Y", "Z", translate("Weight")])
        # Each column as wide as its numbers (a stretched column in a narrow task view cut "3.333333333" to
        # "3...."); the table scrolls sideways when they do not fit.
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QtGui.QHeaderView.ResizeToContents)
        header.setStretchLastSection(True)
        self.table.setTextElideMode(QtCore.Qt.ElideNone)
        self.table.setMinimumWidth(120)
        self.table.setMinimumHeight(160)
        self.table.itemChanged.connect(panel.changed)
        self.rational = QtGui.QCheckBox(translate("Rational (a weight per pole)"))
        self.rational.toggled.connect(self.rational_toggled)

    def rational_toggled(self, *_):
        self.table.setColumnHidden(3, not self.rational.isChecked())
        self.panel.changed()

    @staticmethod
    def item(value):
        """A cell showing `value` with 6 significant digits and keeping it whole: reading an untouched cell
        back gives the exact value, not its shown digits."""
        item = QtGui.QTableWidgetItem("{:.6g}".format(value))
        item.setData(QtCore.Qt.UserRole, float(value))
        return item

    def fill(self, poles, weights, labels):
        self.table.setRowCount(len(poles))
        self.table.setVerticalHeaderLabels(labels)
        for row, pole in enumerate(poles):
            for column, value in enumerate((pole.x, pole.y, pole.z)):
                self.table.setItem(row, column, self.item(value))
            weight = weights[row] if row < len(weights) else 1.0
            self.table.setItem(row, 3, self.item(weight))
        self.rational.setChecked(bool(weights))
        self.table.setColumnHidden(3, not weights)

    def _number(self, row, column):
        item = self.table.item(row, column)
        text = item.text().strip() if item else ""
        kept = item.data(QtCore.Qt.UserRole) if item else None
        if kept is not None and text == "{:.6g}".format(kept):
            return kept
        try:
            return float(text.replace(",", "."))
        except ValueError:
            what = ["X", "Y", "Z", translate("weight")][column]
            raise Failure("Weights" if column == 3 else "Poles",
                          translate("{} of {} is not a number: '{}'").format(what, self.row_label(row), text))

    def poles(self):
        return [V(*(self._number(row, c) for c in range(3))) for row in range(self.table.rowCount())]

    def weights(self):
        if not self.rational.isChecked():
            return []
        return [self._number(row, 3) for row in range(self.table.rowCount())]


class BezierCurvePanel(TaskPanel):
    TITLE, ICON = "RatBez Bézier curve", "RatBez_BezierCurve"

    def build(self):
        self.poles = PoleTable(self, lambda row: translate("pole {}").format(row + 1))
        self.layout.addRow(self.poles.table)
        add = QtGui.QPushButton(translate("Add pole"))
        add.setToolTip(translate("Append a pole beyond the last one (the degree goes up by one)"))
        add.clicked.connect(self.add_pole)
        remove = QtGui.QPushButton(translate("Remove pole"))
        remove.setToolTip(translate("Remove the selected pole, or the last one"))
        remove.clicked.connect(self.remove_pole)
        self.layout.addRow(button_grid([add, remove]))
        self.layout.addRow(self.poles.rational)

    def load(self):
        count = len(self.obj.Poles)
        self.poles.fill(self.obj.Poles, list(self.obj.Weights),
                        [translate("P{}").format(k + 1) for k in range(count)])

    def store(self):
        poles, weights = self.poles.poles(), self.poles.weights()
        self.obj.Poles = poles
        self.obj.Weights = weights

    def add_pole(self):
        self.editing()
        poles, weights = list(self.obj.Poles), list(self.obj.Weights)
        step = poles[-1] - poles[-2] if len(poles) > 1 else V(1, 0, 0)
        poles.append(poles[-1] + step)
        if weights:
            weights.append(1.0)
        self.obj.Poles, self.obj.Weights = poles, weights
        self.reload()

    def remove_pole(self):
        poles, weights = list(self.obj.Poles), list(self.obj.Weights)
        if len(poles) <= 2:
            return
        self.editing()
        row = self.poles.table.currentRow()
        index = row if 0 <= row < len(poles) else len(poles) - 1
        del poles[index]
        if weights:
            del weights[index]
        self.obj.Poles, self.obj.Weights = poles, weights
        self.reload()



class BezierSurfacePanel(TaskPanel):
    TITLE, ICON = "RatBez Bézier surface", "RatBez_BezierSurface"

    def build(self):
        self.degrees = []
        for prop in ("DegreeU", "DegreeV"):
            spin = QtGui.QSpinBox()
            spin.setRange(1, features.MAX_OCCT_BEZIER_DEGREE)
            spin.setToolTip(self.tooltip(prop))
            spin.valueChanged.connect(self.degree_changed)
            self.layout.addRow(translate(prop), spin)
            self.degrees.append(spin)
        self.poles = PoleTable(self, self.pole_name)
        self.layout.addRow(self.poles.table)
        self.layout.addRow(self.poles.rational)

    def pole_name(self, row):
        """'P2,3': row 2 (along u) and column 3 (along v) of the net, counted from 1 as in the messages."""
        columns = self.obj.DegreeV + 1
        return "P{},{}".format(row // columns + 1, row % columns + 1)

    def load(self):
        self.degrees[0].setValue(self.obj.DegreeU)
        self.degrees[1].setValue(self.obj.DegreeV)
        self.poles.fill(self.obj.Poles, list(self.obj.Weights),
                        [self.pole_name(k) for k in range(len(self.obj.Poles))])

    def degree_changed(self, *_):
        if self.loading:
            return
        # The feature regenerates a net of the new size over the same extent (BezierSurface.onChanged).
        self.editing()
        self.obj.DegreeU, self.obj.DegreeV = self.degrees[0].value(), self.degrees[1].value()
        self.reload()

    def store(self):
        self.obj.DegreeU, self.obj.DegreeV = self.degrees[0].value(), self.degrees[1].value()
        self.obj.Poles = self.poles.poles()
        self.obj.Weights = self.poles.weights()


PANELS = {
    "RatBez::Cylinder": CylinderPanel,
    "RatBez::Cone": ConePanel,
    "RatBez::Sphere": SpherePanel,
    "RatBez::Torus": TorusPanel,
    "RatBez::Revolve": RevolvePanel,
    "RatBez::Extrude": ExtrudePanel,
    "RatBez::Ruled": RuledPanel,
    "RatBez::Loft": LoftPanel,
    "RatBez::Sweep": SweepPanel,
    "RatBez::BezierCurve": BezierCurvePanel,
    "RatBez::BezierSurface": BezierSurfacePanel,
}

from . import interpolate_panel  # noqa: E402,F401 (registers the Interpolate panel in PANELS)

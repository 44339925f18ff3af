"""View providers of the RatBez features: icons, the profiles, sections and path as tree children, the task
panel on double-click (setEdit), showing them again on delete."""

from . import features, resources
from .i18n import translate

_ICONS = {
    "RatBez::BezierCurve": "RatBez_BezierCurve",
    "RatBez::BezierSurface": "RatBez_BezierSurface",
    "RatBez::Cylinder": "RatBez_Cylinder",
    "RatBez::Cone": "RatBez_Cone",
    "RatBez::Sphere": "RatBez_Sphere",
    "RatBez::Torus": "RatBez_Torus",
    "RatBez::Revolve": "RatBez_Revolve",
    "RatBez::Extrude": "RatBez_Extrude",
    "RatBez::Ruled": "RatBez_Ruled",
    "RatBez::Loft": "RatBez_Loft",
    "RatBez::Sweep": "RatBez_Sweep",
    "RatBez::Interpolate": "RatBez_Interpolate",
}

# Edit mode 0 (Gui::ViewProvider::Default) is the task panel; other modes (Transform, ...) stay FreeCAD's.
_DEFAULT_EDIT = 0


class ViewProviderRatBez:
    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        obj = getattr(self, "Object", None)
        proxy = features.proxy_of(obj)
        name = _ICONS.get(proxy.TYPE if proxy else "", "RatBezWorkbench")
        return resources.icon(name)

    def claimChildren(self):
        return features.linked_objects(getattr(self, "Object", None))

    def onDelete(self, vobj, subelements):
        for child in features.linked_objects(vobj.Object):
            if child.ViewObject is not None:
                child.ViewObject.Visibility = True
        return True

    # -- editing: the task panel ------------------------------------------------------------------

    def setEdit(self, vobj, mode=0):
        if mode != _DEFAULT_EDIT:
            return None  # FreeCAD's own (the transform dragger for Transform)
        from . import task_panels
        return task_panels.open_for(vobj.Object)

    def unsetEdit(self, vobj, mode=0):
        if mode != _DEFAULT_EDIT:
            return None
        from . import task_panels
        task_panels.close_for(vobj.Object)
        return True

    def doubleClicked(self, vobj):
        import FreeCADGui as Gui
        from . import task_panels
        # With another panel open, FreeCAD's setEdit would end that edit without its Cancel: ask first.
        if task_panels.may_edit(vobj.Object):
            Gui.ActiveDocument.setEdit(vobj.Object.Name, _DEFAULT_EDIT)
        return True

    def setupContextMenu(self, vobj, menu):
        from PySide import QtGui
        action = QtGui.QAction(translate("Edit {}").format(vobj.Object.Label), menu)
        action.triggered.connect(lambda: self.doubleClicked(vobj))
        menu.addAction(action)

    def updateData(self, obj, prop):
        pass

    def onChanged(self, vobj, prop):
        pass

    def dumps(self):
        return None

    def loads(self, state):
        return None

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


"""View providers of the RatBez features: icons, the profile as tree child, showing it again on delete."""

import FreeCAD as App

from . import features, resources

_ICONS = {
    "RatBez::BezierCurve": "RatBez_BezierCurve",
    "RatBez::BezierSurface": "RatBez_BezierSurface",
    "RatBez::Cylinder": "RatBez_Cylinder",
    "RatBez::Cone": "RatBez_Cone",
    "RatBez::Sphere": "RatBez_Sphere",
    "RatBez::Torus": "RatBez_Torus",
    "RatBez::Revolve": "RatBez_Revolve",
    "RatBez::Extrude": "RatBez_Extrude",
}


def _profile_object(obj):
    link = getattr(obj, "Profile", None) if obj is not None else None
    return link[0] if link else None


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
        child = _profile_object(getattr(self, "Object", None))
        return [child] if child is not None else []

    def onDelete(self, vobj, subelements):
        child = _profile_object(vobj.Object)
        if child is not None and child.ViewObject is not None:
            child.ViewObject.Visibility = True
        return True

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

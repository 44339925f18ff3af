"""The workbench's user preferences (Edit > Preferences > RatBez), in FreeCAD's parameter tree."""

import os

import FreeCAD as App

PATH = "User parameter:BaseApp/Preferences/Mod/RatBez"


def _params():
    return App.ParamGet(PATH)


def default_tolerance():
    """Chordal tolerance (mm) offered for OpenSCAD export; None: the kernel's automatic choice."""
    value = _params().GetFloat("DefaultTolerance", 0.0)
    return value if value > 0 else None


def set_default_tolerance(value):
    _params().SetFloat("DefaultTolerance", float(value or 0.0))


def export_directory():
    """Folder the OpenSCAD export dialog starts in (the last one used unless set here)."""
    return _params().GetString("ExportDirectory", "") or os.path.expanduser("~")


def set_export_directory(path):
    _params().SetString("ExportDirectory", path or "")


def debug_tracebacks():
    """Whether failed recomputes also print the Python traceback (for developers)."""
    return _params().GetBool("DebugTracebacks", False)


def set_debug_tracebacks(value):
    _params().SetBool("DebugTracebacks", bool(value))


def analytic_primitives():
    """Whether cylinders, cones, spheres and tori go to FreeCAD as Part's analytic primitives (the default)
    rather than as the kernel's rational B-spline faces (conversion.shape_from_solid says why)."""
    return _params().GetBool("AnalyticPrimitives", True)


def set_analytic_primitives(value):
    _params().SetBool("AnalyticPrimitives", bool(value))

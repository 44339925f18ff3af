# RatBez workbench, application part (runs in FreeCAD and in freecadcmd, without a GUI).
#
# Nothing is imported eagerly here: the documents' proxies import ratbez_wb.features on demand, and
# `import RatBez` gives scripts the make_* functions. This file has no __file__ under FreeCAD 0.20.

import FreeCAD

FreeCAD.addExportType("OpenSCAD library of RatBez solids (*.scad)", "RatBez")
FreeCAD.addExportType("3MF of RatBez solids (*.3mf)", "RatBez")

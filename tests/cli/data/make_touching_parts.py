# Makes touching_parts.brep with FreeCAD (freecadcmd tests/cli/data/make_touching_parts.py): a compound of a
# cylinder and a prism whose section is two squares meeting at a corner, so that the solid touches itself along
# an edge, as parts of users' STEP files do (a keyboard's audio jack). OpenCASCADE calls both valid; no 2-manifold
# mesh holds the prism, and `ratbez export` leaves it out with a note (--strict refuses the file).
import os
import sys

sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402
import Part  # noqa: E402
from FreeCAD import Vector as V  # noqa: E402

figure_eight = Part.makePolygon([V(0, 0, 0), V(5, 0, 0), V(5, 5, 0), V(10, 5, 0), V(10, 10, 0), V(5, 10, 0), V(5, 5, 0),
                                 V(0, 5, 0), V(0, 0, 0)])
prism = Part.Face(figure_eight).extrude(V(0, 0, 5))
assert prism.isValid()
Part.makeCompound([Part.makeCylinder(2, 6, V(20, 0, 0)), prism.Solids[0]]).exportBrep(
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "touching_parts.brep"))

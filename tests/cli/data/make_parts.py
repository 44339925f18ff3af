# Makes the model files of the command's tests with FreeCAD (freecadcmd tests/cli/data/make_parts.py), each a
# compound of a cylinder and a solid OpenCASCADE calls valid but whose mesh cannot be handed out, as parts of
# users' STEP files are; `ratbez export` leaves that solid out with a note, and --strict refuses the file:
#  - touching_parts.brep: a prism whose section is two squares meeting at a corner, so that it touches itself along
#    an edge (a keyboard's audio jack): no 2-manifold mesh holds it;
#  - crossing_parts.brep: a bipyramid whose lower apex is pushed up through its upper faces (a part that
#    intersects itself): it meshes, and the export's CGAL check refuses the mesh.
import os
import sys

sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402
import Part  # noqa: E402
from FreeCAD import Vector as V  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def triangle(p, q, r):
    return Part.Face(Part.makePolygon([p, q, r, p]))


def with_a_cylinder(solid, name):
    assert solid.isValid()
    Part.makeCompound([Part.makeCylinder(2, 6, V(20, 0, 0)), solid]).exportBrep(os.path.join(HERE, name))


figure_eight = Part.makePolygon([V(0, 0, 0), V(5, 0, 0), V(5, 5, 0), V(10, 5, 0), V(10, 10, 0), V(5, 10, 0), V(5, 5, 0),
                                 V(0, 5, 0), V(0, 0, 0)])
with_a_cylinder(Part.Face(figure_eight).extrude(V(0, 0, 5)).Solids[0], "touching_parts.brep")

a, b, c, top, bottom = V(0, 0, 0), V(4, 0, 0), V(0, 4, 0), V(1, 1, 3), V(2.5, 2.5, 2)
shell = Part.Shell([triangle(top, a, b), triangle(top, b, c), triangle(top, c, a),
                    triangle(bottom, b, a), triangle(bottom, c, b), triangle(bottom, a, c)])
shell.sewShape()
with_a_cylinder(Part.Solid(shell), "crossing_parts.brep")

"""Export every RatBez solid from FreeCAD to .scad and render it with the real openscad inside a
boolean operation, where CGAL checks the mesh (a bare polyhedron is exported unchecked). openscad
exits 0 even when it drops a broken mesh, so its output is read for ERROR / WARNING; the rendered STL
must also have the solid's volume (Mesh module) to the accuracy of the tessellation.
"""

import math
import os
import subprocess
import sys

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

import FreeCAD as App  # noqa: E402
import Mesh  # noqa: E402
import Part  # noqa: E402

from harness import Suite, check, close  # noqa: E402

import RatBez  # noqa: E402

OUT = os.path.join(os.environ.get("RATBEZ_TEST_OUT", "/tmp"), "openscad")
os.makedirs(OUT, exist_ok=True)
V = App.Vector
PI = math.pi
TOLERANCE = 0.02
suite = Suite()


def render_in_boolean(scad_path, name):
    """Render the module of `scad_path` inside difference(){module(); far tiny cube} to STL; return the STL path
    after checking openscad's output."""
    wrapper = os.path.join(OUT, name + "_check.scad")
    stl = os.path.join(OUT, name + ".stl")
    # The file is a library: `use` imports its module, named after the file's stem.
    module = os.path.splitext(os.path.basename(scad_path))[0]
    with open(wrapper, "w") as f:
        f.write("use <{}>\ndifference() {{\n  {}();\n  translate([1e4, 1e4, 1e4]) cube(0.01);\n}}\n"
                .format(scad_path, module))
    if os.path.exists(stl):
        os.remove(stl)
    result = subprocess.run(["openscad", "-o", stl, wrapper], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, timeout=240)
    output = result.stdout.decode("utf-8", "replace")
    check(result.returncode == 0, "{}: openscad exit {}\n{}".format(name, result.returncode, output))
    for word in ("ERROR", "WARNING"):
        check(word not in output, "{}: openscad printed {}:\n{}".format(name, word, output))
    check(os.path.isfile(stl) and os.path.getsize(stl) > 0, name + ": no STL written\n" + output)
    return stl


def closed_profile_sketch(doc):
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.Placement = App.Placement(V(0, 0, 0), App.Rotation(V(1, 0, 0), 90))
    sketch.addGeometry(Part.LineSegment(V(2, 0, 0), V(4, 0, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(4, 1.5, 0), V(0, 0, 1), 1.5), -PI / 2, PI / 2))
    sketch.addGeometry(Part.LineSegment(V(4, 3, 0), V(2, 3, 0)))
    sketch.addGeometry(Part.LineSegment(V(2, 3, 0), V(2, 0, 0)))
    circle = doc.addObject("Sketcher::SketchObject", "Circle")
    circle.addGeometry(Part.Circle(V(0, 0, 0), V(0, 0, 1), 2))
    doc.recompute()
    return sketch, circle


@suite.test
def test_every_solid_renders_in_openscad():
    doc = App.newDocument("OpenSCAD")
    sketch, circle = closed_profile_sketch(doc)
    solids = [
        RatBez.make_cylinder(doc, Radius=2, Height=5),
        RatBez.make_cone(doc, Radius1=3, Radius2=0, Height=4),
        RatBez.make_sphere(doc, Radius=3),
        RatBez.make_torus(doc, MajorRadius=5, MinorRadius=1.5),
        RatBez.make_revolve(doc, Profile=sketch, Angle=270),
        RatBez.make_extrude(doc, Profile=circle, Distance=3),
    ]
    moved = RatBez.make_sphere(doc, Radius=2)
    moved.Placement = App.Placement(V(20, 0, 0), App.Rotation(V(1, 1, 0), 30))
    doc.recompute()
    solids.append(moved)
    for obj in solids:
        check(obj.isValid(), obj.Label + " invalid")
        scad = os.path.join(OUT, obj.Name + ".scad")
        RatBez.export_openscad(obj, scad, TOLERANCE)
        stl = render_in_boolean(scad, obj.Name)
        mesh = Mesh.Mesh(stl)
        check(mesh.isSolid() and not mesh.hasNonManifolds(), obj.Label + ": rendered mesh not a closed manifold")
        # A chordal tolerance t shifts the surface by at most t: |dV| <= t * area (plus rounding).
        close(mesh.Volume, obj.ExactVolume, 1.5 * TOLERANCE * obj.Shape.Area / obj.ExactVolume + 1e-6,
              obj.Label + " rendered volume")
        centre = mesh.BoundBox.Center
        expected_centre = obj.Shape.optimalBoundingBox().Center
        check((centre - expected_centre).Length < 0.1, "{}: rendered mesh centred at {}, the shape at {}".format(
            obj.Label, centre, expected_centre))


suite.run_and_exit()

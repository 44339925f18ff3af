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


def openscad_log(source, folder, output):
    """Render `source` (written to folder/user.scad) to `output`; returns openscad's output after checking it."""
    with open(os.path.join(folder, "user.scad"), "w") as f:
        f.write(source)
    result = subprocess.run(["openscad", "-o", output, "user.scad"], cwd=folder, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, timeout=240)
    log = result.stdout.decode("utf-8", "replace")
    check(result.returncode == 0 and "ERROR" not in log and "WARNING" not in log, log)
    return log


@suite.test
def test_several_solids_make_one_library_and_one_3mf():
    import zipfile
    doc = App.newDocument("Library")
    peg = RatBez.make_cylinder(doc, Radius=2, Height=10)
    peg.Label = "Peg"
    knob = RatBez.make_sphere(doc, Radius=3, Center=V(0, 0, 10))
    knob.Label = "cube"  # an OpenSCAD built-in: its module gets _solid
    box = doc.addObject("Part::Box", "Box")  # not a RatBez solid: the kernel reads its shape
    box.Label = "Base plate"
    box.Length, box.Width, box.Height = 20, 20, 2
    box.Placement.Base = V(-10, -10, -2)
    doc.recompute()
    folder = os.path.join(OUT, "library")
    os.makedirs(folder, exist_ok=True)
    scad = os.path.join(folder, "parts.scad")
    RatBez.export_openscad([peg, knob, box], scad, TOLERANCE)
    text = open(scad).read()
    for module in ("Peg", "cube_solid", "Base_plate"):
        check("\nmodule {}() {{\npolyhedron(".format(module) in text, module + " module missing")
    check(text.endswith("module parts() {\nPeg();\ncube_solid();\nBase_plate();\n}\nparts();\n"), text[-200:])
    check(text.startswith("// RatBez 'Peg' from FreeCAD, its Placement applied\n// RatBez 'cube' from FreeCAD"), text[:200])
    exact = {"Peg": PI * 4 * 10, "cube_solid": 4 / 3 * PI * 27, "Base_plate": 800.0}
    for module, volume in exact.items():
        stl = os.path.join(folder, module + ".stl")
        openscad_log("use <parts.scad>\ndifference() {{ {}(); translate([1e4, 1e4, 1e4]) cube(0.01); }}\n".format(module),
                     folder, stl)
        close(Mesh.Mesh(stl).Volume, volume, 0.02, module + " rendered volume")
    # The same solids as 3MF: one object each, named after the Labels as they are.
    path = os.path.join(folder, "parts.3mf")
    RatBez.export_3mf([peg, knob, box], path, TOLERANCE)
    model = zipfile.ZipFile(path).read("3D/3dmodel.model").decode()
    for label in ("Peg", "cube", "Base plate"):
        check('name="{}"'.format(label) in model, label + " not a 3MF object")
    stl = os.path.join(folder, "parts_3mf.stl")
    log = openscad_log('difference() { import("parts.3mf"); translate([1e4, 1e4, 1e4]) cube(0.01); }\n', folder, stl)
    check("Simple:        yes" in log, log)
    # The union of the three: the knob overlaps the peg's top, the peg stands on the plate.
    volume = Mesh.Mesh(stl).Volume
    check(800 + PI * 40 < volume < 800 + PI * 40 + 36 * PI, "union volume {}".format(volume))
    # A solid the kernel cannot read (yet) is refused with the object's Label, and nothing is written.
    holed = doc.addObject("Part::Cut", "Holed")
    holed.Base, holed.Tool = doc.addObject("Part::Box", "B2"), doc.addObject("Part::Cylinder", "C2")
    holed.Tool.Placement.Base = V(5, 5, -1)
    doc.recompute()
    try:
        RatBez.export_openscad([peg, holed], os.path.join(folder, "holed.scad"), TOLERANCE)
        readable = True
    except ValueError as error:
        readable = False
        check(str(error).startswith("'Holed': the ratbez kernel cannot read this solid yet: face "), str(error))
        check(not os.path.exists(os.path.join(folder, "holed.scad")), "a refused export left a file")
    print("a Part Cut with a cylindrical hole: {}".format("read by the kernel" if readable else "refused"))


suite.run_and_exit()

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
        close(mesh.Volume, obj.ExactVolume.Value, 1.5 * TOLERANCE * obj.Shape.Area / obj.ExactVolume.Value + 1e-6,
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


@suite.test
def test_solids_in_a_moved_part_export_where_freecad_shows_them():
    """An App::Part container moves what it holds in the 3D view: a RatBez solid and a Part box in a Part turned
    and moved export there, to .scad and STL alike (they were exported at their own Placement alone)."""
    doc = App.newDocument("Container")
    container = doc.addObject("App::Part", "Part")
    peg = RatBez.make_cylinder(doc, Radius=2, Height=10)
    peg.Placement.Base = V(0, 5, 0)
    box = doc.addObject("Part::Box", "Box")
    box.Placement.Base = V(10, 0, 0)
    container.addObject(peg)
    container.addObject(box)
    container.Placement = App.Placement(V(30, 0, 0), App.Rotation(V(0, 0, 1), 90))
    doc.recompute()
    shown = {}
    for obj in (peg, box):
        placed = obj.Shape.copy()
        placed.Placement = obj.getGlobalPlacement()
        shown[obj.Name] = placed.optimalBoundingBox()
    folder = os.path.join(OUT, "container")
    os.makedirs(folder, exist_ok=True)
    for obj in (peg, box):
        scad = os.path.join(folder, obj.Name + ".scad")
        RatBez.export_openscad(obj, scad, TOLERANCE)
        rendered = Mesh.Mesh(render_in_boolean(scad, "container_" + obj.Name)).BoundBox
        expected = shown[obj.Name]
        for got, want in ((rendered.XMin, expected.XMin), (rendered.YMin, expected.YMin), (rendered.ZMax, expected.ZMax),
                          (rendered.XMax, expected.XMax), (rendered.YMax, expected.YMax)):
            check(abs(got - want) <= TOLERANCE, "{} exported at {}, FreeCAD shows it at {}".format(obj.Label, rendered, expected))
    stl = os.path.join(folder, "both.stl")
    RatBez.export_stl([peg, box], stl, TOLERANCE)
    together = Mesh.Mesh(stl).BoundBox
    everything = shown[peg.Name]
    everything.add(shown[box.Name])
    for got, want in ((together.XMin, everything.XMin), (together.YMin, everything.YMin), (together.XMax, everything.XMax),
                      (together.YMax, everything.YMax)):
        check(abs(got - want) <= TOLERANCE, "STL at {}, shown at {}".format(together, everything))


@suite.test
def test_an_object_with_a_solid_the_kernel_cannot_read_is_refused_whole():
    """The kernel's reader reads a file's other solids without one it cannot read; the export of an object the
    user picked holds all its solids or refuses, naming the one and why (not a library short of a part)."""
    doc = App.newDocument("PartlyBroken")
    open_box = Part.Solid(Part.Shell(Part.makeBox(1, 1, 1, V(5, 0, 0)).Faces[:5]))  # no lid: an open shell
    pair = doc.addObject("Part::Feature", "Pair")
    pair.Shape = Part.makeCompound([Part.makeBox(1, 1, 1), open_box])
    doc.recompute()
    try:
        RatBez.export_openscad(pair, os.path.join(OUT, "pair.scad"), TOLERANCE)
        check(False, "an object with an unreadable solid exported")
    except ValueError as error:
        check("'Pair': the ratbez kernel cannot read this solid yet: left out 1 of 2 solids: solid 1: " in str(error) and
              "(the shell is open)" in str(error), str(error))


def freecads_own_solids(doc):
    """Solids FreeCAD makes with its own tools, as users combine them: a Part Cut (a box with a cylindrical hole),
    a Part Fillet, a PartDesign Body (pad, pocket and a revolution), and one Part compound of two solids."""
    holed = doc.addObject("Part::Cut", "Holed")
    holed.Base, holed.Tool = doc.addObject("Part::Box", "B2"), doc.addObject("Part::Cylinder", "C2")
    holed.Tool.Placement.Base = V(5, 5, -1)
    holed.Tool.Height = 12
    rounded = doc.addObject("Part::Box", "B3")
    rounded.Placement.Base = V(20, 0, 0)
    doc.recompute()  # the box first: a Fillet without its edges does not recompute
    filleted = doc.addObject("Part::Fillet", "Filleted")
    filleted.Base, filleted.Edges = rounded, [(i, 1.5, 1.5) for i in range(1, 13)]
    body = doc.addObject("PartDesign::Body", "Body")
    sketch = body.newObject("Sketcher::SketchObject", "PadSketch")
    sketch.Support = (doc.getObject("XY_Plane"), [""])
    sketch.MapMode = "FlatFace"
    corners = [V(0, 0, 0), V(8, 0, 0), V(8, 6, 0), V(0, 6, 0)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(a, b))
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile, pad.Length = sketch, 4
    doc.recompute()
    hole_sketch = body.newObject("Sketcher::SketchObject", "HoleSketch")
    hole_sketch.Support = (pad, ["Face6"])
    hole_sketch.MapMode = "FlatFace"
    hole_sketch.addGeometry(Part.Circle(V(4, 3, 0), V(0, 0, 1), 1.5))
    doc.recompute()
    pocket = body.newObject("PartDesign::Pocket", "Pocket")
    pocket.Profile, pocket.Type = hole_sketch, "ThroughAll"
    body.Placement.Base = V(0, 20, 0)
    pair = doc.addObject("Part::Compound", "Pair")
    sphere, cone = doc.addObject("Part::Sphere", "S4"), doc.addObject("Part::Cone", "K4")
    sphere.Radius, sphere.Placement.Base = 3, V(40, 0, 3)
    cone.Radius1, cone.Radius2, cone.Height, cone.Placement.Base = 3, 1, 5, V(50, 0, 0)
    pair.Links = [sphere, cone]
    doc.recompute()
    for obj in (holed, filleted, body, pair):
        check(obj.isValid() and obj.Shape.isValid(), obj.Label + " did not build in FreeCAD")
    return holed, filleted, body, pair


@suite.test
def test_freecads_own_solids_export_and_check():
    """Part booleans, fillets, a PartDesign Body and a compound export like RatBez solids (issue 24): each
    object's solids become modules rendered clean by openscad with FreeCAD's volume (these are analytic
    faces, where Shape.Volume is exact), one object holding two solids is a library of its own, and "Check
    against OpenCASCADE" reports every solid."""
    doc = App.newDocument("FreeCADSolids")
    objects = freecads_own_solids(doc)
    folder = os.path.join(OUT, "freecad_solids")
    os.makedirs(folder, exist_ok=True)
    scad = os.path.join(folder, "workshop.scad")
    RatBez.export_openscad(list(objects), scad, TOLERANCE)
    text = open(scad).read()
    expected = {"Holed": objects[0].Shape.Volume, "Filleted": objects[1].Shape.Volume,
                "Body": objects[2].Shape.Volume, "Pair_1": objects[3].Shape.Solids[0].Volume,
                "Pair_2": objects[3].Shape.Solids[1].Volume}
    for module, volume in expected.items():
        check("\nmodule {}() {{\n".format(module) in text, module + " module missing")
        stl = os.path.join(folder, module + ".stl")
        openscad_log("use <workshop.scad>\ndifference() {{ {}(); translate([1e4, 1e4, 1e4]) cube(0.01); }}\n"
                     .format(module), folder, stl)
        close(Mesh.Mesh(stl).Volume, volume, 0.01, module + " rendered volume")
    # The compound alone: one object, two solids, still a library (it wrote only the first solid before).
    alone = os.path.join(folder, "pair.scad")
    RatBez.export_openscad(objects[3], alone, TOLERANCE)
    text = open(alone).read()
    check("module Pair_1()" in text and "module Pair_2()" in text, text[-300:])
    check(text.endswith("module pair() {\nPair_1();\nPair_2();\n}\npair();\n"), text[-200:])
    stl = os.path.join(folder, "pair.stl")
    openscad_log("use <pair.scad>\ndifference() { pair(); translate([1e4, 1e4, 1e4]) cube(0.01); }\n", folder, stl)
    close(Mesh.Mesh(stl).Volume, objects[3].Shape.Volume, 0.01, "pair rendered volume")
    path = os.path.join(folder, "pair.3mf")
    RatBez.export_3mf(objects[3], path, TOLERANCE)
    import zipfile
    model = zipfile.ZipFile(path).read("3D/3dmodel.model").decode()
    check('name="Pair_1"' in model and 'name="Pair_2"' in model, "the compound's 3MF objects")
    # Check against OpenCASCADE: every solid of every object, each passing (BOP check included: faces trimmed on a
    # sphere go over on OCCT's sphere, which its self-intersection search leaves out), with FreeCAD's volume.
    for obj in objects:
        reports = RatBez.check_occt_all(obj)
        check(len(reports) == len(obj.Shape.Solids), "{}: {} reports".format(obj.Label, len(reports)))
        for (name, report), solid in zip(reports, obj.Shape.Solids):
            check(report["valid"] and not report["failures"], RatBez.format_check_report(obj, report, name))
            close(report["volume"], solid.Volume, 1e-6, name + " volume")
        text = RatBez.format_check_report(obj, reports[-1][1], reports[-1][0])
        check(text.startswith("RatBez OpenCASCADE check of '{}".format(obj.Label)), text)
    # Progress over all the solids of a compound: each solid's name, and the fraction of the whole (a progress bar).
    told = []
    RatBez.check_occt_all(objects[3], lambda name, fraction: told.append((name, fraction)))
    names = [name for name, _ in told]
    fractions = [fraction for _, fraction in told]
    check(names == sorted(names) and set(names) == {"Pair_1", "Pair_2"} and fractions == sorted(fractions)
          and fractions[-1] == 1 and all(f >= 0.5 for name, f in told if name == "Pair_2")
          and all(f <= 0.5 for name, f in told if name == "Pair_1"), "progress of a compound: {}".format(told))
    check(RatBez.check_occt(objects[0])["valid"], "check_occt of a Part Cut")
    try:
        RatBez.check_occt(objects[3])
        check(False, "check_occt of a compound of two solids did not refuse")
    except ValueError as error:
        check("holds 2 solids: check_occt_all" in str(error), str(error))


suite.run_and_exit()

"""What the Bézier-patch representation (ratbez.brep_string(..., bezier_faces=True), an option) costs and buys,
against one face per kernel face (the default, which the workbench hands FreeCAD for every solid but the
analytic primitives): FreeCAD's Shape.Volume, Shape.Area and CenterOfMass errors, faces, poles, .brep and
.FCStd sizes, and Part Cut times. Every primitive and example (examples/*.json) is measured; each is cut by a
box through its middle and by a sphere (FreeCAD's Part Cut), 5 times, the median time reported.

    freecadcmd bench/freecad_representation.py            (with build/kernel/python on the path)

Prints a Markdown table; timings are measurements, never pass/fail.
"""

import glob
import os
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "build", "kernel", "python"), os.path.join(HERE, "..", "tests", "freecad")]

import FreeCAD as App  # noqa: E402
import Part  # noqa: E402
import ratbez  # noqa: E402

import exact  # noqa: E402


def part_shape(solid, bezier_faces):
    shape = Part.Shape()
    shape.importBrepFromString(ratbez.brep_string(solid, bezier_faces=bezier_faces), False)
    return shape.Solids[0]


def poles(shape):
    total = 0
    for face in shape.Faces:
        surface = face.Surface
        if isinstance(surface, Part.BSplineSurface):
            total += surface.NbUPoles * surface.NbVPoles
    return total


def fcstd_size(shape):
    doc = App.newDocument("Size")
    doc.addObject("Part::Feature", "Shape").Shape = shape
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "shape.FCStd")
        doc.saveAs(path)
        size = os.path.getsize(path)
    App.closeDocument(doc.Name)
    return size


def cut_time(shape):
    box = shape.BoundBox
    tools = [Part.makeBox(box.XLength, box.YLength, box.ZLength / 2,
                          App.Vector(box.XMin + box.XLength / 2, box.YMin - 1, box.ZMin - 1)),
             Part.makeSphere(0.4 * box.DiagonalLength / 2, box.Center + App.Vector(box.XLength / 3, 0, 0))]
    times = []
    for _ in range(5):
        start = time.perf_counter()
        for tool in tools:
            result = shape.cut(tool)
        times.append(time.perf_counter() - start)
    return statistics.median(times), result.isValid()


def relative(a, b):
    return abs(a - b) / abs(b)


def row(name, spec):
    solid = exact.solid(spec)
    volume, area, centre = solid.volume(), solid.area(), exact.centroid(spec)
    cells = []
    for bezier_faces in (False, True):
        shape = part_shape(solid, bezier_faces)
        com = shape.CenterOfMass
        com_error = ((com.x - centre[0]) ** 2 + (com.y - centre[1]) ** 2 + (com.z - centre[2]) ** 2) ** 0.5
        seconds, valid = cut_time(shape)
        cells.append((len(shape.Faces), poles(shape), relative(shape.Volume, volume), relative(shape.Area, area),
                      com_error / shape.BoundBox.DiagonalLength, len(ratbez.brep_string(solid, bezier_faces=bezier_faces)),
                      fcstd_size(shape), seconds * 1000, valid))
    (f0, p0, v0, a0, c0, b0, s0, t0, ok0), (f1, p1, v1, a1, c1, b1, s1, t1, ok1) = cells
    return ("| {} | {} / {} | {} / {} | {:.1e} / {:.1e} | {:.1e} / {:.1e} | {:.1e} / {:.1e} | {:.1f} / {:.1f} | "
            "{:.1f} / {:.1f} | {:.0f} / {:.0f}{} |").format(
        name, f0, f1, p0, p1, v0, v1, a0, a1, c0, c1, b0 / 1024, b1 / 1024, s0 / 1024, s1 / 1024, t0, t1,
        "" if ok0 and ok1 else " (invalid cut)")


def main():
    shapes = [("sphere r=3", {"type": "sphere", "radius": 3}),
              ("cylinder r=2 h=5", {"type": "cylinder", "radius": 2, "height": 5}),
              ("cone 3/1 h=4", {"type": "cone", "radius1": 3, "radius2": 1, "height": 4}),
              ("torus 5/1.5", {"type": "torus", "major_radius": 5, "minor_radius": 1.5})]
    for path in sorted(glob.glob(os.path.join(HERE, "..", "examples", "*.json"))):
        shapes.append(exact.load(path))
    print("| shape | faces | poles | Shape.Volume error | Shape.Area error | CenterOfMass error / size "
          "| .brep KiB | .FCStd KiB | Part Cut ms (2 cuts) |")
    print("|---|---|---|---|---|---|---|---|---|")
    print("| (one face per kernel face / Bézier faces) | | | | | | | | |")
    for name, spec in shapes:
        print(row(name, spec))
        sys.stdout.flush()


main()

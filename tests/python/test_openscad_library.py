"""OpenSCAD libraries (issue 27) with the real openscad binary: names that never shadow OpenSCAD's own
modules, several solids with colour in one library. OpenSCAD exits 0 even when CGAL drops a mesh, so every
render's output is read for WARNING / ERROR."""
import math
import re
import shutil
import subprocess

import pytest

import ratbez
from conftest import needs_cgal, raises_naming

needs_openscad = pytest.mark.skipif(shutil.which("openscad") is None, reason="openscad is not installed")


def render(folder, source):
    """Renders `source` (a user file in `folder`) to ASCII STL; returns (facets, volume)."""
    (folder / "user.scad").write_text(source)
    run = subprocess.run(["openscad", "-o", "out.stl", "user.scad"], cwd=folder, capture_output=True, text=True,
                         timeout=120)
    log = run.stdout + run.stderr
    assert run.returncode == 0 and "WARNING" not in log and "ERROR" not in log, log
    numbers = [float(x) for x in re.findall(r"vertex\s+(\S+)\s+(\S+)\s+(\S+)", (folder / "out.stl").read_text())
               for x in x]
    volume = 0.0
    for k in range(0, len(numbers), 9):
        a, b, c = numbers[k:k + 3], numbers[k + 3:k + 6], numbers[k + 6:k + 9]
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]))
    return len(numbers) // 9, volume / 6


@needs_cgal
def test_explicit_builtin_module_names_are_refused(tmp_path):
    for name in ("cylinder", "sphere", "polyhedron", "import", "len", "for"):
        error = raises_naming("module", ratbez.export_openscad, ratbez.sphere(1), tmp_path / "a.scad", 0.1, module=name)
        assert "OpenSCAD built-in" in str(error)
    raises_naming("solids['cube']", ratbez.export_openscad, {"cube": ratbez.sphere(1)}, tmp_path / "a.scad", 0.1)
    raises_naming("color", ratbez.export_openscad, ratbez.sphere(1), tmp_path / "a.scad", 0.1, color="red")
    assert not (tmp_path / "a.scad").exists()


@needs_cgal
@needs_openscad
def test_a_user_file_keeps_openscads_own_cylinder_and_sphere(tmp_path):
    # Named after the files: cylinder.scad and sphere.scad give cylinder_solid() and sphere_solid().
    ratbez.export_openscad(ratbez.cylinder(5, 20), tmp_path / "cylinder.scad", tolerance=0.05)
    ratbez.export_openscad(ratbez.sphere(10), tmp_path / "sphere.scad", tolerance=0.05)
    assert "module cylinder_solid() {" in (tmp_path / "cylinder.scad").read_text()
    facets, volume = render(tmp_path, "use <cylinder.scad>\nuse <sphere.scad>\n"
                                      "cylinder(r=2, h=12, $fn=32);\ntranslate([10, 0, 0]) sphere(r=1, $fn=16);\n")
    polygon = 0.5 * 32 * 4 * math.sin(2 * math.pi / 32)  # OpenSCAD's own 32-gon of radius 2
    assert volume == pytest.approx(polygon * 12 + 4 / 3 * math.pi, rel=0.05)  # not the r = 5 cylinder, not r = 10
    facets, volume = render(tmp_path, "use <cylinder.scad>\ndifference() { cylinder_solid(); "
                                      "translate([0, 0, -1]) cylinder(r=2, h=12, $fn=64); }\n")
    assert volume == pytest.approx(math.pi * (25 * 20 - 4 * 11), rel=0.01)  # the mesh is within 0.05 of the surface


@needs_cgal
@needs_openscad
def test_two_solid_library_with_colour_renders_each_module_clean(tmp_path):
    solids = {"peg": ratbez.cylinder(2, 10), "knob": ratbez.sphere(3, center=(0, 0, 10))}
    ratbez.export_openscad(solids, tmp_path / "parts.scad", tolerance=0.01, color={"knob": "#ff0000"})
    text = (tmp_path / "parts.scad").read_text()
    assert "// module peg():\n" in text and "// module knob():\n" in text
    assert "module knob() {\ncolor([1,0,0,1])\npolyhedron(" in text
    assert text.endswith("module parts() {\npeg();\nknob();\n}\nparts();\n")
    far = "translate([100, 100, 100]) cube(0.01);"  # a boolean operation makes CGAL check the mesh
    for module, exact in (("peg", math.pi * 40), ("knob", 36 * math.pi)):
        _, volume = render(tmp_path, f"use <parts.scad>\ndifference() {{ {module}(); {far} }}\n")
        assert volume == pytest.approx(exact, rel=0.01), module
    _, volume = render(tmp_path, f"use <parts.scad>\ndifference() {{ parts(); {far} }}\n")
    # The union of both: the ball overlaps the peg's top, so less than the sum, more than either.
    assert 36 * math.pi < volume < math.pi * 40 + 36 * math.pi

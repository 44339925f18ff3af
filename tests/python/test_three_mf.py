"""3MF (issue 27): ratbez.write_3mf through lib3mf, one object per solid with its name and colour, the
version in the model's metadata, and OpenSCAD's import() of the file rendering clean with the real openscad
binary (which links the same lib3MF). OpenSCAD exits 0 even when CGAL drops a mesh, so each render's output
is read for WARNING / ERROR."""
import math
import re
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree
import zipfile

import pytest

import ratbez
from conftest import needs_cgal, raises_naming

needs_openscad = pytest.mark.skipif(shutil.which("openscad") is None, reason="openscad is not installed")
CORE = "{http://schemas.microsoft.com/3dmanufacturing/core/2015/02}"


def model(path):
    """The 3MF's model part: (metadata {name: text}, objects [(name, pid, pindex, vertices, triangles)],
    base materials {(group id, index): (name, displaycolor)})."""
    with zipfile.ZipFile(path) as package:
        root = ElementTree.fromstring(package.read("3D/3dmodel.model"))
    metadata = {m.get("name"): m.text for m in root.iter(CORE + "metadata")}
    materials = {}
    for group in root.iter(CORE + "basematerials"):
        for index, base in enumerate(group.iter(CORE + "base")):
            materials[(group.get("id"), str(index))] = (base.get("name"), base.get("displaycolor"))
    objects = []
    for obj in root.iter(CORE + "object"):
        vertices = [(float(v.get("x")), float(v.get("y")), float(v.get("z"))) for v in obj.iter(CORE + "vertex")]
        triangles = [(int(t.get("v1")), int(t.get("v2")), int(t.get("v3"))) for t in obj.iter(CORE + "triangle")]
        objects.append((obj.get("name"), obj.get("pid"), obj.get("pindex"), vertices, triangles))
    return metadata, objects, materials


def render(folder, source):
    """Renders `source` (a user file in `folder`) to ASCII STL; returns (facets, volume, log)."""
    (folder / "user.scad").write_text(source)
    run = subprocess.run(["openscad", "-o", "out.stl", "user.scad"], cwd=folder, capture_output=True, text=True,
                         timeout=300)
    log = run.stdout + run.stderr
    assert run.returncode == 0 and "WARNING" not in log and "ERROR" not in log, log
    numbers = [float(x) for x in re.findall(r"vertex\s+(\S+)\s+(\S+)\s+(\S+)", (folder / "out.stl").read_text())
               for x in x]
    volume = 0.0
    for k in range(0, len(numbers), 9):
        a, b, c = numbers[k:k + 3], numbers[k + 3:k + 6], numbers[k + 6:k + 9]
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]))
    return len(numbers) // 9, volume / 6, log


def mesh_volume(vertices, triangles):
    six = 0.0
    for i, j, k in triangles:
        a, b, c = vertices[i], vertices[j], vertices[k]
        six += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0]))
    return six / 6


@needs_cgal
def test_one_solid_is_one_named_coloured_object_with_the_version_and_what_was_measured(tmp_path):
    ball = ratbez.sphere(10, center=(1, 2, 3))
    ratbez.write_3mf(ball, tmp_path / "my ball.3mf", tolerance=0.01, color="#ff800080")
    metadata, objects, materials = model(tmp_path / "my ball.3mf")
    assert metadata["Application"] == f"ratbez {ratbez.__version__}"
    assert metadata["Title"] == "my ball"
    description = metadata["Description"]
    assert description.startswith(f"ratbez {ratbez.__version__}, a 3MF file of 1 solid\nsource: Python\nobject my ball:\n")
    assert "coordinates float32 cut to 6 decimals (3MF as lib3mf writes it)" in description
    deviation = float(re.search(r"measured maximum deviation: (\S+)", description).group(1))
    assert 0 < deviation <= 0.01
    [(name, pid, pindex, vertices, triangles)] = objects
    assert name == "my ball"  # any text: 3MF names are not identifiers
    assert materials[(pid, pindex)] == ("my ball", "#FF800080")
    mesh = ball.tessellate(0.01)
    assert len(triangles) == len(mesh.triangles)
    # lib3mf writes 6 decimals; the mesh as written is within the tolerance of the exact volume times area.
    assert mesh_volume(vertices, triangles) == pytest.approx(ball.volume(), abs=0.01 * ball.area())
    assert all(re.fullmatch(r"-?\d+(\.\d{6})?", text) for text in
               re.findall(r'x="([^"]*)"', zipfile.ZipFile(tmp_path / "my ball.3mf").read("3D/3dmodel.model").decode()))
    ratbez.write_3mf(ball, tmp_path / "named.3mf", 0.05, name="Ball, 20 mm")
    assert model(tmp_path / "named.3mf")[1][0][0] == "Ball, 20 mm"
    assert model(tmp_path / "named.3mf")[1][0][1] is None  # no colour, no material


@needs_cgal
def test_the_hosts_locale_survives_lib3mf(tmp_path):
    # lib3mf 1.8.1 sets the C locale to "C" and leaves it so; in FreeCAD that made Python's file encoding
    # ASCII. write_3mf restores the host's locale.
    import locale
    before = locale.setlocale(locale.LC_ALL)
    locale.setlocale(locale.LC_CTYPE, "C.UTF-8")
    changed = locale.setlocale(locale.LC_ALL)
    try:
        ratbez.write_3mf(ratbez.sphere(1), tmp_path / "b\u00e4ll.3mf", 0.1)
        assert locale.setlocale(locale.LC_ALL) == changed
        assert locale.getencoding() == "UTF-8"
    finally:
        locale.setlocale(locale.LC_ALL, before)


@needs_cgal
def test_a_dict_gives_one_object_per_solid_in_order_each_with_its_colour(tmp_path):
    solids = {"peg": ratbez.cylinder(2, 10), "knob": ratbez.sphere(3, center=(0, 0, 10))}
    ratbez.write_3mf(solids, tmp_path / "parts.3mf", tolerance=0.01, color={"knob": "#ff0000"})
    metadata, objects, materials = model(tmp_path / "parts.3mf")
    assert [o[0] for o in objects] == ["peg", "knob"]
    assert objects[0][1] is None
    assert materials[(objects[1][1], objects[1][2])] == ("knob", "#FF0000FF")
    assert metadata["Title"] == "parts"
    assert "\nobject peg:\n  tolerance: 0.01;" in metadata["Description"]
    assert "\nobject knob:\n  tolerance: 0.01;" in metadata["Description"]
    for (_, _, _, vertices, triangles), solid in zip(objects, solids.values()):
        assert mesh_volume(vertices, triangles) == pytest.approx(solid.volume(), abs=0.01 * solid.area())


@needs_cgal
def test_bad_arguments_are_refused_by_name_and_nothing_is_written(tmp_path):
    ball = ratbez.sphere(1)
    raises_naming("path", ratbez.write_3mf, ball, tmp_path / "ball.stl")
    raises_naming("color", ratbez.write_3mf, ball, tmp_path / "ball.3mf", color="red")
    raises_naming("color", ratbez.write_3mf, {"a": ball}, tmp_path / "ball.3mf", color={"b": "#ff0000"})
    raises_naming("name", ratbez.write_3mf, ball, tmp_path / "ball.3mf", name="")
    raises_naming("name", ratbez.write_3mf, {"a": ball}, tmp_path / "ball.3mf", name="x")
    raises_naming("solids", ratbez.write_3mf, {"": ball}, tmp_path / "ball.3mf")
    raises_naming("solids", ratbez.write_3mf, {}, tmp_path / "ball.3mf")
    raises_naming("solid", ratbez.write_3mf, ball.tessellate(0.1), tmp_path / "ball.3mf")
    raises_naming("tolerance", ratbez.write_3mf, ball, tmp_path / "ball.3mf", tolerance=-1)
    # lib3mf's 6 decimals move a 0.02 mm ball's vertices beyond a 1e-6 tolerance: refused, naming 3MF.
    error = raises_naming("mesh", ratbez.write_3mf, ratbez.sphere(0.01), tmp_path / "ball.3mf", tolerance=1e-6)
    assert "3MF, as lib3mf 1.8 writes it, stores float32 coordinates cut to 6 decimals" in str(error)
    assert list(tmp_path.iterdir()) == []


@needs_cgal
@needs_openscad
def test_openscad_imports_the_3mf_with_the_same_triangles_and_renders_it_clean(tmp_path):
    vase = ratbez.revolve(ratbez.BezierCurve([(0, 0, 0), (4, 0, 0), (1, 0, 3), (3, 0, 8), (0, 0, 8)], weights=[1, 1, 2, 1, 1]))
    ratbez.write_3mf(vase, tmp_path / "vase.3mf", tolerance=0.01)
    _, [(_, _, _, vertices, triangles)], _ = model(tmp_path / "vase.3mf")
    written = mesh_volume(vertices, triangles)
    # Bare: OpenSCAD passes the imported mesh through, triangle for triangle.
    facets, volume, log = render(tmp_path, 'import("vase.3mf");\n')
    assert facets == len(triangles) == len(vase.tessellate(0.01).triangles)
    assert volume == pytest.approx(written, rel=2e-5)
    # In a boolean operation CGAL checks it: closed, 2-manifold, outward ("Simple: yes", no warnings).
    far = "translate([100, 100, 100]) cube(0.01);"
    facets, volume, log = render(tmp_path, f'difference() {{ import("vase.3mf"); {far} }}\n')
    assert "Simple:        yes" in log
    assert volume == pytest.approx(written, rel=2e-5)
    assert volume == pytest.approx(vase.volume(), abs=0.01 * vase.area())


@needs_cgal
@needs_openscad
def test_openscad_imports_a_two_object_3mf_clean(tmp_path):
    solids = {"peg": ratbez.cylinder(2, 10), "knob": ratbez.sphere(3, center=(0, 0, 10))}
    ratbez.write_3mf(solids, tmp_path / "parts.3mf", tolerance=0.01, color={"knob": "#ff0000"})
    # OpenSCAD 2021.01 imports every object of the file and unites them.
    _, volume, log = render(tmp_path, 'difference() { import("parts.3mf"); translate([50, 0, 0]) cube(1); }\n')
    assert "Simple:        yes" in log
    assert 36 * math.pi < volume < 40 * math.pi + 36 * math.pi  # the ball overlaps the peg's top

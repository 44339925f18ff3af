"""One version for the project (issue 27): CMake's `project(ratbez VERSION ...)` is the source; the Python
module, the `ratbez` command, the FreeCAD workbench's package.xml and the headers of the .scad and .3mf files
written must say the same."""
import os
import pathlib
import re
import subprocess

import ratbez

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cmake_version():
    match = re.search(r"project\(ratbez VERSION (\d+\.\d+\.\d+)", (ROOT / "CMakeLists.txt").read_text())
    assert match, "CMakeLists.txt has no project(ratbez VERSION x.y.z)"
    return match.group(1)


def test_python_module_has_the_cmake_version():
    assert ratbez.__version__ == cmake_version()


def test_workbench_package_xml_has_the_cmake_version():
    text = (ROOT / "freecad_workbench" / "RatBez" / "package.xml").read_text()
    assert re.findall(r"<version>([^<]*)</version>", text) == [cmake_version()]


def test_command_prints_the_version():
    build = pathlib.Path(os.environ.get("RATBEZ_BUILD_DIR", ROOT / "build"))
    command = build / "cli" / "ratbez"
    run = subprocess.run([str(command), "--version"], capture_output=True, text=True, timeout=60)
    assert (run.returncode, run.stdout, run.stderr) == (0, f"ratbez {cmake_version()}\n", "")


def test_written_files_name_the_cmake_version(tmp_path):
    import zipfile
    if not getattr(ratbez, "has_cgal", False):
        return
    ratbez.export_openscad(ratbez.sphere(1), tmp_path / "ball.scad", 0.1)
    assert (tmp_path / "ball.scad").read_text().startswith(f"// ratbez {cmake_version()}, an OpenSCAD library file\n")
    ratbez.export_openscad({"a": ratbez.sphere(1), "b": ratbez.sphere(1, center=(3, 0, 0))}, tmp_path / "lib.scad", 0.1)
    assert (tmp_path / "lib.scad").read_text().startswith(f"// ratbez {cmake_version()}, an OpenSCAD library file of 2 solids\n")
    ratbez.write_3mf(ratbez.sphere(1), tmp_path / "ball.3mf", 0.1)
    model = zipfile.ZipFile(tmp_path / "ball.3mf").read("3D/3dmodel.model").decode()
    assert f'<metadata name="Application">ratbez {cmake_version()}</metadata>' in model
    assert f"ratbez {cmake_version()}, a 3MF file of 1 solid" in model

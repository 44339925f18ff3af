"""One version for the project (issue 27): CMake's `project(ratbez VERSION ...)` is the source; the Python
module, the `ratbez` command and the FreeCAD workbench's package.xml must say the same."""
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

"""The module imports inside FreeCAD's own Python (freecadcmd), and its B-rep reaches Part intact."""
import os
import pathlib
import shutil
import subprocess
import textwrap

import pytest

import ratbez

FREECADCMD = shutil.which("freecadcmd") or shutil.which("FreeCADCmd")

SCRIPT = textwrap.dedent(
    """
    import os, sys, traceback
    try:
        sys.path.insert(0, os.environ["RATBEZ_MODULE_DIR"])
        import ratbez
        assert os.path.dirname(ratbez.__file__) == os.environ["RATBEZ_MODULE_DIR"], ratbez.__file__
        solid = ratbez.sphere(2.0)
        assert abs(solid.volume() - 32.0 / 3.0 * 3.141592653589793) < 1e-8
        if ratbez.has_occt:
            import Part
            shape = Part.Shape()
            shape.importBrepFromString(ratbez.brep_string(solid))
            assert shape.isValid(), "Part reports the imported B-rep invalid"
            assert len(shape.Solids) == 1, shape.ShapeType
            assert abs(shape.Volume / solid.volume() - 1) < 1e-2, shape.Volume
        with open(os.environ["RATBEZ_RESULT"], "w") as result:
            result.write("ok")
    except BaseException:
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)  # freecadcmd exits 0 on an uncaught exception
    """
)


@pytest.mark.skipif(FREECADCMD is None, reason="freecadcmd is not installed")
def test_import_inside_freecad(tmp_path):
    script = tmp_path / "import_ratbez.py"
    script.write_text(SCRIPT)
    result = tmp_path / "result.txt"
    env = dict(os.environ)
    env["RATBEZ_MODULE_DIR"] = str(pathlib.Path(ratbez.__file__).resolve().parent)
    env["RATBEZ_RESULT"] = str(result)
    env["FREECAD_USER_HOME"] = str(tmp_path)  # keep FreeCAD's config out of the user's home
    env.pop("PYTHONPATH", None)  # the script finds the module by itself
    run = subprocess.run([FREECADCMD, str(script)], env=env, stdin=subprocess.DEVNULL, capture_output=True,
                         text=True, timeout=300)
    output = run.stdout + run.stderr
    assert run.returncode == 0, output
    assert result.exists() and result.read_text() == "ok", output

#!/usr/bin/python3
"""The `freecad` install component puts the whole Mod folder and the compiled module side by side.

    test_install.py CMAKE BUILD_DIR MOD_DIR

Installs into a temporary DESTDIR (never the real system), then checks the files, and that the
installed module and workbench import together in a plain /usr/bin/python3 with FreeCAD's libs.
"""

import glob
import os
import subprocess
import sys
import tempfile


def main():
    cmake, build, mod_dir = sys.argv[1:4]
    with tempfile.TemporaryDirectory(prefix="ratbez-install-") as destdir:
        env = dict(os.environ, DESTDIR=destdir)
        subprocess.run([cmake, "--install", build, "--component", "freecad"], env=env, check=True)
        root = destdir + mod_dir
        failures = []
        for name in ("Init.py", "InitGui.py", "RatBez.py", "package.xml", "ratbez_wb/features.py",
                     "ratbez_wb/commands.py", "ratbez_wb/conversion.py", "Resources/icons/RatBezWorkbench.svg",
                     "Resources/icons/RatBez_Cylinder.svg", "Resources/icons/RatBez_CheckOCCT.svg",
                     "Resources/icons/preferences-ratbez.svg", "Resources/translations/RatBez.ts",
                     "Resources/translations/RatBez_en.qm", "Resources/translations/RatBez_de.qm", "LICENSE",
                     "README.md"):
            if not os.path.isfile(os.path.join(root, name)):
                failures.append("missing " + name)
        modules = glob.glob(os.path.join(root, "ratbez*.so"))
        if len(modules) != 1:
            failures.append("expected one compiled ratbez module in {}, found {}".format(root, modules))
        if glob.glob(os.path.join(root, "**", "__pycache__"), recursive=True):
            failures.append("__pycache__ installed")
        if not failures:
            probe = ("import sys; sys.path[:0] = [{!r}, '/usr/lib/freecad-python3/lib'];"
                     "import ratbez; s = ratbez.sphere(1.0); assert abs(s.volume() - 4.18879020478639) < 1e-9;"
                     "import FreeCAD, RatBez; assert callable(RatBez.make_cylinder); print('import ok')").format(root)
            result = subprocess.run(["/usr/bin/python3", "-c", probe], stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
            print(result.stdout.decode())
            if result.returncode != 0:
                failures.append("installed module does not import")
        for failure in failures:
            print("FAIL:", failure)
        print("PASSED" if not failures else "FAILED")
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

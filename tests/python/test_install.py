"""The `python` install component: cmake --install into a fresh venv (made with --system-site-packages,
so numpy comes from Debian), then `import ratbez` from a new interpreter of that venv, outside the build
tree and without PYTHONPATH. CTest sets RATBEZ_BUILD_DIR; run by hand with it set to the build directory."""
import os
import shutil
import subprocess
import sys

import pytest

BUILD_DIR = os.environ.get("RATBEZ_BUILD_DIR")


@pytest.mark.skipif(not BUILD_DIR, reason="RATBEZ_BUILD_DIR not set (CTest sets it)")
def test_install_into_a_venv(tmp_path):
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", str(venv)], check=True)
    subprocess.run([shutil.which("cmake") or "cmake", "--install", BUILD_DIR, "--component", "python",
                    "--prefix", str(venv)], check=True, capture_output=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    script = ("import ratbez, sys; s = ratbez.sphere(2.0); "
              "print(ratbez.__file__); print(s.tessellate(1e-2).is_closed())")
    result = subprocess.run([str(venv / "bin" / "python"), "-c", script], cwd=tmp_path, env=env,
                            capture_output=True, text=True, check=True)
    installed, closed = result.stdout.split()
    assert installed.startswith(str(venv)), installed
    assert closed == "True"
    # The stub-only package beside it, for type checkers.
    stubs = list(venv.glob("lib/python*/site-packages/ratbez-stubs/__init__.pyi"))
    assert len(stubs) == 1 and "class Solid" in stubs[0].read_text()

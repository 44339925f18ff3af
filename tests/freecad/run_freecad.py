#!/usr/bin/python3
"""Run one FreeCAD test script against the build-tree RatBez workbench, isolated from the user's home.

    run_freecad.py --stage BUILD/freecad/Mod/RatBez --out DIR [--gui] [--timeout S] SCRIPT

A temporary directory becomes FreeCAD's user data (with Mod/RatBez -> the staged Mod folder) and
home, so the test sees exactly this build's workbench and leaves nothing behind. freecadcmd exits 0
even on an uncaught exception, so success needs BOTH exit status 0 AND the line RATBEZ_TEST_PASSED
in the output; a hang is killed after the timeout.
"""

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile

PASS_MARKER = "RATBEZ_TEST_PASSED"
FAIL_MARKER = "RATBEZ_TEST_FAILED"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--stage", required=True, help="staged Mod/RatBez folder of the build")
    parser.add_argument("--out", required=True, help="directory for the test's output files")
    parser.add_argument("--gui", action="store_true", help="run the full GUI under xvfb-run")
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("script")
    args = parser.parse_args()

    stage = os.path.abspath(args.stage)
    if not os.path.isfile(os.path.join(stage, "InitGui.py")):
        print("run_freecad: {} is not a staged RatBez Mod folder (build target "
              "ratbez_freecad_stage)".format(stage))
        return 1
    os.makedirs(args.out, exist_ok=True)
    root = tempfile.mkdtemp(prefix="ratbez-freecad-")
    try:
        data = os.path.join(root, "data")
        home = os.path.join(root, "home")
        os.makedirs(os.path.join(data, "Mod"))
        os.makedirs(home)
        os.symlink(stage, os.path.join(data, "Mod", "RatBez"))
        env = dict(os.environ)
        env.update({
            "FREECAD_USER_DATA": data + "/",
            "FREECAD_USER_HOME": home,
            "HOME": home,
            "PYTHONDONTWRITEBYTECODE": "1",
            "RATBEZ_TEST_OUT": os.path.abspath(args.out),
            "RATBEZ_TEST_DIR": os.path.dirname(os.path.abspath(args.script)),
            "QTWEBENGINE_DISABLE_SANDBOX": "1",
            "LC_ALL": "C.UTF-8",
        })
        script = os.path.abspath(args.script)
        if args.gui:
            command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad", script]
        else:
            command = ["freecadcmd", script]
        # A session of its own: a hang is killed with everything it started (xvfb-run leaves FreeCAD and Xvfb
        # running when only it is killed).
        process = subprocess.Popen(command, env=env, cwd=root, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        try:
            stdout, _ = process.communicate(timeout=args.timeout)
            output = stdout.decode("utf-8", "replace")
            status = process.returncode
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            stdout, _ = process.communicate()
            output = stdout.decode("utf-8", "replace")
            output += "\nrun_freecad: TIMEOUT after {} s\n".format(args.timeout)
            status = -1
        sys.stdout.write(output)
        passed = status == 0 and PASS_MARKER in output and FAIL_MARKER not in output
        print("run_freecad: exit status {}, {}".format(status, "PASSED" if passed else "FAILED"))
        return 0 if passed else 1
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())

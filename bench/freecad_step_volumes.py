"""FreeCAD's Shape.Volume, Area and CenterOfMass errors on the STEP files ratbez writes, for every example and
every corpus solid (tests/freecad/step_volumes.py measures them; tests/freecad/test_step_in_freecad.py holds
them to 1e-4).

    freecadcmd bench/freecad_step_volumes.py            (with build/kernel/python on the path)

Prints a Markdown table.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "build", "kernel", "python"), os.path.join(HERE, "..", "tests", "freecad")]

import step_volumes  # noqa: E402


def cell(value):
    return "-" if value is None else "{:.1e}".format(value)


print("| solid (written by ratbez, read by FreeCAD) | faces | Shape.Volume error | Shape.Area error | "
      "CenterOfMass error / size |")
print("|---|---|---|---|---|")
for row in step_volumes.measurements():
    print("| {} | {} | {} | {} | {} |".format(row["name"], row["faces"], cell(row["volume_error"]),
                                               cell(row["area_error"]), cell(row["centre_error"])))

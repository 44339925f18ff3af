"""Issue 25, item 1: FreeCAD reads the STEP files ratbez writes with the right Shape.Volume, Area and
CenterOfMass (OpenCASCADE's fixed Gauss rule, which FreeCAD's measurements, Measure and Check geometry use):
every example and every corpus solid written by ratbez.write_step and read back by FreeCAD (step_volumes.py
measures them; bench/freecad_step_volumes.py prints the table). Headless, through run_freecad.py.

Every example is within 1e-4 of the kernel's certified values (closed-form centres where they exist). Corpus
solids with a trimmed face on an arc surface (a cylinder or sphere cut by a boolean: the kernel holds its
surface in the NURBS Book's circle form, degree 2 with double knots, so C0 in its parameter inside the face,
which one Gauss rule over the face reads slowly; only untrimmed faces go over in the one-span arc form, whose
parameter a trimmed face's p-curves cannot follow exactly) are listed in BEYOND; the list is strict both
ways, and they stay within 1e-2.
"""

import os
import sys

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

from harness import Suite, check, say  # noqa: E402

import step_volumes  # noqa: E402

WITHIN = 1e-4
LOOSE = 1e-2
# Corpus solids FreeCAD reads beyond WITHIN (largest of the three errors, measured with FreeCAD 0.20.2).
BEYOND = {
    "corpus/cylinder_cut_cylinder": 1.6e-3,
    "corpus/fused_cylinders": 1.5e-3,
    "corpus/partdesign_revolution": 7.6e-4,
    "corpus/shipped_boxtest[1]": 7.2e-4,
    "corpus/shipped_boxtest[5]": 1.0e-3,
    "corpus/shipped_boxtest[7]": 1.0e-3,
    "corpus/shipped_test_path_tool_bit_shape_00": 7.2e-4,
    "corpus/sphere_minus_box": 2.5e-3,
}
suite = Suite()


@suite.test
def test_freecad_reads_ratbez_step_files_with_the_right_measures():
    rows = step_volumes.measurements()
    check(sum(row["name"].startswith("examples/") for row in rows) >= 9, "examples not found")
    check(sum(row["name"].startswith("corpus/") for row in rows) >= 30, "corpus not found")
    problems = []
    for row in rows:
        name = row["name"]
        if row["solids"] != 1:
            problems.append("{}: FreeCAD read {} solids back".format(name, row["solids"]))
            continue
        worst = max(e for e in (row["volume_error"], row["area_error"], row["centre_error"]) if e is not None)
        say("   {:45s} volume {:.1e}  area {:.1e}  centre {}".format(
            name, row["volume_error"], row["area_error"],
            "-" if row["centre_error"] is None else "{:.1e}".format(row["centre_error"])))
        if name in BEYOND:
            if worst <= WITHIN:
                problems.append("{}: within {:g} now ({:.1e}); remove it from BEYOND".format(name, WITHIN, worst))
            elif worst > LOOSE:
                problems.append("{}: {:.1e}, beyond even {:g}".format(name, worst, LOOSE))
        elif worst > WITHIN:
            problems.append("{}: FreeCAD measures it {:.1e} off".format(name, worst))
    unknown = set(BEYOND) - {row["name"] for row in rows}
    check(not unknown, "BEYOND names no solid: {}".format(sorted(unknown)))
    check(not problems, "\n".join(problems))


suite.run_and_exit()

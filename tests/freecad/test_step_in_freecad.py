"""Issue 25, item 1: FreeCAD reads the STEP files ratbez writes with the right Shape.Volume, Area and
CenterOfMass (OpenCASCADE's fixed Gauss rule, which FreeCAD's measurements, Measure and Check geometry use):
every example and every corpus solid written by ratbez.write_step and read back by FreeCAD (step_volumes.py
measures them; bench/freecad_step_volumes.py prints the table). Headless, through run_freecad.py.

Every one is within 1e-6 of the kernel's certified values (the issue asks 1e-4; closed-form centres for the
examples, FreeCAD's own reading of the corpus file for its solids): the largest is 2e-7, a corpus solid with a
face trimmed on a cylinder, which write_step splits at its surface's C0 knots (kernel/occt/src/c0_split.hpp);
whole, such faces read up to 2.5e-3 off.
"""

import os
import sys

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

from harness import Suite, check, say  # noqa: E402

import step_volumes  # noqa: E402

WITHIN = 1e-6
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
        errors = {"volume": row["volume_error"], "area": row["area_error"], "centre": row["centre_error"]}
        say("   {:45s} {}".format(name, "  ".join("{} {}".format(k, "-" if e is None else "{:.1e}".format(e))
                                                  for k, e in errors.items())))
        problems += ["{}: FreeCAD's {} is {:.1e} off".format(name, k, e) for k, e in errors.items()
                     if e is not None and e > WITHIN]
    check(not problems, "\n".join(problems))


suite.run_and_exit()

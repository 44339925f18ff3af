"""Issue 25, item 1: FreeCAD reads the STEP files ratbez writes with the right Shape.Volume, Area and
CenterOfMass (OpenCASCADE's fixed Gauss rule, which FreeCAD's measurements, Measure and Check geometry use):
every example and every corpus solid written by ratbez.write_step and read back by FreeCAD (step_volumes.py
measures them; bench/freecad_step_volumes.py prints the table). Headless, through run_freecad.py.

Every one is within 1e-6 of the kernel's certified values (the issue asks 1e-4; closed-form centres for the
examples, FreeCAD's own reading of the corpus file for its solids), or of a read solid whose faces go back on
the file's cylinders, cones and tori, within 4 times FreeCAD's error on its own reading of the file (OCCT's rule
takes 18 points across such a face: cylinder_cut_cylinder 3.5e-6, FreeCAD's reading of it 1.6e-6). A face trimmed
on a cylinder that stays a B-spline is split at its surface's C0 knots (kernel/occt/src/c0_split.hpp); whole,
such faces read up to 2.5e-3 off.
"""

import os
import sys

sys.path.insert(0, os.environ.get("RATBEZ_TEST_DIR", os.path.dirname(os.path.abspath(__file__))))

from harness import Suite, check, say  # noqa: E402

import step_volumes  # noqa: E402

WITHIN = 1e-6
ISSUE = 1e-4       # issue 25's bound
OWN_READING = 4    # times FreeCAD's error on its own reading of a corpus file
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
        # A solid read from a file goes back with its faces on the file's cylinders, cones and tori where it
        # can (kernel/occt/src/elementary_faces.hpp), which OCCT's rule reads as it reads FreeCAD's own reading of
        # the file (18 points across such a face): as close as that, within the issue's 1e-4 in any case.
        own = {"volume": row.get("own_volume_error"), "area": row.get("own_area_error")}
        problems += ["{}: FreeCAD's {} is {:.1e} off{}".format(
                         name, k, e, "" if own.get(k) is None else " (its own reading of the file: {:.1e})".format(own[k]))
                     for k, e in errors.items()
                     if e is not None and (e > ISSUE or e > max(WITHIN, OWN_READING * (own.get(k) or 0)))]
    check(not problems, "\n".join(problems))


suite.run_and_exit()

"""FreeCAD reading the STEP files ratbez writes (issue 25, item 1): every example (examples/*.json) and every
solid of the corpus (tests/corpus/freecad/*.step, made by FreeCAD), written by ratbez.write_step and read back
by FreeCAD (Part.read), measured by FreeCAD's Shape.Volume, Area and CenterOfMass (OpenCASCADE's fixed Gauss
rule) against the kernel's certified volume and area and against the centre of mass of the source: the
examples' closed forms (exact.centroid; none for ruled solids, lofts and sweeps), and FreeCAD's own reading of
the corpus solids (from the .brep FreeCAD wrote beside each STEP file). Used by tests/freecad/test_step_in_freecad.py and bench/freecad_step_volumes.py."""

import glob
import os
import tempfile

import FreeCAD as App
import Part
import ratbez

import exact

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples")
CORPUS = os.path.join(HERE, "..", "corpus", "freecad")


def _relative(measured, exact_value):
    return abs(measured - exact_value) / abs(exact_value)


def _read_back(solid, folder):
    path = os.path.join(folder, "solid.step")
    ratbez.write_step(solid, path)
    shape = Part.read(path)
    return shape.Solids


def measurements():
    """One dict per solid: name, faces (FreeCAD's), volume_error, area_error (relative), centre_error
    (relative to the bounding box's diagonal; None without a reference), solids (that FreeCAD read back), and for a
    corpus solid own_volume_error, own_area_error: FreeCAD's reading of the corpus file itself (None otherwise)."""
    sources = []
    for path in sorted(glob.glob(os.path.join(EXAMPLES, "*.json"))):
        name, spec = exact.load(path)
        centre = exact.centroid(spec)
        sources.append(("examples/" + name, exact.solid(spec),
                        None if centre is None else App.Vector(*(float(c) for c in centre)), None))
    for path in sorted(glob.glob(os.path.join(CORPUS, "*.step"))):
        stem = os.path.splitext(os.path.basename(path))[0]
        # The centres from FreeCAD's .brep of the same solids: OpenCASCADE's STEP reader reads FreeCAD's own
        # sphere_minus_box_off_axis.step as the eighth of the sphere in the box (ratbez reads it as written).
        brep = os.path.splitext(path)[0] + ".brep"
        theirs = (Part.read(brep) if os.path.exists(brep) else Part.read(path)).Solids
        ours = ratbez.read_step_all(path)
        for k, solid in enumerate(ours):
            own = theirs[k] if len(theirs) == len(ours) else None
            sources.append(("corpus/{}{}".format(stem, "" if len(ours) == 1 else "[{}]".format(k)), solid,
                            None if own is None else own.CenterOfMass, own))
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for name, solid, centre, own in sources:
            solids = _read_back(solid, folder)
            row = {"name": name, "solids": len(solids), "faces": None, "volume_error": None, "area_error": None,
                   "centre_error": None,
                   # FreeCAD's measures of its own reading of the corpus file: as far as its rule reads the file's
                   # own surfaces (cylinders, cones, tori trimmed by p-curves; ours go back on the same surfaces).
                   "own_volume_error": None if own is None else _relative(own.Volume, solid.volume()),
                   "own_area_error": None if own is None else _relative(own.Area, solid.area())}
            if len(solids) == 1:
                shape = solids[0]
                row["faces"] = len(shape.Faces)
                row["volume_error"] = _relative(shape.Volume, solid.volume())
                row["area_error"] = _relative(shape.Area, solid.area())
                if centre is not None:
                    row["centre_error"] = (shape.CenterOfMass - centre).Length / shape.BoundBox.DiagonalLength
            rows.append(row)
    return rows

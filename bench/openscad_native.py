"""Triangles of our meshes against OpenSCAD's own at equal measured deviation: the real openscad renders
sphere(r, $fn = N) and rotate_extrude($fn = n) translate([R, 0]) circle(r, $fn = m) to STL, the project's
dense measurement (ratbez.max_deviation) reads how far each strays from the exact solid, and the search
keeps the fewest triangles whose deviation is within the tolerance; beside it, ratbez's mesh of the same
solid at that tolerance. Writes one JSON of rows that bench/report.py turns into the "native" rows.

  native/<case>/openscad   triangles, deviation and the $fn found (the sphere also as OpenSCAD users
                           straddle it: scale(2R / (2R - d)) sphere($fn))
  native/<case>/ours       triangles and deviation of solid.tessellate(tolerance)
  native/minkowski/<ours|openscad>   seconds of openscad rendering minkowski() { cube([20, 20, 5],
                           center = true); scale(0.2) ball(); } with ratbez's exported sphere r = 10 at 0.01
                           as ball(), and with sphere(r = 2, $fn) at the $fn found for it (equal deviation)

Usage: python3 bench/openscad_native.py BUILD_DIR OUT_JSON   (skips, writing no rows, without openscad)
"""

import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

CASES = (("sphere_r10_tol0.01", 0.01), ("sphere_r10_tol0.01_straddled", 0.01), ("torus_R10_r3_tol0.01", 0.01))


def read_ascii_stl(ratbez, text):
    """The mesh of an ASCII STL, its vertices welded by their exact printed coordinates."""
    index, vertices, triangles, corner = {}, [], [], []
    for line in text.splitlines():
        words = line.split()
        if not words or words[0] != "vertex":
            continue
        key = tuple(float(w) for w in words[1:4])
        if key not in index:
            index[key] = len(vertices)
            vertices.append(key)
        corner.append(index[key])
        if len(corner) == 3:
            triangles.append(corner)
            corner = []
    return ratbez.Mesh(vertices, triangles)


def native(ratbez, folder, source):
    """Renders OpenSCAD `source` and returns its mesh."""
    scad, stl = os.path.join(folder, "native.scad"), os.path.join(folder, "native.stl")
    with open(scad, "w") as f:
        f.write(source)
    subprocess.run(["openscad", "-o", stl, scad], check=True, capture_output=True, timeout=120)
    with open(stl) as f:
        return read_ascii_stl(ratbez, f.read())


def fewest(measure, low, high):
    """The smallest n in [low, high] with measure(n) within the tolerance (measure: n -> (ok, mesh, deviation)),
    by bisection: the deviation of these inscribed meshes falls as n grows."""
    best = measure(high)
    assert best[0], "the upper end of the search is too coarse"
    while high - low > 1:
        middle = (low + high) // 2
        trial = measure(middle)
        if trial[0]:
            high, best = middle, trial
        else:
            low = middle
    return high, best


def sphere_case(ratbez, folder, tolerance):
    solid, r = ratbez.sphere(10.0), 10.0

    def measure(fn):
        mesh = native(ratbez, folder, f"sphere(r = {r}, $fn = {fn});\n")
        deviation = ratbez.max_deviation(solid, mesh)
        return deviation <= tolerance, mesh, deviation

    chord = math.pi / math.acos(1 - tolerance / r)  # segments for the sag alone
    fn, (_, mesh, deviation) = fewest(measure, 3, int(chord * 1.5) + 4)
    return solid, {"triangles": len(mesh.triangles), "deviation": deviation, "fn": fn}


def straddled_sphere_case(ratbez, folder, tolerance):
    """OpenSCAD's own straddling trick: sphere($fn = N) scaled by 2R / (2R - d), d its measured inward
    deviation, so that its vertices sit d/2 outside and its faces d/2 inside; the fewest N within the
    tolerance (issue 28: the fair comparison, beside the naive $fn)."""
    solid, r = ratbez.sphere(10.0), 10.0

    def measure(fn):
        inward = ratbez.max_deviation(solid, native(ratbez, folder, f"sphere(r = {r}, $fn = {fn});\n"))
        scale = 2 * r / (2 * r - inward)
        mesh = native(ratbez, folder, f"scale({scale!r}) sphere(r = {r}, $fn = {fn});\n")
        deviation = ratbez.max_deviation(solid, mesh)
        return deviation <= tolerance, mesh, deviation

    chord = math.pi / math.acos(1 - tolerance / r)
    fn, (_, mesh, deviation) = fewest(measure, 3, int(chord * 1.5) + 4)
    return solid, {"triangles": len(mesh.triangles), "deviation": deviation, "fn": f"{fn}, scaled"}


def torus_case(ratbez, folder, tolerance):
    R, r = 10.0, 3.0
    solid = ratbez.torus(R, r)

    def around(m):
        def measure(n):
            mesh = native(ratbez, folder,
                          f"rotate_extrude($fn = {n}) translate([{R}, 0]) circle(r = {r}, $fn = {m});\n")
            deviation = ratbez.max_deviation(solid, mesh)
            return deviation <= tolerance, mesh, deviation
        return measure

    # The tube's sag takes a share of the tolerance, the ring's the rest: try tube counts from a little above
    # the one that spends all of it on the tube upward, each with its fewest ring count (coarser tubes leave
    # the ring nothing; much finer ones cost more than they save).
    tube_alone = math.pi / math.acos(1 - tolerance / r)
    best = None
    ring_alone = math.pi / math.acos(1 - tolerance / (R + r))
    for m in range(int(tube_alone * 1.1) + 1, int(tube_alone * 1.8) + 2, 3):
        try:
            n, (_, mesh, deviation) = fewest(around(m), int(ring_alone), int(ring_alone * 4) + 4)
        except AssertionError:
            continue
        if best is None or len(mesh.triangles) < best["triangles"]:
            best = {"triangles": len(mesh.triangles), "deviation": deviation, "fn": f"{m} x {n}"}
    return solid, best


def rendering_seconds(folder, source, files=()):
    """Wall time of openscad rendering `source` to STL (its convex fast paths or not), best of two."""
    scad, stl = os.path.join(folder, "timed.scad"), os.path.join(folder, "timed.stl")
    with open(scad, "w") as f:
        f.write(source)
    best = math.inf
    for _ in range(2):
        start = time.perf_counter()
        subprocess.run(["openscad", "-o", stl, scad], check=True, capture_output=True, timeout=1800)
        best = min(best, time.perf_counter() - start)
    return best


def minkowski_case(ratbez, folder, fn):
    """Issue 28: minkowski() of a box and a ball, the ball ratbez's (convex since the hull) or OpenSCAD's."""
    ratbez.export_openscad(ratbez.sphere(10.0), os.path.join(folder, "ball.scad"), 0.01)
    box = "cube([20, 20, 5], center = true);"
    ours = rendering_seconds(folder, f"use <ball.scad>\nminkowski() {{ {box} scale(0.2) ball(); }}\n")
    theirs = rendering_seconds(folder, f"minkowski() {{ {box} sphere(r = 2, $fn = {fn}); }}\n")
    return ({"name": "native/minkowski/ours", "seconds": ours},
            {"name": "native/minkowski/openscad", "seconds": theirs, "fn": fn})


def main(build, out):
    sys.path.insert(0, os.path.join(build, "kernel", "python"))
    import ratbez

    rows = []
    if shutil.which("openscad") is None:
        print("openscad_native.py: no openscad on PATH, no rows", file=sys.stderr)
    else:
        with tempfile.TemporaryDirectory() as folder:
            for (name, tolerance), case in zip(CASES, (sphere_case, straddled_sphere_case, torus_case)):
                solid, theirs = case(ratbez, folder, tolerance)
                ours = solid.tessellate(tolerance)
                rows.append({"name": f"native/{name}/openscad", "tolerance": tolerance, **theirs})
                rows.append({"name": f"native/{name}/ours", "tolerance": tolerance, "triangles": len(ours.triangles),
                             "deviation": ratbez.max_deviation(solid, ours)})
                print(rows[-2], rows[-1], file=sys.stderr)
            sphere_fn = next(r["fn"] for r in rows if r["name"] == "native/sphere_r10_tol0.01/openscad")
            rows.extend(minkowski_case(ratbez, folder, sphere_fn))
            print(rows[-2], rows[-1], file=sys.stderr)
    with open(out, "w") as f:
        json.dump({"context": {"openscad": shutil.which("openscad") or ""}, "benchmarks": rows}, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

#!/usr/bin/env python3
"""Renders docs/loft_alignment.png, the README's picture of a ruled loft before and after alignment (issue 26):
a circle r = 2 at z = 0 (starting at +X) ruled to a 3 x 3 square at z = 4 (starting at its SW corner).

Left: what ratbez built before issue 26, point u of the circle ruled to point u of the square (the surface
`ratbez.ruled_surface(circle, square, align=False)` now refuses: it pinches near the square's corners, volume
18.6). Right: `ratbez.ruled_surface(circle, square)`, matched by arc length from the start of least twist
(the loft's volume 43.09, OpenCASCADE's ruled ThruSections 43.16). Side surfaces only, tessellated to 0.005,
drawn by OpenSCAD:

    PYTHONPATH=build/kernel/python /usr/bin/python3 docs/loft_alignment.py [out.png]
"""
import os
import subprocess
import sys
import tempfile

import ratbez

HERE = os.path.dirname(os.path.abspath(__file__))
CORNERS = [(-1.5, -1.5, 4), (1.5, -1.5, 4), (1.5, 1.5, 4), (-1.5, 1.5, 4)]


def square():
    """The square from its SW corner as one degree-2 curve on the circle's knots (each side's midpoint
    between its corners: the sides elevated to degree 2)."""
    points = []
    for k in range(4):
        a, b = CORNERS[k], CORNERS[(k + 1) % 4]
        points += [a, tuple((x + y) / 2 for x, y in zip(a, b))]
    points.append(CORNERS[0])
    return ratbez.NurbsCurve(2, ratbez.circle(2.0).knots, points)


def unaligned(circle, top):
    """The ruled surface point u to point u (what align=False builds, without the check that refuses it)."""
    return ratbez.NurbsSurface(circle.degree, 1, circle.knots, [0, 0, 1, 1],
                               [[p, q] for p, q in zip(circle.points, top.points)],
                               [[w, 1.0] for w in circle.weights])


def polyhedron(mesh, shift):
    points = ",".join("[{:.5f},{:.5f},{:.5f}]".format(x + shift, y, z) for x, y, z in mesh.vertices)
    faces = ",".join("[{},{},{}]".format(a, c, b) for a, b, c in mesh.triangles)  # OpenSCAD: clockwise
    return "polyhedron(points=[{}], faces=[{}]);\n".format(points, faces)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "loft_alignment.png")
    circle, top = ratbez.circle(2.0), square()
    before = unaligned(circle, top).tessellate(0.005)
    after = ratbez.ruled_surface(circle, top).tessellate(0.005)
    with tempfile.TemporaryDirectory() as folder:
        scad = os.path.join(folder, "loft_alignment.scad")
        with open(scad, "w") as f:
            f.write("color([0.85, 0.45, 0.25]) " + polyhedron(before, -3.2))
            f.write("color([0.25, 0.55, 0.85]) " + polyhedron(after, 3.2))
        subprocess.run(["xvfb-run", "-a", "openscad", "--imgsize=1200,600", "--camera=0,0,2,62,0,25,24",
                        "--colorscheme=Tomorrow", "-o", out, scad], check=True)
    print(out)


if __name__ == "__main__":
    main()

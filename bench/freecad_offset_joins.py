"""Part Offset and Thickness of ruled solids: RatBez beside Part's own tools, with both joins (issue 25).

Part's Offset (makeOffsetShape) and Thickness (makeThickness, the top face removed) of the ruled solids of
ruled_and_loft_solids.py (circle to triangle and to square, the polygon at heights 2, 4 and 6), at -0.5, -0.3,
0.3 and 0.5 with the Arc and the Intersection join, each in a child process: OpenCASCADE 7.6.3 crashes on some of
them (a null edge in BRepOffset_Inter2d::ConnexIntByInt, with the Intersection join), Part's own Loft included.
Each result is judged as a FreeCAD user would meet it:

- clean: one valid solid that Part > Check geometry with BOP check passes;
- BOP-flagged: valid, but the BOP check finds self-intersections or too small edges;
- invalid: BRepCheck rejects the result (or it is empty);
- raised: OpenCASCADE raises (FreeCAD reports the error);
- crashed: the process dies (FreeCAD would).

    freecadcmd bench/freecad_offset_joins.py     (with build/kernel/python on the path; about 10 minutes)

Prints a Markdown table of the counts per solid and tool, then every case where a RatBez result is worse than
Part Loft's. Nothing here is pass/fail.
"""

import collections
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "build", "kernel", "python"),
                os.path.join(HERE, "..", "freecad_workbench", "RatBez")]

from ruled_and_loft_solids import solids  # noqa: E402

HEIGHTS = (2.0, 4.0, 6.0)
DISTANCES = (-0.5, -0.3, 0.3, 0.5)
JOINS = {"Arc": 0, "Intersection": 2}
OPERATIONS = ("offset", "thickness")
VERDICTS = ("clean", "BOP-flagged", "invalid", "raised", "crashed")
RANK = {verdict: rank for rank, verdict in enumerate(VERDICTS)}

# The child: FreeCAD's Part in Debian's python (FreeCAD's own interpreter), one operation on one BREP file.
CHILD = r'''
import sys
sys.path.append("/usr/lib/freecad/lib")
import FreeCAD, Part
shape = Part.Shape()
shape.read(sys.argv[1])
operation, distance, join = sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
try:
    if operation == "offset":
        result = shape.makeOffsetShape(distance, 1e-7, False, False, 0, join, False)
    else:
        top = max(shape.Faces, key=lambda face: face.CenterOfMass.z)
        result = shape.makeThickness([top], distance, 1e-7, False, False, 0, join)
except Exception:
    print("raised")
    sys.exit()
if not result.isValid() or len(result.Solids) != 1 or abs(result.Volume) < 1e-9:
    print("invalid")
    sys.exit()
try:
    result.check(True)
    print("clean")
except Exception:
    print("BOP-flagged")
'''


def verdict(path, operation, distance, join):
    try:
        run = subprocess.run(["/usr/bin/python3", "-c", CHILD, path, operation, repr(distance), str(join)],
                             capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return "crashed"  # a hang is as bad for a user
    said = run.stdout.split()
    return said[-1] if run.returncode == 0 and said and said[-1] in VERDICTS else "crashed"


def main():
    counts = collections.defaultdict(collections.Counter)
    found = {}
    with tempfile.TemporaryDirectory() as folder:
        for kind in ("ruled 3", "ruled 4"):
            for height in HEIGHTS:
                for tool, shape in solids(kind, height):
                    path = os.path.join(folder, "solid.brep")
                    shape.exportBrep(path)
                    for operation in OPERATIONS:
                        for join_name, join in JOINS.items():
                            for distance in DISTANCES:
                                case = (kind, height, operation, join_name, distance)
                                found[case + (tool,)] = said = verdict(path, operation, distance, join)
                                counts[(kind, tool)][said] += 1
    print("| solid | tool | " + " | ".join(VERDICTS) + " |")
    print("|---|---|" + "---|" * len(VERDICTS))
    for (kind, tool), counted in counts.items():
        print("| {} | {} | ".format(kind, tool) + " | ".join(str(counted[v]) for v in VERDICTS) + " |")
    print("\nWhere RatBez's result is worse than Part Loft's:")
    for case in sorted({key[:-1] for key in found}):
        ours, loft = found[case + ("RatBez",)], found[case + ("Part Loft",)]
        if RANK[ours] > RANK[loft]:
            kind, height, operation, join_name, distance = case
            print("- {} at height {:g}, {} {:+g} with the {} join: RatBez {}, Part Loft {}".format(
                kind, height, operation, distance, join_name, ours, loft))
    sys.stdout.flush()


main()

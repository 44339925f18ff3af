"""Part Chamfer and Fillet across sizes on ruled solids and lofts: RatBez beside Part's own tools (issue 25).

tests/freecad/test_part_operations.py holds every kind of RatBez solid to Part's result at one size. This measures
how far that carries: each size from 0.02 to 0.98 in steps of 0.02 on every sharp edge at once, on

- the RatBez Ruled and Loft objects of the workbench (RatBez.make_ruled / make_loft of the same Part wires),
- Part Loft of the same sections (Ruled for the ruled solids), and
- for the ruled solids, Part's other tool for them, Ruled Surface: makeRuledSurface of each arc of the circle with
  the side of the polygon it faces, and the two caps, sewn. Its surfaces are Part Loft's to 1e-7 (the same
  volume), in another representation,

each with the polygon (the loft's middle section) at heights 2, 4 and 6.

A size "works" when the tool returns one valid solid. Part's two tools disagree with each other at some sizes on
the same surfaces, and RatBez's ruled surface is another one (the exact rational arc ruled to the side, where
Part's rules OpenCASCADE's polynomial approximation of the arc by angle: 0.5 % apart in volume), so the sets are
reported side by side, not compared for equality. Nothing here is pass/fail.

Why the sets differ (traced with a ChFi3d_ChBuilder subclass around PerformThreeCorner): where a ruling meets the
circle, three sharp edges meet at a point where the two arcs of the rim are tangent. OCCT chains tangent edges into
one fillet only when every other edge at the vertex is smooth (ChFi3d_Builder::FaceTangency), and the ruling is
sharp, so each arc gets its own stripe and the corner goes to PerformThreeCorner, which must intersect the two
arcs' traces on the cap: two curves that touch tangentially there, intersected at Precision::PIntersection
(ChFi3d_IntTraces). Whether the touch is found ("FD en vis a vis non trouvees" when not) depends on rounding in
the traces, so it comes and goes with the representation: on the same surfaces Part's Loft and Ruled Surface
differ at 13 to 17 sizes of the square's chamfer. Raising the degree or the spans of the side faces, rulings
uniform in v, the rims as B-splines or with compact p-curves each moved the failing sizes about without reducing
their number over the three heights.

    freecadcmd bench/freecad_edge_tool_sizes.py       (with build/kernel/python on the path; about 15 minutes)

Prints a Markdown table: per solid, height, tool and operation, the number of sizes that work and the sizes that
fail; then the totals over the heights.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "build", "kernel", "python"),
                os.path.join(HERE, "..", "tests", "freecad"), os.path.join(HERE, "..", "freecad_workbench", "RatBez")]

from ruled_and_loft_solids import KINDS, solids  # noqa: E402
from sharp_edges import sharp_edges  # noqa: E402  (as tests/freecad/test_part_operations.py picks them)

SIZES = [d / 100 for d in range(2, 100, 2)]
HEIGHTS = (2.0, 4.0, 6.0)  # of the polygon (the loft's middle section)


def works(shape, operation, size):
    edges = sharp_edges(shape)
    try:
        result = shape.makeChamfer(size, edges) if operation == "chamfer" else shape.makeFillet(size, edges)
    except Exception:  # OpenCASCADE's "command not done" and the like
        return False
    return result.isValid() and len(result.Solids) == 1


def main():
    totals = {}
    print("| solid | height | tool | volume | operation | sizes that work, of {} | sizes that fail |".format(len(SIZES)))
    print("|---|---|---|---|---|---|---|")
    for kind in KINDS:
        for height in HEIGHTS:
            for tool, shape in solids(kind, height):
                for operation in ("chamfer", "fillet"):
                    failing = [size for size in SIZES if not works(shape, operation, size)]
                    totals[kind, tool, operation] = totals.get((kind, tool, operation), 0) + len(SIZES) - len(failing)
                    print("| {} | {:g} | {} | {:.4f} | {} | {} | {} |".format(
                        kind, height, tool, shape.Volume, operation, len(SIZES) - len(failing),
                        ", ".join("{:g}".format(size) for size in failing) or "-"))
                    sys.stdout.flush()
    print()
    print("| solid | tool | operation | sizes that work, of {} |".format(len(SIZES) * len(HEIGHTS)))
    print("|---|---|---|---|")
    for (kind, tool, operation), works_at in totals.items():
        print("| {} | {} | {} | {} |".format(kind, tool, operation, works_at))


main()

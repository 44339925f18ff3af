"""The one table of scripts/bench.sh: every benchmark row with ours / OpenCASCADE ratios and its target.

Reads the Google Benchmark JSON files that bench.sh writes (one per program, medians of the
repetitions) and prints one row per comparison. A program that wrote no file (none of its benchmarks
matched BENCH_FILTER) has no rows. Each section is a function of the loaded results, so a section can be
added without touching the others.

Usage: python3 bench/report.py RESULTS_DIR CORES
"""

import json
import os
import sys

PROGRAMS = ("evaluation", "tessellation", "profile_check", "properties", "modelling", "export", "python", "native")


def load(results, program):
    """(context, {run name: median row}) of one program's JSON, or ({}, {}) when it did not run."""
    try:
        with open(os.path.join(results, program + ".json")) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return {}, {}
    rows = {}
    for b in data.get("benchmarks", []):
        if b.get("aggregate_name", "median") != "median":
            continue
        rows[b.get("run_name", b["name"])] = b
    return data.get("context", {}), rows


def seconds(b):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
    return b["cpu_time"] * scale


def si(x):
    for unit, factor in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if abs(x) >= factor:
            return f"{x / factor:.3g}{unit}"
    return f"{x:.3g}"


def faster_or_slower(ours, theirs):
    """Our time against OCCT's, in words: "4.1x faster" or "3.1x slower"."""
    return f"{theirs / ours:.1f}x faster" if theirs >= ours else f"{ours / theirs:.1f}x slower"


def against_occt(rows, occt_name):
    """(name parts, ours, OCCT's) for every "<kind>/<shape>/ours[/<size>]" whose OCCT twin ran too."""
    for name, b in rows.items():
        parts = name.split("/")
        if len(parts) < 3 or parts[2] != "ours":
            continue
        o = rows.get("/".join(parts[:2] + [occt_name] + parts[3:]))
        if o is not None:
            yield parts, b, o


class Table:
    def __init__(self):
        self.rows = [("benchmark", "ours", "OCCT", "ours/OCCT", "target", "status")]
        self.verdicts = []

    def row(self, *cells, verdict=None):
        if verdict is not None:
            self.verdicts.append(verdict)
        cells = tuple(str(c) for c in cells)
        self.rows.append(cells + ("",) * (len(self.rows[0]) - len(cells)))

    def print(self, header):
        widths = [max(len(r[i]) for r in self.rows) for i in range(len(self.rows[0]))]
        print()
        print(header)
        for k, r in enumerate(self.rows):
            print("  ".join(c.ljust(w) if i == 0 else c.rjust(w) for i, (c, w) in enumerate(zip(r, widths))))
            if k == 0:
                print("  ".join("-" * w for w in widths))
        print(f"\n{self.verdicts.count('PASS')} targets met, {self.verdicts.count('FAIL')} missed")


def evaluation_runs(rows, program):
    """(base "eval/<shape>/<D>", grid size n, row) for every "eval/<shape>/<D>/<program>/<n>"."""
    for name, b in rows.items():
        parts = name.split("/")
        if len(parts) >= 5 and parts[3] == program:
            yield "/".join(parts[:3]), parts[4], b


def evaluation_rows(table, rows):
    """Points per second, ours against GeomAdaptor_Surface (the target) and Geom_BSplineSurface."""
    for base, n, b in evaluation_runs(rows, "ours"):
        ours = b["points_per_second"]
        for other, target in (("GeomAdaptor_Surface", 3.0), ("Geom_BSplineSurface", None)):
            o = rows.get(f"{base}/{other}/{n}")
            if o is None:
                continue
            ratio = ours / o["points_per_second"]
            status = "" if target is None else ("PASS" if ratio >= target else "FAIL")
            table.row(f"{base} {n}x{n} vs {other}", si(ours) + " pt/s", si(o["points_per_second"]) + " pt/s",
                      f"{ratio:.1f}x", ">= 3x" if target else "", status, verdict=status or None)
        p, a = rows.get(f"{base}/ours_portable/{n}"), rows.get(f"{base}/GeomAdaptor_Surface/{n}")
        if p and a:
            table.row(f"{base} {n}x{n} portable(SSE2) vs GeomAdaptor", si(p["points_per_second"]) + " pt/s",
                      si(a["points_per_second"]) + " pt/s", f"{p['points_per_second'] / a['points_per_second']:.1f}x")


def tessellation_rows(table, rows):
    """Speed-up over BRepMesh, triangle counts, deviation against the tolerance."""
    for parts, b, o in against_occt(rows, "BRepMesh"):
        if parts[0] != "tess":
            continue
        speedup = seconds(o) / seconds(b)
        label = f"tess/{parts[1]} tol 1e-{parts[3]}"
        ok = speedup >= 10 and b["triangles"] <= o["triangles"] and b["deviation_over_tolerance"] <= 1
        status = "PASS" if ok else "FAIL"
        table.row(label + " time", f"{seconds(b) * 1e3:.3g} ms", f"{seconds(o) * 1e3:.3g} ms",
                  f"{speedup:.2f}x faster", ">= 10x", status, verdict=status)
        table.row(label + " triangles", si(b["triangles"]), si(o["triangles"]),
                  f"{b['triangles'] / o['triangles']:.2f}", "<= 1", "")
        table.row(label + " deviation/tol", f"{b['deviation_over_tolerance']:.3f}",
                  f"{o['deviation_over_tolerance']:.3f}", "", "ours <= 1", "")


def corpus_rows(table, rows):
    """Issue 24: every corpus model (solids made by FreeCAD) meshed by us and by BRepMesh at 1e-3 of its size:
    time, triangles and the two-sided deviation of both meshes measured the same way. Targets: faster, fewer
    triangles, never over the tolerance (BRepMesh's overshoot is shown, not judged)."""
    for parts, b, o in against_occt(rows, "BRepMesh"):
        if parts[0] != "corpus":
            continue
        speedup = seconds(o) / seconds(b)
        ok = speedup >= 1 and b["triangles"] <= o["triangles"] and b["deviation_over_tolerance"] <= 1
        status = "PASS" if ok else "FAIL"
        label = f"corpus/{parts[1]} tol 1e-3 of size"
        table.row(label + " time", f"{seconds(b) * 1e3:.3g} ms", f"{seconds(o) * 1e3:.3g} ms",
                  faster_or_slower(seconds(b), seconds(o)), "faster", status, verdict=status)
        table.row(label + " triangles", si(b["triangles"]), si(o["triangles"]),
                  f"{b['triangles'] / o['triangles']:.2f}", "<= 1", "")
        table.row(label + " deviation/tol", f"{b['deviation_over_tolerance']:.3f}",
                  f"{o['deviation_over_tolerance']:.3f}", "", "ours <= 1", "")


def bound_rows(table, rows):
    """Issue 17's sphere (r = 10, tolerance 0.01): triangles against the fewest any inscribed mesh needs (4,837);
    the target is that bound, the issue's must 5,400."""
    for name, b in rows.items():
        parts = name.split("/")
        if parts[0] != "bound" or "bound" not in b:
            continue
        ok = b["triangles"] <= b["bound"] and b["deviation_over_tolerance"] <= 1
        status = "PASS" if ok else "FAIL"
        table.row(f"{parts[1]} triangles vs inscribed bound", si(b["triangles"]), "-",
                  f"{b['triangles'] / b['bound']:.2f} of {b['bound']:.0f}", "<= bound (must: 5400)", status,
                  verdict=status)
        table.row(f"{parts[1]} deviation/tol", f"{b['deviation_over_tolerance']:.3f}", "-", "", "<= 1", "")
        # Issue 28: a mesh within the tolerance both ways may sag 2 x tol where centred on the surface, so the
        # limit is half the inscribed bound; its target 3,400 triangles is 0.70 of the inscribed bound.
        limit = b["bound"] / 2
        target = 3400
        status = "PASS" if b["triangles"] <= target else "FAIL"
        table.row(f"{parts[1]} triangles vs straddling limit", si(b["triangles"]), "-",
                  f"{b['triangles'] / limit:.2f} of {limit:.0f}", f"<= {target}", status, verdict=status)


def profile_rows(table, rows):
    """Revolve's and extrude's crossing test against BRepCheck_Analyzer on the same cap face."""
    for parts, b, o in against_occt(rows, "BRepCheck"):
        table.row(f"profile/{parts[1]} ({b['spans']:.0f} spans) check vs BRepCheck_Analyzer(cap)",
                  f"{seconds(b) * 1e6:.3g} us", f"{seconds(o) * 1e6:.3g} us", faster_or_slower(seconds(b), seconds(o)))


def properties_rows(table, rows):
    """Volume and area against BRepGProp (its fixed rule, then Eps 1e-12), with each answer's error."""
    for occt_name in ("BRepGProp", "BRepGProp_eps"):
        for parts, b, o in against_occt(rows, occt_name):
            label = f"{parts[0]}/{parts[1]} vs {occt_name}"
            table.row(label + " time", f"{seconds(b) * 1e6:.3g} us", f"{seconds(o) * 1e6:.3g} us",
                      faster_or_slower(seconds(b), seconds(o)))
            table.row(label + " relative error", f"{b['relative_error']:.1e}", f"{o['relative_error']:.1e}", "")


def modelling_rows(table, rows):
    """Lofts against ThruSections and sweeps against MakePipeShell on the same input: time, control points,
    volume error against the closed form, the tubes' deviation from the true sweep (its target: the
    tolerance in the shape's name, e.g. helix_1e-4), and BRepCheck validity (the target: ours valid)."""
    for occt_name in ("ThruSections", "MakePipeShell"):
        for parts, b, o in against_occt(rows, occt_name):
            label = f"{parts[0]}/{parts[1]} vs {occt_name}"
            table.row(label + " time", f"{seconds(b) * 1e3:.3g} ms", f"{seconds(o) * 1e3:.3g} ms",
                      faster_or_slower(seconds(b), seconds(o)))
            table.row(label + " control points", si(b["control_points"]), si(o["control_points"]),
                      f"{b['control_points'] / o['control_points']:.2f}")
            table.row(label + " volume error", f"{b['volume_error']:.1e}", f"{o['volume_error']:.1e}", "")
            if "deviation" in b and "deviation" in o:
                tolerance = float(parts[1].rsplit("_", 1)[1]) if "_1e-" in parts[1] else None
                status = "" if tolerance is None else ("PASS" if b["deviation"] <= tolerance else "FAIL")
                table.row(label + " deviation", f"{b['deviation']:.1e}", f"{o['deviation']:.1e}", "",
                          f"ours <= {tolerance:g}" if tolerance else "", status, verdict=status or None)
            status = "PASS" if b["valid"] == 1 else "FAIL"
            table.row(label + " valid (BRepCheck)", "yes" if b["valid"] == 1 else "no", "yes" if o["valid"] == 1 else "no",
                      "", "ours valid", status, verdict=status)


def export_rows(table, rows):
    """Writing meshes has no OCCT counterpart: triangles per second against the target."""
    for name, b in rows.items():
        parts = name.split("/")
        rate = b["triangles_per_second"]
        target = 2e6 if parts[1] == "scad" else None
        status = "" if target is None else ("PASS" if rate >= target else "FAIL")
        table.row(f"export/{parts[1]} {si(float(parts[2]))} triangles", si(rate) + " tri/s", "-",
                  f"{rate / target:.2f} of target" if target else "", ">= 2M tri/s" if target else "", status,
                  verdict=status or None)


def python_rows(table, rows):
    """Bulk evaluation through Python (bench/python_evaluation.py) against OCCT's GeomAdaptor_Surface and the C++
    grid evaluator, all measured in that script's run. D0 is held to >= 100M points/s and >= 4x GeomAdaptor,
    D1 (the point and both partials in one evaluate_partials call) to >= 40M points/s."""
    for base, n, b in evaluation_runs(rows, "python"):
        rate = b["points_per_second"]
        adaptor, cpp = rows.get(f"{base}/GeomAdaptor_Surface/{n}"), rows.get(f"{base}/ours/{n}")
        d0 = base.endswith("/D0")
        ratio = rate / adaptor["points_per_second"] if adaptor else None
        ok = rate >= (100e6 if d0 else 40e6) and (not d0 or (ratio is not None and ratio >= 4))
        status = "PASS" if ok else "FAIL"
        table.row(f"python {base} {n}x{n} vs GeomAdaptor", si(rate) + " pt/s",
                  si(adaptor["points_per_second"]) + " pt/s" if adaptor else "-",
                  f"{ratio:.1f}x" if ratio is not None else "", ">= 100M pt/s, >= 4x" if d0 else ">= 40M pt/s",
                  status, verdict=status)
        if cpp:
            table.row(f"python {base} {n}x{n} vs C++ grid", si(rate) + " pt/s", "-",
                      f"{rate / cpp['points_per_second']:.2f} of C++ {si(cpp['points_per_second'])} pt/s")


def native_rows(table, rows):
    """Triangles against OpenSCAD's own sphere($fn) / rotate_extrude($fn) meshes at equal measured deviation
    (bench/openscad_native.py; the "OCCT" column holds OpenSCAD's): ours must need fewer, both within the
    tolerance."""
    for name, b in rows.items():
        parts = name.split("/")
        if len(parts) != 3 or parts[2] != "ours" or f"native/{parts[1]}/openscad" not in rows:
            continue
        o = rows[f"native/{parts[1]}/openscad"]
        ok = b["triangles"] < o["triangles"] and b["deviation"] <= b["tolerance"] and o["deviation"] <= o["tolerance"]
        status = "PASS" if ok else "FAIL"
        table.row(f"native/{parts[1]} triangles vs OpenSCAD $fn {o['fn']}", si(b["triangles"]), si(o["triangles"]),
                  f"{b['triangles'] / o['triangles']:.2f}", "< 1", status, verdict=status)
        table.row(f"native/{parts[1]} deviation/tol", f"{b['deviation'] / b['tolerance']:.3f}",
                  f"{o['deviation'] / o['tolerance']:.3f}", "", "both <= 1", "")


def minkowski_rows(table, rows):
    """Issue 28: OpenSCAD's minkowski() of a box and our exported ball against the same with its own
    sphere($fn) at equal deviation: our convex mesh keeps OpenSCAD's convex fast path (within 5x)."""
    ours, theirs = rows.get("native/minkowski/ours"), rows.get("native/minkowski/openscad")
    if not ours or not theirs:
        return
    ratio = ours["seconds"] / theirs["seconds"]
    status = "PASS" if ratio <= 5 else "FAIL"
    table.row(f"native/minkowski box + ball vs sphere($fn = {theirs['fn']})", f"{ours['seconds']:.3g} s",
              f"{theirs['seconds']:.3g} s", f"{ratio:.2f}", "<= 5", status, verdict=status)


SECTIONS = (("evaluation", evaluation_rows), ("tessellation", tessellation_rows), ("tessellation", corpus_rows),
            ("tessellation", bound_rows),
            ("profile_check", profile_rows),
            ("properties", properties_rows), ("modelling", modelling_rows), ("export", export_rows),
            ("python", python_rows), ("native", native_rows), ("native", minkowski_rows))


def main(results, cores):
    loaded = {program: load(results, program) for program in PROGRAMS}
    context = next((c for c, _ in loaded.values() if c), {})
    table = Table()
    for program, section in SECTIONS:
        section(table, loaded[program][1])
    table.print(f"ratbez benchmarks: nproc = {cores}, single-threaded, CPU time medians; "
                f"grid kernels: {context.get('ratbez_grid_kernels', '?')}; "
                f"CPU {context.get('mhz_per_cpu', '?')} MHz, load average {context.get('load_avg', '?')}")
    return table


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: report.py RESULTS_DIR CORES")
    main(sys.argv[1], sys.argv[2])

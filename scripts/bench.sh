#!/usr/bin/env bash
# Builds the project as scripts/setup.sh does (the normal Release build in build/ includes bench/),
# runs the benchmark programs (evaluation, tessellation, the profile check and volume/area against
# OpenCASCADE in the same run, export alone) and prints ONE table: every row with ours / OCCT ratios and the target it is held to.
#
# Times are CPU times of the (single-threaded) benchmark thread, the median of the repetitions: on a
# shared machine wall time also counts other processes' turns. Google Benchmark's JSON is kept in
# build/bench-results/ for anything the table leaves out.
#
# Usage: bash scripts/bench.sh [--no-build]
# Environment: RATBEZ_JOBS (build parallelism, default 2), BENCH_REPETITIONS (default 3),
#              BENCH_MIN_TIME (seconds per repetition, default 0.5), BENCH_FILTER (a regex on names).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec </dev/null

build="${RATBEZ_BUILD_DIR:-build}"
results="$build/bench-results"
jobs="${RATBEZ_JOBS:-2}"
repetitions="${BENCH_REPETITIONS:-3}"
min_time="${BENCH_MIN_TIME:-0.5}"
filter="${BENCH_FILTER:-.}"

if [ "${1:-}" != "--no-build" ]; then
  RATBEZ_JOBS="$jobs" bash scripts/setup.sh >&2  # installs what is missing, builds build/ (bench included)
fi

mkdir -p "$results"
rm -f "$results"/*.json
for program in evaluation tessellation profile_check properties export; do
  echo "== bench_$program" >&2
  "$build/bench/bench_$program" --benchmark_filter="$filter" --benchmark_repetitions="$repetitions" \
    --benchmark_min_time="$min_time" --benchmark_report_aggregates_only=true \
    --benchmark_out="$results/$program.json" --benchmark_out_format=json >&2
done

/usr/bin/python3 - "$results" "$(nproc)" <<'PYTHON'
import json, os, sys

results, cores = sys.argv[1], sys.argv[2]

def load(program):
    # A program none of whose benchmarks matched BENCH_FILTER writes no JSON: it has no rows.
    path = os.path.join(results, program + ".json")
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return {}, {}
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        rows[b["run_name"] if "run_name" in b else b["name"]] = b
    return data["context"], rows

def seconds(b):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
    return b["cpu_time"] * scale

def si(x):
    for unit, factor in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if abs(x) >= factor:
            return f"{x / factor:.3g}{unit}"
    return f"{x:.3g}"

def against_occt(results, occt_name):
    """(name parts, ours, OCCT's) for every "<kind>/<shape>/ours[/<size>]" whose OCCT twin ran too."""
    for name, b in results.items():
        parts = name.split("/")
        if parts[2] != "ours":
            continue
        o = results.get("/".join(parts[:2] + [occt_name] + parts[3:]))
        if o is not None:
            yield parts, b, o

def speed(ours, theirs):
    """Ours against OCCT's time, in words: "4.1x faster" or "3.1x slower"."""
    return f"{theirs / ours:.1f}x faster" if theirs >= ours else f"{ours / theirs:.1f}x slower"

lines = []
def row(*cells):
    lines.append(cells)

(context, evaluation), (tessellation_context, tessellation), (profile_context, profile_check), \
    (properties_context, properties), (export_context, export) = (
    load("evaluation"), load("tessellation"), load("profile_check"), load("properties"), load("export"))
context = context or tessellation_context or profile_context or properties_context or export_context

row("benchmark", "ours", "OCCT", "ours/OCCT", "target", "status")
verdicts = []

# Evaluation: points per second, ours against GeomAdaptor_Surface (the target) and Geom_BSplineSurface.
for name, b in evaluation.items():
    parts = name.split("/")
    if parts[3] != "ours":
        continue
    base = "/".join(parts[:3])
    n = parts[4]
    ours = b["points_per_second"]
    for other, target in (("GeomAdaptor_Surface", 3.0), ("Geom_BSplineSurface", None)):
        o = evaluation.get(f"{base}/{other}/{n}")
        if o is None:
            continue
        ratio = ours / o["points_per_second"]
        status = "" if target is None else ("PASS" if ratio >= target else "FAIL")
        if target is not None:
            verdicts.append(status)
        row(f"{base} {n}x{n} vs {other}", si(ours) + " pt/s", si(o["points_per_second"]) + " pt/s",
            f"{ratio:.1f}x", ">= 3x" if target else "", status)
    p = evaluation.get(f"{base}/ours_portable/{n}")
    a = evaluation.get(f"{base}/GeomAdaptor_Surface/{n}")
    if p and a:
        row(f"{base} {n}x{n} portable(SSE2) vs GeomAdaptor", si(p["points_per_second"]) + " pt/s",
            si(a["points_per_second"]) + " pt/s", f"{p['points_per_second'] / a['points_per_second']:.1f}x", "", "")

# Tessellation: speed-up over BRepMesh, triangle counts, deviation against the tolerance.
for parts, b, o in against_occt(tessellation, "BRepMesh"):
    speed = seconds(o) / seconds(b)
    label = f"tess/{parts[1]} tol 1e-{parts[3]}"
    status = "PASS" if speed >= 10 and b["triangles"] <= o["triangles"] and b["deviation_over_tolerance"] <= 1 else "FAIL"
    verdicts.append(status)
    row(label + " time", f"{seconds(b) * 1e3:.3g} ms", f"{seconds(o) * 1e3:.3g} ms", f"{speed:.2f}x faster", ">= 10x", status)
    row(label + " triangles", si(b["triangles"]), si(o["triangles"]), f"{b['triangles'] / o['triangles']:.2f}", "<= 1", "")
    row(label + " deviation/tol", f"{b['deviation_over_tolerance']:.3f}", f"{o['deviation_over_tolerance']:.3f}",
        "", "ours <= 1", "")

# Profile check (revolve's and extrude's crossing test) against BRepCheck_Analyzer on the same cap face.
for parts, b, o in against_occt(profile_check, "BRepCheck"):
    row(f"profile/{parts[1]} ({b['spans']:.0f} spans) check vs BRepCheck_Analyzer(cap)",
        f"{seconds(b) * 1e6:.3g} us", f"{seconds(o) * 1e6:.3g} us", speed(seconds(b), seconds(o)), "", "")

# Volume and area against BRepGProp (its fixed rule, then its adaptive one at Eps 1e-12), with each
# answer's relative error against the closed form.
for occt_name in ("BRepGProp", "BRepGProp_eps"):
    for parts, b, o in against_occt(properties, occt_name):
        label = f"{parts[0]}/{parts[1]} vs {occt_name}"
        row(label + " time", f"{seconds(b) * 1e6:.3g} us", f"{seconds(o) * 1e6:.3g} us", speed(seconds(b), seconds(o)), "", "")
        row(label + " relative error", f"{b['relative_error']:.1e}", f"{o['relative_error']:.1e}", "", "", "")

# Export: no OCCT counterpart; triangles per second against the target.
for name, b in export.items():
    parts = name.split("/")
    rate = b["triangles_per_second"]
    target = 2e6 if parts[1] == "scad" else None
    status = "" if target is None else ("PASS" if rate >= target else "FAIL")
    if target is not None:
        verdicts.append(status)
    row(f"export/{parts[1]} {si(float(parts[2]))} triangles", si(rate) + " tri/s", "-",
        f"{rate / target:.2f} of target" if target else "", ">= 2M tri/s" if target else "", status)

widths = [max(len(str(r[i])) for r in lines) for i in range(len(lines[0]))]
print()
print(f"ratbez benchmarks: nproc = {cores}, single-threaded, CPU time medians; "
      f"grid kernels: {context.get('ratbez_grid_kernels', '?')}; "
      f"CPU {context.get('mhz_per_cpu', '?')} MHz, load average {context.get('load_avg', '?')}")
for k, r in enumerate(lines):
    print("  ".join(str(c).ljust(w) if i == 0 else str(c).rjust(w) for i, (c, w) in enumerate(zip(r, widths))))
    if k == 0:
        print("  ".join("-" * w for w in widths))
print(f"\n{verdicts.count('PASS')} targets met, {verdicts.count('FAIL')} missed")
PYTHON

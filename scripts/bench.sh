#!/usr/bin/env bash
# Builds the project as scripts/setup.sh does (the normal Release build in build/ includes bench/),
# runs the benchmark programs (evaluation, tessellation, the profile check, volume/area and lofts/sweeps
# against OpenCASCADE in the same run, export alone, bulk evaluation through Python, triangles against
# OpenSCAD's native $fn meshes) and prints ONE table:
# every row with ours / OCCT ratios and the target it is held to.
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
for program in evaluation tessellation profile_check properties modelling export; do
  echo "== bench_$program" >&2
  "$build/bench/bench_$program" --benchmark_filter="$filter" --benchmark_repetitions="$repetitions" \
    --benchmark_min_time="$min_time" --benchmark_report_aggregates_only=true \
    --benchmark_out="$results/$program.json" --benchmark_out_format=json >&2
done

# Bulk evaluation through the Python module, with the C++ and GeomAdaptor rows it is compared to re-measured
# in the same run (bench/python_evaluation.py).
if ls "$build"/kernel/python/ratbez*.so >/dev/null 2>&1; then
  echo "== python bulk evaluation" >&2
  BENCH_REPETITIONS="$repetitions" BENCH_MIN_TIME="$min_time" BENCH_FILTER="$filter" \
    /usr/bin/python3 bench/python_evaluation.py "$build" "$results/python.json"
fi

# Triangles against OpenSCAD's own sphere($fn) and rotate_extrude($fn) at equal measured deviation, with the
# real openscad (bench/openscad_native.py).
if ls "$build"/kernel/python/ratbez*.so >/dev/null 2>&1; then
  echo "== native OpenSCAD meshes" >&2
  /usr/bin/python3 bench/openscad_native.py "$build" "$results/native.json"
fi

/usr/bin/python3 bench/report.py "$results" "$(nproc)"

"""Bulk surface evaluation through Python (surface.evaluate into numpy), against the C++ grid evaluator and
OpenCASCADE's GeomAdaptor_Surface measured in the same run: this script first runs bench_evaluation for
the same surfaces and grid size, then times the Python calls, and writes one Google Benchmark-style JSON
with all of those rows (medians of the repetitions, CPU time), which bench/report.py turns into the
"python" rows of the table.

  D0: s.evaluate(us, vs)                                   the points, shape (n, n, 3)
  D1: s.evaluate_partials(us, vs)                          the point and both first partials in one pass,
                                                           shape (n, n, 3, 3), as OCCT's D1 gives them

Names: eval/<surface>/<D0|D1>/python/<n>, beside the C++ rows eval/<surface>/<D0|D1>/<ours|GeomAdaptor_Surface>/<n>.
The surfaces are bench_shapes.hpp's sphere, torus and revolved rational cubic (the random bicubic is drawn
by C++'s mt19937 and is left to the C++ rows).

Usage: python3 bench/python_evaluation.py BUILD_DIR OUT_JSON
Environment (as scripts/bench.sh): BENCH_REPETITIONS (default 3), BENCH_MIN_TIME (seconds per repetition,
default 0.5), BENCH_FILTER (a regex on the names).
"""

import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

GRID = 1000
SURFACES = ("sphere", "torus", "revolved_cubic")


def surfaces(ratbez):
    """The evaluation surfaces of bench_shapes.hpp, built the same way."""
    profile = ratbez.BezierCurve([(0, 0, 0), (1.6, 0, 0.2), (1.1, 0, 1.7), (0, 0, 2)], [1.0, 0.6, 1.8, 1.0])
    return {"sphere": ratbez.sphere(1.0).faces[0].surface,
            "torus": ratbez.torus(1.0, 0.3).faces[0].surface,
            "revolved_cubic": ratbez.revolve(profile).faces[0].surface}


def cpu_times(call, repetitions, min_time):
    """Median CPU seconds per call over `repetitions` runs of at least `min_time` seconds each."""
    call()  # warm up: first-touch page faults of the output, caches
    times = []
    for _ in range(repetitions):
        count, start, wall = 0, time.process_time(), time.perf_counter()
        while True:
            call()
            count += 1
            if time.perf_counter() - wall >= min_time:
                break
        times.append((time.process_time() - start) / count)
    return statistics.median(times)


def row(name, seconds, points):
    return {"name": name + "_median", "run_name": name, "run_type": "aggregate", "aggregate_name": "median",
            "cpu_time": seconds * 1e3, "time_unit": "ms", "points": float(points),
            "points_per_second": points / seconds}


def cpp_rows(build, pattern, repetitions, min_time):
    """(context, rows) of bench_evaluation for the same surfaces and grid size."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "evaluation.json")
        subprocess.run([os.path.join(build, "bench", "bench_evaluation"), f"--benchmark_filter={pattern}",
                        f"--benchmark_repetitions={repetitions}", f"--benchmark_min_time={min_time}",
                        "--benchmark_report_aggregates_only=true", f"--benchmark_out={out}",
                        "--benchmark_out_format=json"], check=True, stdout=sys.stderr)
        with open(out) as f:
            data = json.load(f)
    rows = [b for b in data.get("benchmarks", []) if b.get("aggregate_name") == "median"]
    return data.get("context", {}), rows


def main(build, out):
    sys.path.insert(0, os.path.join(build, "kernel", "python"))
    import numpy as np
    import ratbez

    repetitions = int(os.environ.get("BENCH_REPETITIONS", "3"))
    min_time = float(os.environ.get("BENCH_MIN_TIME", "0.5"))
    wanted = re.compile(os.environ.get("BENCH_FILTER", "."))
    names = "|".join(SURFACES)
    context, rows = cpp_rows(build, f"eval/({names})/D[01]/(ours|GeomAdaptor_Surface)/{GRID}$", repetitions, min_time)
    rows = [b for b in rows if wanted.search(b["run_name"])]
    for name, surface in surfaces(ratbez).items():
        (u0, u1), (v0, v1) = surface.domain
        us, vs = np.linspace(u0, u1, GRID), np.linspace(v0, v1, GRID)
        calls = {"D0": lambda: surface.evaluate(us, vs),
                 "D1": lambda: surface.evaluate_partials(us, vs)}
        for order, call in calls.items():
            label = f"eval/{name}/{order}/python/{GRID}"
            if wanted.search(label):
                rows.append(row(label, cpu_times(call, repetitions, min_time), GRID * GRID))
                print(f"{label}: {rows[-1]['points_per_second'] / 1e6:.0f} M points/s", file=sys.stderr)
    context["python"] = sys.version.split()[0]
    context["numpy"] = np.__version__
    with open(out, "w") as f:
        json.dump({"context": context, "benchmarks": rows}, f, indent=1)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: python_evaluation.py BUILD_DIR OUT_JSON")
    main(sys.argv[1], sys.argv[2])

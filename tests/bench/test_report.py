"""bench/report.py, the table of scripts/bench.sh, on tests/bench/fixture: a few rows of real Google
Benchmark output from each benchmark program (medians, as bench.sh writes them)."""

import importlib.util
import json
import os
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURE = os.path.join(HERE, "fixture")
SCRIPT = os.path.join(HERE, "..", "..", "bench", "report.py")

spec = importlib.util.spec_from_file_location("report", SCRIPT)
report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report)


def labels(table):
    return [row[0] for row in table.rows[1:]]


def test_every_section_prints_its_rows_without_a_filter(capsys):
    table = report.main(FIXTURE, "2")
    names = labels(table)
    for prefix in ("eval/sphere/D0", "eval/sphere/D1", "tess/sphere tol 1e-2 time", "tess/sphere tol 1e-2 triangles",
                   "profile/circle_4_arcs", "volume/sphere vs BRepGProp time", "area/sphere vs BRepGProp_eps",
                   "loft/circles vs ThruSections time", "loft/circles_ruled vs ThruSections control points",
                   "sweep/torus vs MakePipeShell volume error", "sweep/helix_1e-4 vs MakePipeShell deviation",
                   "sweep/helix_1e-6 vs MakePipeShell valid (BRepCheck)", "export/scad", "export/stl_binary",
                   "python eval/sphere/D0 1000x1000 vs GeomAdaptor", "python eval/sphere/D1 1000x1000 vs GeomAdaptor",
                   "python eval/sphere/D0 1000x1000 vs C++ grid", "sphere_r10_tol0.01 triangles vs inscribed bound",
                   "native/sphere_r10_tol0.01 triangles vs OpenSCAD", "native/torus_R10_r3_tol0.01 deviation/tol"):
        assert any(n.startswith(prefix) for n in names), prefix
    # The fixture's targets (evaluation >= 3x GeomAdaptor, tessellation, the sphere against its inscribed
    # bound, .scad export rate, each loft and sweep valid, the two helix sweeps within their tolerance, Python
    # D0 and D1, fewer triangles than OpenSCAD's sphere and torus, the sphere against the straddling limit's
    # target of issue 28) all get a verdict.
    assert len(table.verdicts) == 4 + 5 + 2 + 2 + 1 + 2 + 1 and set(table.verdicts) <= {"PASS", "FAIL"}
    out = capsys.readouterr().out
    assert "targets met" in out and "ratbez benchmarks: nproc = 2" in out
    assert all(len(row) == len(table.rows[0]) for row in table.rows)


def test_the_script_runs_as_bench_sh_calls_it():
    result = subprocess.run([sys.executable, SCRIPT, FIXTURE, "2"], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    assert "tess/sphere tol 1e-2 time" in result.stdout and "export/scad 250k triangles" in result.stdout


@pytest.mark.parametrize("missing", report.PROGRAMS)
def test_a_program_that_matched_no_filter_has_no_rows(tmp_path, missing):
    for program in report.PROGRAMS:
        if program != missing:
            shutil.copy(os.path.join(FIXTURE, program + ".json"), tmp_path)
    table = report.main(str(tmp_path), "2")
    assert len(table.rows) > 1
    first = {"evaluation": "eval/", "tessellation": "tess/", "profile_check": "profile/",
             "properties": "volume/", "modelling": "loft/", "export": "export/", "python": "python ",
             "native": "native/"}[missing]
    assert not any(n.startswith(first) for n in labels(table))


def test_modelling_verdicts_follow_validity_and_tolerance(tmp_path):
    """A sweep whose deviation exceeds the tolerance in its name, or an invalid loft, is a FAIL."""
    import json
    with open(os.path.join(FIXTURE, "modelling.json")) as f:
        data = json.load(f)
    for b in data["benchmarks"]:
        if b["run_name"] == "sweep/helix_1e-6/ours":
            b["deviation"] = 2e-6
        if b["run_name"] == "loft/circles/ours":
            b["valid"] = 0
    with open(tmp_path / "modelling.json", "w") as f:
        json.dump(data, f)
    table = report.Table()
    report.modelling_rows(table, report.load(str(tmp_path), "modelling")[1])
    rows = {row[0]: row for row in table.rows[1:]}
    assert rows["sweep/helix_1e-6 vs MakePipeShell deviation"][5] == "FAIL"
    assert rows["sweep/helix_1e-4 vs MakePipeShell deviation"][5] == "PASS"
    assert rows["loft/circles vs ThruSections valid (BRepCheck)"][5] == "FAIL"
    assert table.verdicts.count("FAIL") == 2


def test_python_rows_hold_d0_and_d1_to_their_targets(tmp_path):
    """A D0 row passes only at >= 100M points/s and >= 4x GeomAdaptor; D1 at >= 40M points/s."""
    def python_json(d0_rate, adaptor_rate, d1_rate):
        def row(name, rate):
            return {"name": name + "_median", "run_name": name, "aggregate_name": "median", "cpu_time": 1e3 / rate,
                    "time_unit": "ms", "points": 1e6, "points_per_second": rate}
        rows = [row("eval/s/D0/python/1000", d0_rate), row("eval/s/D0/GeomAdaptor_Surface/1000", adaptor_rate),
                row("eval/s/D0/ours/1000", 3e8), row("eval/s/D1/python/1000", d1_rate)]
        (tmp_path / "python.json").write_text(json.dumps({"context": {}, "benchmarks": rows}))
        return report.main(str(tmp_path), "2").verdicts

    assert python_json(2e8, 2e7, 5e7) == ["PASS", "PASS"]
    assert python_json(9e7, 1e7, 5e7) == ["FAIL", "PASS"]   # under 100M points/s
    assert python_json(2e8, 6e7, 3e7) == ["FAIL", "FAIL"]   # under 4x GeomAdaptor; D1 under 40M


def test_native_rows_want_fewer_triangles_within_the_tolerance(tmp_path):
    def verdict(ours, theirs, our_deviation=0.009):
        rows = [{"name": "native/s/ours", "tolerance": 0.01, "triangles": ours, "deviation": our_deviation},
                {"name": "native/s/openscad", "tolerance": 0.01, "triangles": theirs, "deviation": 0.0099, "fn": 99}]
        (tmp_path / "native.json").write_text(json.dumps({"context": {}, "benchmarks": rows}))
        table = report.Table()
        report.native_rows(table, report.load(str(tmp_path), "native")[1])
        return table.verdicts

    assert verdict(4000, 9896) == ["PASS"]
    assert verdict(9896, 9896) == ["FAIL"]
    assert verdict(4000, 9896, our_deviation=0.011) == ["FAIL"]


def test_the_sphere_passes_at_or_below_its_inscribed_bound_only(tmp_path):
    """bound/sphere_r10_tol0.01 (issue 17): PASS with the fixture's 4,284 triangles of 4,837, FAIL above it;
    against issue 28's straddling limit (2,418, target 3,400): FAIL at 4,284, PASS at 3,400."""
    with open(os.path.join(FIXTURE, "tessellation.json")) as f:
        data = json.load(f)
    table = report.Table()
    report.bound_rows(table, report.load(FIXTURE, "tessellation")[1])
    assert table.verdicts == ["PASS", "FAIL"]
    assert any(row[0] == "sphere_r10_tol0.01 triangles vs straddling limit" and row[3] == "1.77 of 2418"
               for row in table.rows)
    for triangles, verdicts in ((lambda b: b["bound"] + 1, ["FAIL", "FAIL"]), (lambda b: 3400, ["PASS", "PASS"])):
        for b in data["benchmarks"]:
            if b["run_name"].startswith("bound/"):
                b["triangles"] = triangles(b)
        with open(tmp_path / "tessellation.json", "w") as f:
            json.dump(data, f)
        table = report.Table()
        report.bound_rows(table, report.load(str(tmp_path), "tessellation")[1])
        assert table.verdicts == verdicts

"""bench/report.py, the table of scripts/bench.sh, on tests/bench/fixture: a few rows of real Google
Benchmark output from each benchmark program (medians, as bench.sh writes them)."""

import importlib.util
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
                   "export/scad", "export/stl_binary"):
        assert any(n.startswith(prefix) for n in names), prefix
    # The fixture's targets (evaluation >= 3x GeomAdaptor, tessellation, .scad export rate) all get a verdict.
    assert len(table.verdicts) == 4 and set(table.verdicts) <= {"PASS", "FAIL"}
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
             "properties": "volume/", "export": "export/"}[missing]
    assert not any(n.startswith(first) for n in labels(table))

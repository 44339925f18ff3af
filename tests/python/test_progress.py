"""Progress and Ctrl-C on the long calls besides tessellate (test_tessellation.py has those): Solid.volume
and area, the exports, check_mesh and occt_check take progress=callable(fraction); the fractions rise to
1.0, a callback that raises stops the call (an export then leaves no file), and SIGINT while the call runs
with the GIL released comes back as KeyboardInterrupt from the call itself."""
import os
import signal
import threading

import pytest

import ratbez
from conftest import needs_cgal, needs_occt, raises_naming


class Stop(Exception):
    pass


def stop(fraction):
    raise Stop()


def assert_rises_to_one(fractions):
    assert fractions and fractions[-1] == 1.0
    assert all(0 <= f <= 1 for f in fractions)
    assert fractions == sorted(fractions)


def interrupted(call, after):
    """Runs call() with SIGINT sent `after` seconds in; True if call raised KeyboardInterrupt."""
    timer = threading.Timer(after, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        call()
    except KeyboardInterrupt:
        return True
    finally:
        timer.cancel()
    return False


@pytest.fixture(scope="module")
def fine_mesh():
    """About 290k triangles: the CGAL checks take 0.3 s to a second, depending on the machine."""
    return ratbez.sphere(10.0).tessellate(1.5e-4)


# --- volume and area --------------------------------------------------------------------------------

@pytest.mark.parametrize("measure", ["volume", "area"])
def test_measures_report_their_end(measure):
    fractions = []
    value = getattr(ratbez.torus(3.0, 1.0), measure)(progress=fractions.append)
    assert_rises_to_one(fractions)
    exact = getattr(ratbez.torus(3.0, 1.0), "exact_" + measure)
    assert value == pytest.approx(exact, rel=1e-13)


@pytest.mark.parametrize("measure", ["volume", "area"])
def test_a_raising_callback_stops_a_measure(measure):
    with pytest.raises(Stop):
        getattr(ratbez.sphere(1.0), measure)(progress=stop)


@pytest.mark.parametrize("measure", ["volume", "area"])
def test_measures_refuse_a_progress_that_is_not_callable(measure):
    raises_naming("progress", getattr(ratbez.sphere(1.0), measure), progress="yes")


# --- exports ----------------------------------------------------------------------------------------

@needs_cgal
@pytest.mark.parametrize("writer,name", [("export_openscad", "ball.scad"), ("write_stl", "ball.stl"),
                                         ("write_off", "ball.off")])
def test_export_progress_rises_to_one(tmp_path, writer, name):
    fractions = []
    getattr(ratbez, writer)(ratbez.sphere(1.0), tmp_path / name, tolerance=1e-3, progress=fractions.append)
    assert_rises_to_one(fractions)
    assert (tmp_path / name).exists()


@needs_cgal
def test_export_of_a_mesh_reports_progress(tmp_path):
    fractions = []
    ratbez.write_off(ratbez.sphere(1.0).tessellate(1e-3), tmp_path / "mesh.off", progress=fractions.append)
    assert_rises_to_one(fractions)


@needs_cgal
def test_a_raising_callback_stops_an_export_and_leaves_no_file(tmp_path):
    with pytest.raises(Stop):
        ratbez.export_openscad(ratbez.sphere(1.0), tmp_path / "ball.scad", tolerance=1e-3, progress=stop)
    assert list(tmp_path.iterdir()) == []


@needs_cgal
def test_ctrl_c_stops_a_long_export_before_it_writes(tmp_path):
    # Uninterrupted: over 10 s (the rounding search measures and checks ~290k triangles per candidate).
    # SIGINT lands in the deviation measurement or the CGAL checks, past the tessellation; the file is
    # written only at the end, so its absence shows the call stopped inside the kernel.
    target = tmp_path / "ball.scad"
    assert interrupted(lambda: ratbez.export_openscad(ratbez.sphere(10.0), target, tolerance=1.5e-4), after=1.5)
    assert list(tmp_path.iterdir()) == []


# --- check_mesh -------------------------------------------------------------------------------------

@needs_cgal
def test_check_mesh_progress_rises_to_one():
    fractions = []
    assert ratbez.check_mesh(ratbez.sphere(1.0).tessellate(1e-3), progress=fractions.append)["ok"]
    assert_rises_to_one(fractions)


@needs_cgal
def test_check_mesh_polls_inside_the_self_intersection_test(fine_mesh):
    # The self-intersection test is one CGAL call, which takes over half a second here; the progress reaches
    # it through the point reads (kSelfIntersectionStart = 0.2 in mesh_checks.cpp), every 20 ms at most.
    during = []

    def record(fraction):
        if fraction == 0.2:
            during.append(fraction)
            if len(during) == 3:
                raise Stop()

    with pytest.raises(Stop):
        ratbez.check_mesh(fine_mesh, progress=record)


@needs_cgal
def test_ctrl_c_interrupts_check_mesh(fine_mesh):
    # Sent well before the checks can end (0.3 s on a fast machine; sent at 0.3 s it raced them).
    assert interrupted(lambda: ratbez.check_mesh(fine_mesh), after=0.05)


# --- occt_check -------------------------------------------------------------------------------------

@needs_occt
def test_occt_check_progress_rises_to_one():
    fractions = []
    assert ratbez.occt_check(ratbez.torus(3.0, 1.0), progress=fractions.append)["passed"]
    assert_rises_to_one(fractions)


@needs_occt
def test_a_raising_callback_stops_occt_check():
    with pytest.raises(Stop):
        ratbez.occt_check(ratbez.torus(3.0, 1.0), progress=stop)

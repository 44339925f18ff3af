"""read_step / read_brep: our own files come back as the same solid, OpenCASCADE's refusals name the path,
and a read stops on Ctrl-C."""
import os
import signal
import warnings

import pytest

import ratbez
from conftest import needs_occt, raises_naming


def face_points_of(face):
    """Points of a face at a few fractions of its parameter domain."""
    (u0, u1), (v0, v1) = face.surface.domain
    return [face.point(min(u0 + s * (u1 - u0), u1), min(v0 + t * (v1 - v0), v1))
            for s in (0.0, 0.3, 1.0) for t in (0.0, 0.6, 1.0)]


def face_points(solid):
    """Points of every face at a few fractions of its parameter domain."""
    return [p for face in solid.faces for p in face_points_of(face)]


@needs_occt
@pytest.mark.parametrize("reader, writer, suffix", [("read_brep", "write_brep", ".brep"),
                                                    ("read_step", "write_step", ".step")])
def test_round_trip_gives_the_same_solid(tmp_path, reader, writer, suffix):
    vase = ratbez.BezierCurve([(0, 0, 0), (4, 0, 0.5), (0.5, 0, 3), (0, 0, 4)], weights=[1, 0.5, 2, 1])
    for solid in (ratbez.torus(3, 1, center=(1, 2, 3), axis=(1, 0, 1)), ratbez.cone(2, 0.5, 3),
                  ratbez.revolve(vase, angle=270)):
        path = tmp_path / ("solid" + suffix)
        getattr(ratbez, writer)(solid, path)
        read = getattr(ratbez, reader)(path)
        assert isinstance(read, ratbez.Solid)
        assert [f.kind for f in read.faces] == [f.kind for f in solid.faces]
        assert read.volume() == pytest.approx(solid.volume(), rel=1e-12)
        assert read.area() == pytest.approx(solid.area(), rel=1e-12)
        # The same surfaces, not the same parameters: arcs go to OpenCASCADE in their one-span form
        # (kernel/occt/src/smooth_arcs.hpp), so the points read back are compared with the original faces.
        size = max(abs(x) for p in face_points(solid) for x in p)
        for original, face in zip(solid.faces, read.faces):
            for q in face_points_of(face):
                if original.kind == "planar":
                    (u0, _), (v0, _) = original.surface.domain
                    p, n = original.point(u0, v0), original.normal(u0, v0)
                    off = abs(sum((a - b) * c for a, b, c in zip(q, p, n)))
                else:
                    off = original.surface.closest_point(q)[2]
                assert off <= 1e-12 * size


@needs_occt
def test_read_back_solids_convert_again_with_one_face_per_patch(tmp_path):
    # The workbench's path: a STEP sphere read back has unclamped knots ([-0.25, 0, 0, ..., 1, 1.25]), and
    # one face per Bézier patch of it crashed the interpreter; pickling on the way must not matter either.
    import pickle
    for solid in (ratbez.sphere(3), ratbez.cylinder(2, 5)):
        path = tmp_path / "solid.step"
        ratbez.write_step(solid, str(path))
        read = pickle.loads(pickle.dumps(ratbez.read_step(str(path))))
        assert len(ratbez.brep_string(read, bezier_faces=True)) > 0
        again = tmp_path / "again.step"
        ratbez.write_step(read, str(again), bezier_faces=True)
        assert ratbez.read_step(str(again)).volume() == pytest.approx(solid.volume(), rel=1e-12)


@needs_occt
def test_bad_files_name_the_path(tmp_path):
    raises_naming("path", ratbez.read_step, tmp_path / "missing.step")
    raises_naming("path", ratbez.read_brep, str(tmp_path / "missing.brep"))
    garbage = tmp_path / "garbage.step"
    garbage.write_text("not a STEP file\n")
    assert "not a readable STEP file" in str(raises_naming("path", ratbez.read_step, garbage))
    assert "not a readable .brep file" in str(raises_naming("path", ratbez.read_brep, garbage))
    raises_naming("path", ratbez.read_step, 42)
    raises_naming("progress", ratbez.read_brep, garbage, progress=3)


@needs_occt
def test_progress_and_ctrl_c(tmp_path):
    path = tmp_path / "sphere.brep"
    ratbez.write_brep(ratbez.sphere(1), path)
    fractions = []
    ratbez.read_brep(path, progress=fractions.append)
    assert fractions and fractions[-1] == 1.0 and fractions == sorted(fractions)

    # Ctrl-C arriving during the read (here: sent at its first progress call) ends it with KeyboardInterrupt.
    def interrupt(fraction):
        os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        ratbez.read_brep(path, progress=interrupt)


@needs_occt
@pytest.mark.parametrize("reader, writer, suffix", [("read_brep_all", "write_brep", ".brep"),
                                                    ("read_step_all", "write_step", ".step")])
def test_a_list_of_solids_writes_one_file_read_back_in_order_with_names(tmp_path, reader, writer, suffix):
    """What read_step_all returns goes back out whole: one STEP product per solid, named, or a .brep compound."""
    bolt = ratbez.cylinder(1, 6)
    bolt.name = "Bolt"
    nut = ratbez.torus(3, 1, center=(10, 0, 0))
    nut.name = "Écrou"                        # a name outside ASCII comes back as written
    plain = ratbez.sphere(2, center=(0, 10, 0))  # no name: named after the file and its place in it
    path = tmp_path / ("parts" + suffix)
    getattr(ratbez, writer)([bolt, nut, plain], path)
    back = getattr(ratbez, reader)(path)
    assert [s.volume() for s in back] == pytest.approx([bolt.volume(), nut.volume(), plain.volume()], rel=1e-9)
    # STEP keeps the names (one product each); a .brep holds none, so the file's stem names them all.
    assert [s.name for s in back] == (["Bolt", "Écrou", "parts_3"] if suffix == ".step" else
                                      ["parts_1", "parts_2", "parts_3"])
    # Every solid has a name of its own, so {s.name: s} keeps them all (README: Reading real models).
    twins = tmp_path / ("twins" + suffix)
    getattr(ratbez, writer)([bolt, bolt.translated((5, 0, 0)), plain], twins)
    names = [s.name for s in getattr(ratbez, reader)(twins)]
    assert len(set(names)) == 3 and all(names), names
    getattr(ratbez, writer)((bolt,), path)  # a tuple of one is one solid
    assert len(getattr(ratbez, reader)(path)) == 1
    for bad, argument in (([], "solid"), ([bolt, 3], "solid[1]"), (5, "solid")):
        raises_naming(argument, getattr(ratbez, writer), bad, path)
    # The one-solid reader names as the all-solids reader does (it gave a file's unnamed solid no name).
    getattr(ratbez, writer)(plain, tmp_path / ("ball" + suffix))
    assert getattr(ratbez, reader.replace("_all", ""))(tmp_path / ("ball" + suffix)).name == "ball"
    # A file name the format does not go by is refused, as the mesh writers refuse theirs (STEP went into x.stl).
    for other in ("x.stl", "x.scad", "x"):
        assert "must end in" in str(raises_naming("path", getattr(ratbez, writer), plain, tmp_path / other))
    getattr(ratbez, writer)(plain, tmp_path / ("CAPS" + suffix.upper()))  # any case, as CAD systems name them


@needs_occt
def test_hostile_files_raise_ratbez_error_naming_file_and_count_and_ctrl_c_lands(tmp_path):
    """Issue 29: a claimed 150,000,000 poles is a ratbez.Error naming the file and the count (it was MemoryError);
    a .brep OpenCASCADE reads forever stops within 0.5 s of Ctrl-C; a progress callback may read and write again
    (it deadlocked on the bridge's messenger lock)."""
    import time
    path = tmp_path / "cylinder.brep"
    ratbez.write_brep(ratbez.cylinder(1, 2), path, analytic_primitives=False)  # a B-spline record to mutate
    lines = path.read_text().split("\n")
    k = next(i for i, line in enumerate(lines) if line.startswith("Surfaces ")) + 1
    fields = lines[k].split(" ")
    fields[7] = "150000000"  # "9 urational vrational uperiodic vperiodic udegree vdegree nbupoles ..."
    lines[k] = " ".join(fields)
    poles = tmp_path / "poles.brep"
    poles.write_text("\n".join(lines))
    error = raises_naming("path", ratbez.read_brep, poles)
    assert "poles.brep" in str(error) and "150000000" in str(error)

    text = path.read_text()
    cut = tmp_path / "cut.brep"
    cut.write_text(text[:text.index("\nEd\n") + 4])
    start = time.monotonic()

    def interrupt_after_a_while(fraction):
        if time.monotonic() - start > 0.3:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        ratbez.read_brep(cut, progress=interrupt_after_a_while)
    assert time.monotonic() - start < 0.3 + 0.5

    again = []

    def read_and_write_again(fraction):
        if not again:
            again.append(fraction)
            ratbez.write_step(ratbez.sphere(1), tmp_path / "inner.step")
            ratbez.read_step(tmp_path / "inner.step")

    ratbez.write_step(ratbez.sphere(2), tmp_path / "outer.step")
    assert ratbez.read_step(tmp_path / "outer.step", progress=read_and_write_again).volume() > 0 and again


IDF_SOT404 = "/usr/share/freecad/Mod/Idf/Idflibs/SOT404.stp"


@needs_occt
@pytest.mark.skipif(not os.path.exists(IDF_SOT404), reason="FreeCAD's Idf parts are not installed")
def test_faces_outside_every_solid_are_left_out_with_a_read_warning():
    """A real STEP part (FreeCAD's SOT404: four solids and an open shell of 17 faces): the solids read, the shell
    bounds no volume and is left out, and the reader says so with a ratbez.ReadWarning naming the file."""
    with pytest.warns(ratbez.ReadWarning, match=r"SOT404\.stp': left out 17 face\(s\) outside every solid"):
        solids = ratbez.read_step_all(IDF_SOT404)
    assert len(solids) == 4
    assert issubclass(ratbez.ReadWarning, UserWarning)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ratbez.ReadWarning)
        with pytest.raises(ratbez.ReadWarning):
            ratbez.read_step_all(IDF_SOT404)

"""Value semantics: pickle (every protocol), copy and deepcopy give back every type with its exact data
(a Solid and a Face by their surfaces, edges and construction record, not a mesh), == and hash by value
for curves and surfaces, shapes through multiprocessing, and corrupted pickles refused."""
import copy
import math
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import ratbez
from conftest import raises_naming


def solids():
    profile = [ratbez.BezierCurve([(1, 0, 0), (2.5, 0, 1), (1, 0, 2)], weights=[1, 2, 1]),
               ratbez.BezierCurve([(1, 0, 2), (1, 0, 0)])]
    return {"cylinder": ratbez.cylinder(1, 2, center=(1, 2, 3), axis=(0, 1, 1)),
            "cone": ratbez.cone(2, 0, 3),
            "sphere": ratbez.sphere(1.5, center=(0, 1, 0)),
            "torus": ratbez.torus(3, 1, axis=(1, 0, 0)),
            "revolution": ratbez.revolve(profile, angle=270),
            "extrusion": ratbez.extrude([ratbez.circle(2)], (0, 0, 1), 1, holes=[[ratbez.circle(0.5)]]),
            "none": ratbez.sphere(1).transformed([[1, 0.2, 0, 0], [0, 2, 0, 0], [0, 0, 1, 0]])}


def same_solid(a, b):
    assert a.kind == b.kind and a.parameters == b.parameters and a.exact_volume == b.exact_volume
    assert a.volume() == b.volume() and a.area() == b.area()  # the same numbers, bit for bit
    assert a.euler_characteristic() == b.euler_characteristic()
    assert len(a.faces) == len(b.faces)
    for fa, fb in zip(a.faces, b.faces):
        same_face(fa, fb)
    ma, mb = a.tessellate(0.05), b.tessellate(0.05)
    assert np.array_equal(ma.vertices, mb.vertices) and np.array_equal(ma.triangles, mb.triangles)


def same_face(a, b):
    assert a.kind == b.kind and a.surface == b.surface
    assert [[c for c in loop] for loop in a.loops] == [[c for c in loop] for loop in b.loops]


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_solids_pickle_exactly_with_every_protocol(protocol):
    for name, solid in solids().items():
        same_solid(pickle.loads(pickle.dumps(solid, protocol=protocol)), solid)


def test_copy_and_deepcopy_of_every_type():
    solid = solids()["extrusion"]
    values = [ratbez.BezierCurve([(0, 0), (1, 2), (3, 1)], weights=[1, 3, 1]), ratbez.circle(2, center=(1, 1, 1)),
              ratbez.BezierSurface([[(0, 0, 0), (1, 0, 1)], [(0, 1, 0), (1, 1, 2)]]), ratbez.sphere(1).faces[0].surface]
    for value in values:
        for twin in (copy.copy(value), copy.deepcopy(value), pickle.loads(pickle.dumps(value))):
            assert twin == value and twin is not value and type(twin) is type(value) and hash(twin) == hash(value)
            assert twin.weights == value.weights
    for twin in (copy.copy(solid), copy.deepcopy(solid)):
        same_solid(twin, solid)
    for face in solid.faces:  # planar faces with a hole, and the surface faces of the prism's sides
        for twin in (copy.copy(face), copy.deepcopy(face), pickle.loads(pickle.dumps(face))):
            same_face(twin, face)
    mesh = solid.tessellate(0.05)
    for twin in (copy.copy(mesh), copy.deepcopy(mesh), pickle.loads(pickle.dumps(mesh))):
        assert np.array_equal(twin.vertices, mesh.vertices) and np.array_equal(twin.triangles, mesh.triangles)
    # deepcopy inside containers shares nothing with the original container.
    box = {"shape": solid, "curves": values}
    twin = copy.deepcopy(box)
    assert twin["curves"] == values and twin["shape"] is not solid


def test_equality_is_by_value():
    a = ratbez.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [(0, 0), (1, 1), (2, 0)], weights=[1, 2, 1])
    b = ratbez.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [(0, 0, 0), (1, 1, 0), (2, 0, 0)], weights=[1.0, 2.0, 1.0])
    assert a == b and not (a != b) and hash(a) == hash(b) and len({a, b}) == 1
    assert a != ratbez.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [(0, 0), (1, 1), (2, 0)], weights=[1, 3, 1])
    assert a != ratbez.NurbsCurve(2, [0, 0, 0, 2, 2, 2], [(0, 0), (1, 1), (2, 0)], weights=[1, 2, 1])  # knots
    # The same points and unit weights are the same curve, rational flag or not.
    assert ratbez.BezierCurve([(0, 0), (1, 1)]) == ratbez.BezierCurve([(0, 0), (1, 1)], weights=[1, 1])
    # The same curve in another parameterisation is a different value.
    bezier = ratbez.BezierCurve([(0, 0), (1, 2), (3, 1)])
    assert bezier != bezier.elevate() and bezier != bezier.reversed() and bezier == bezier.reversed().reversed()
    assert ratbez.circle(1) == ratbez.circle(1) and ratbez.circle(1) != ratbez.circle(1.0000001)
    assert (ratbez.circle(1) == "circle") is False and ratbez.circle(1) != None  # noqa: E711
    s = ratbez.sphere(1).faces[0].surface
    assert s == ratbez.sphere(1).faces[0].surface and s != ratbez.sphere(2).faces[0].surface
    assert ratbez.NurbsSurface.from_bezier(ratbez.BezierSurface([[(0, 0, 0), (1, 0, 0)], [(0, 1, 0), (1, 1, 1)]])) == \
        ratbez.NurbsSurface(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], [[(0, 0, 0), (1, 0, 0)], [(0, 1, 0), (1, 1, 1)]])


def measure(solid):
    """Runs in a worker process: the solid arrived pickled; the mesh goes back pickled."""
    return solid.kind, solid.volume(), solid.tessellate(0.05), solid.scaled(2)


def test_shapes_travel_through_multiprocessing():
    shapes = list(solids().values())[:4]
    with ProcessPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(measure, shapes))
    for solid, (kind, volume, mesh, doubled) in zip(shapes, results):
        assert kind == solid.kind and volume == solid.volume()
        local = solid.tessellate(0.05)
        assert np.array_equal(mesh.vertices, local.vertices) and np.array_equal(mesh.triangles, local.triangles)
        assert doubled.kind == solid.kind and doubled.volume() == pytest.approx(8 * volume, rel=1e-12)


def test_corrupted_pickles_are_refused():
    kind, state = ratbez.sphere(1).__reduce__()[1]
    assert kind == "Solid"
    tables, construction, name = state
    assert name == ""
    assert ratbez._restore("Solid", (tables, construction)).volume() == ratbez.sphere(1).volume()  # older pickles
    vertices, edges, faces = tables
    surface_face = faces[0]
    bad_sides = tuple((99, False) for _ in range(4))
    raises_naming("faces[0]", ratbez._restore, "Solid", ((vertices, edges, (surface_face[:2] + (bad_sides,),)),
                                                          construction))
    raises_naming("state", ratbez._restore, "Solid", (tables,))
    raises_naming("construction", ratbez._restore, "Solid", (tables, ("cube", ())))
    raises_naming("type", ratbez._restore, "Widget", ())
    curve_state = ratbez.circle(1).__reduce__()[1][1]
    raises_naming("state.points", ratbez._restore, "NurbsCurve", curve_state[:2] + ((1.0, 2.0, 3.0),) + curve_state[3:])
    degree, knots, points, rational = curve_state
    with pytest.raises(ratbez.Error):  # a weight of -1: the constructors validate restored data too
        ratbez._restore("NurbsCurve", (degree, knots, points[:-1] + (-1.0,), rational))
    assert math.isclose(ratbez._restore("NurbsCurve", curve_state).point(0.25)[1], 1.0)

"""Exact references for the FreeCAD measurement tests: the CLI's shape specs (examples/*.json) built with
the ratbez module, and their centres of mass from closed forms or from line integrals over the profile.

Volumes and areas are the kernel's own (certified cubature). Centres of mass: closed forms for the
primitives (none for ruled solids, lofts and sweeps); for revolutions and extrusions, Green's theorem turns
the region integrals of the profile into integrals along its curves, taken by Gauss–Legendre on every knot
span of every piece (cut in 16, 24 points each: rational pieces of moderate weights are then integrated to
rounding).
"""

import json
import math

import numpy

import ratbez

_NODES, _WEIGHTS = numpy.polynomial.legendre.leggauss(24)


def _vec(p):
    p = list(p) + [0.0] * (3 - len(p))
    return numpy.array(p, dtype=float)


def _piece(spec):
    kind = spec["type"]
    if kind == "line":
        return ratbez.line_segment(spec["from"], spec["to"])
    if kind == "bezier":
        return ratbez.NurbsCurve(len(spec["points"]) - 1, [0.0] * len(spec["points"]) + [1.0] * len(spec["points"]),
                                 spec["points"], spec.get("weights"))
    if kind == "nurbs":
        return ratbez.NurbsCurve(spec["degree"], spec["knots"], spec["points"], spec.get("weights"))
    if kind == "arc":
        return ratbez.arc(spec["radius"], spec["start_deg"], spec["end_deg"], spec.get("center", (0, 0, 0)),
                          spec.get("normal", (0, 0, 1)))
    if kind == "circle":
        return ratbez.circle(spec["radius"], spec.get("center", (0, 0, 0)), spec.get("normal", (0, 0, 1)))
    if kind == "interpolate":
        return ratbez.interpolate(spec["points"], spec.get("degree", 3), spec.get("parameterization", "chord"),
                                  spec.get("tangents"), spec.get("closed", False))
    raise ValueError("unknown profile piece " + kind)


def load(path):
    """(name, shape spec dict) of an example file."""
    with open(path) as f:
        document = json.load(f)
    return document.get("name", path), document["shape"]


def solid(shape):
    """The ratbez.Solid of a shape spec."""
    kind = shape["type"]
    center, axis = shape.get("center", (0, 0, 0)), shape.get("axis", (0, 0, 1))
    if kind == "cylinder":
        return ratbez.cylinder(shape["radius"], shape["height"], center, axis)
    if kind == "cone":
        return ratbez.cone(shape["radius1"], shape["radius2"], shape["height"], center, axis)
    if kind == "sphere":
        return ratbez.sphere(shape["radius"], center)
    if kind == "torus":
        return ratbez.torus(shape["major_radius"], shape["minor_radius"], center, axis)
    if kind == "ruled":
        return ratbez.loft([[_piece(p) for p in shape[side]] for side in ("profile_a", "profile_b")], degree=1,
                           ruled=True, align=shape.get("align", True))
    if kind == "loft":
        return ratbez.loft([[_piece(p) for p in profile] for profile in shape["profiles"]],
                           degree=shape.get("degree", 3), ruled=shape.get("ruled", False),
                           align=shape.get("align", True))
    pieces = [_piece(p) for p in shape["profile"]]
    if kind == "sweep":
        return ratbez.sweep(pieces, [_piece(p) for p in shape["path"]], shape.get("tolerance", 1e-6))
    if kind == "revolve":
        return ratbez.revolve(pieces, shape.get("axis_point", (0, 0, 0)), shape.get("axis_dir", (0, 0, 1)),
                              shape.get("angle", 360.0))
    if kind == "extrude":
        return ratbez.extrude(pieces, shape["direction"], shape["distance"])
    raise ValueError("unknown shape " + kind)


def _line_integral(curves, integrand):
    """Sum over the curves of the integral of integrand(point, derivative) dt."""
    total = 0.0
    for curve in curves:
        knots = sorted(set(curve.knots))
        a0, b0 = curve.domain
        for k0, k1 in zip(knots[:-1], knots[1:]):
            if k1 <= a0 or k0 >= b0:
                continue
            for part in range(16):
                a = k0 + (k1 - k0) * part / 16
                b = k0 + (k1 - k0) * (part + 1) / 16
                for x, w in zip(_NODES, _WEIGHTS):
                    t = 0.5 * (a + b) + 0.5 * (b - a) * x
                    total += 0.5 * (b - a) * w * integrand(_vec(curve.point(t)), _vec(curve.derivative(t)))
    return total


def _unit(v):
    v = _vec(v)
    return v / numpy.linalg.norm(v)


def centroid(shape, curves=None):
    """The exact centre of mass of a shape spec (numpy array); None for ruled solids, lofts and sweeps (no
    closed form: their volumes and areas are still the kernel's certified values)."""
    kind = shape["type"]
    if kind in ("ruled", "loft", "sweep"):
        return None
    center, axis = _vec(shape.get("center", (0, 0, 0))), _unit(shape.get("axis", (0, 0, 1)))
    if kind == "cylinder":
        return center + axis * shape["height"] / 2
    if kind == "cone":
        r1, r2, h = shape["radius1"], shape["radius2"], shape["height"]
        return center + axis * h * (r1 * r1 + 2 * r1 * r2 + 3 * r2 * r2) / (4 * (r1 * r1 + r1 * r2 + r2 * r2))
    if kind in ("sphere", "torus"):
        return center
    curves = curves or [_piece(p) for p in shape["profile"]]
    if kind == "revolve":
        return revolve_centroid(curves, shape.get("axis_point", (0, 0, 0)), shape.get("axis_dir", (0, 0, 1)),
                                shape.get("angle", 360.0))
    return extrude_centroid([curves], shape["direction"], shape["distance"])


def revolve_centroid(curves, axis_point, axis_dir, angle_deg):
    """Centre of mass of the revolution of a profile (closed, or with both ends on the axis) lying in a
    plane through the axis. In the plane, r along e (away from the axis) and z along the axis: the solid's
    moments are integrals of r, r z and r^2 over the profile's region, turned by Green's theorem into
    integrals of (r^2/2) dz, (r^2 z/2) dz, (r^3/3) dz along it (all vanish on the axis)."""
    a, d = _vec(axis_point), _unit(axis_dir)
    far = max((_vec(c.point(t)) for c in curves for t in numpy.linspace(*c.domain, 9)),
              key=lambda p: numpy.linalg.norm((p - a) - d * numpy.dot(p - a, d)))
    e = _unit((far - a) - d * numpy.dot(far - a, d))
    f = numpy.cross(d, e)

    def rz(p, dp):
        return numpy.dot(p - a, e), numpy.dot(p - a, d), numpy.dot(dp, d)

    def integral(g):
        return _line_integral(curves, lambda p, dp: g(*rz(p, dp)))

    first = integral(lambda r, z, dz: r * r / 2 * dz)
    sign = 1.0 if first > 0 else -1.0
    r_moment = sign * first
    rz_moment = sign * integral(lambda r, z, dz: r * r * z / 2 * dz)
    rr_moment = sign * integral(lambda r, z, dz: r ** 3 / 3 * dz)
    alpha = math.radians(angle_deg)
    volume = alpha * r_moment
    moment = d * alpha * rz_moment + e * math.sin(alpha) * rr_moment + f * (1 - math.cos(alpha)) * rr_moment
    return a + moment / volume


def extrude_centroid(loops, direction, distance):
    """Centre of mass of a prism: the centroid of the profile's region (outer loop minus holes, by Green's
    theorem in the profile's plane) moved half the sweep."""
    points = [_vec(c.point(t)) for c in loops[0] for t in numpy.linspace(*c.domain, 5)]
    origin = points[0]
    normal = numpy.zeros(3)
    for p, q in zip(points, points[1:] + points[:1]):
        normal += numpy.cross(p - origin, q - origin)
    normal = normal / numpy.linalg.norm(normal)
    ex = _unit(points[1] - origin - normal * numpy.dot(points[1] - origin, normal))
    ey = numpy.cross(normal, ex)
    area = mx = my = 0.0
    for index, curves in enumerate(loops):
        def xy(p, dp):
            return numpy.dot(p - origin, ex), numpy.dot(p - origin, ey), numpy.dot(dp, ex), numpy.dot(dp, ey)
        a = _line_integral(curves, lambda p, dp: (lambda x, y, dx, dy: 0.5 * (x * dy - y * dx))(*xy(p, dp)))
        sx = _line_integral(curves, lambda p, dp: (lambda x, y, dx, dy: x * x / 2 * dy)(*xy(p, dp)))
        sy = _line_integral(curves, lambda p, dp: (lambda x, y, dx, dy: -y * y / 2 * dx)(*xy(p, dp)))
        sign = (1.0 if a > 0 else -1.0) * (1.0 if index == 0 else -1.0)
        area, mx, my = area + sign * a, mx + sign * sx, my + sign * sy
    u = _unit(direction)
    return origin + ex * mx / area + ey * my / area + u * distance / 2

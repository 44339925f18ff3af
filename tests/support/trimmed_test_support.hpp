#pragma once
// Every solid the kernel builds, rebuilt with trimmed faces: a surface face becomes its surface trimmed by its
// own four sides (the p-curves are the sides of its parameter rectangle, a pole side a segment along the pole),
// a planar face its plane patch trimmed by its loops (the p-curves are the loops in the plane's coordinates,
// exactly the patch's parameters). The edges and vertices stay the same objects, so the rebuilt faces close
// into the same shell. The result is the same solid, so every measure, mesh and conversion of the trimmed
// kind can be held against the untrimmed one: the widest test of trimmed faces there is without a file.

#include <memory>
#include <vector>

#include "ratbez/brep.hpp"

namespace ratbez::test {

// A straight p-curve from a (at t0) to b (at t1).
inline std::shared_ptr<const NurbsCurve> straight_pcurve(const Vec3& a, const Vec3& b, double t0, double t1) {
    return std::make_shared<const NurbsCurve>(NurbsCurve(1, {t0, t0, t1, t1}, {a, b}));
}

// The side `s` of a surface face as a coedge with its p-curve (brep.hpp: the edge's parameter is the side's
// surface parameter, run backwards when the edge runs against it).
inline Coedge side_coedge(const Face& face, int s) {
    const Coedge& c = face.sides()[static_cast<std::size_t>(s)];
    const NurbsSurface& surface = face.surface();
    const Interval du = surface.domain_u(), dv = surface.domain_v();
    const bool along_u = s == 0 || s == 2;
    const double fixed = s == 0 ? dv.min : s == 1 ? du.max : s == 2 ? dv.max : du.min;
    const bool traversal_increasing = s == 0 || s == 1;
    const bool with_parameter = traversal_increasing != c.reversed;
    const Interval d = c.edge->curve.domain();
    const double at_start = with_parameter ? d.min : d.max, at_end = with_parameter ? d.max : d.min;
    const auto uv = [&](double q) { return along_u ? Vec3{q, fixed, 0} : Vec3{fixed, q, 0}; };
    return Coedge{c.edge, c.reversed, straight_pcurve(uv(at_start), uv(at_end), d.min, d.max)};
}

// A planar face's coedge with the edge in the plane's coordinates as its p-curve.
inline Coedge planar_coedge(const Face& face, const Coedge& c) {
    const Plane& plane = face.plane();
    std::vector<Vec4> points = c.edge->curve.homogeneous_points();
    for (Vec4& p : points) {
        const Vec3 d = project(p) - plane.origin;
        p = Vec4{dot(d, plane.x_axis) * p.w, dot(d, plane.y_axis) * p.w, 0, p.w};
    }
    const NurbsCurve& curve = c.edge->curve;
    return Coedge{c.edge, c.reversed,
                  std::make_shared<const NurbsCurve>(
                      NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), std::move(points), curve.is_rational()))};
}

inline Face as_trimmed(const Face& face) {
    if (face.kind() == Face::Kind::trimmed) return face;
    std::vector<std::vector<Coedge>> loops;
    if (face.kind() == Face::Kind::surface) {
        loops.emplace_back();
        for (int s = 0; s < 4; ++s) loops.back().push_back(side_coedge(face, s));
    } else {
        for (const auto& loop : face.loops()) {
            loops.emplace_back();
            for (const Coedge& c : loop) loops.back().push_back(planar_coedge(face, c));
        }
    }
    return Face::trimmed(face.surface(), std::move(loops));
}

// The solid with every face (or, with `only`, the faces for which only(index) is true) made trimmed.
template <class Only>
Solid as_trimmed(const Solid& solid, Only&& only) {
    std::vector<Face> faces;
    for (std::size_t i = 0; i < solid.faces().size(); ++i)
        faces.push_back(only(i) ? as_trimmed(solid.faces()[i]) : solid.faces()[i]);
    return Solid(std::move(faces));
}
inline Solid as_trimmed(const Solid& solid) {
    return as_trimmed(solid, [](std::size_t) { return true; });
}

}  // namespace ratbez::test

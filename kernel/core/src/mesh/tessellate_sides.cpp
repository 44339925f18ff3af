// The sides of a surface face and their edges' parameters (tessellate_sides.hpp).

#include "mesh/tessellate_sides.hpp"

#include <algorithm>

#include "ratbez/error.hpp"

namespace ratbez::detail {

double side_parameter(const NurbsSurface& surface, Side side) {
    switch (side) {
        case Side::v_min: return surface.domain_v().min;
        case Side::v_max: return surface.domain_v().max;
        case Side::u_min: return surface.domain_u().min;
        case Side::u_max: break;
    }
    return surface.domain_u().max;
}

SideMap map_side(const Face& face, Side side) {
    const Coedge& coedge = face.sides()[side_slot(side)];
    require(coedge.edge != nullptr, "solid", "a surface face has a side without an edge");
    const NurbsSurface& s = face.surface();
    const Interval du = s.domain_u(), dv = s.domain_v();
    SideMap m;
    m.edge = coedge.edge.get();
    m.degenerate = coedge.edge->degenerate;
    const bool along_u = runs_along_u(side);
    m.p0 = along_u ? du.min : dv.min;
    m.p1 = along_u ? du.max : dv.max;
    const Interval dt = coedge.edge->curve.domain();
    m.t0 = dt.min, m.t1 = dt.max;
    if (!m.degenerate) {
        // The edge is the isocurve with the same parameter; compare an interior point of each run
        // direction so that closed edges (start == end) are decided too.
        const double fixed = side_parameter(s, side);
        auto surface_at = [&](double p) { return along_u ? s.point(p, fixed) : s.point(fixed, p); };
        const Vec3 edge_quarter = coedge.edge->curve.point(m.t0 + 0.25 * (m.t1 - m.t0));
        const double same = distance(edge_quarter, surface_at(m.p0 + 0.25 * (m.p1 - m.p0)));
        const double opposite = distance(edge_quarter, surface_at(m.p0 + 0.75 * (m.p1 - m.p0)));
        m.flipped = opposite < same;
    }
    return m;
}

std::vector<double> merge_params(std::vector<double> params, double t0, double t1) {
    params.push_back(t0);
    params.push_back(t1);
    std::sort(params.begin(), params.end());
    const double eps = 1e-12 * (t1 - t0);
    std::vector<double> out;
    for (double t : params) {
        if (t < t0 || t > t1) continue;
        if (!out.empty() && t - out.back() <= eps) continue;
        out.push_back(t);
    }
    if (out.back() != t1) {
        if (t1 - out.back() <= eps && out.size() > 1) out.back() = t1;
        else out.push_back(t1);
    }
    return out;
}

}  // namespace ratbez::detail

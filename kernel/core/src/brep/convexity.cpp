// Convexity of a solid from its exact faces (convexity.hpp): the faces' second fundamental forms at samples
// of their surfaces, and the creases along every edge.

#include "ratbez/convexity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "ratbez/surface_grid.hpp"

namespace ratbez {
namespace {

// Samples per knot span and direction, ends included: a curvature that changes sign inside a span shows at
// one of them unless it does so over less than a quarter of the span.
constexpr int kSpanSamples = 4;

// The distinct parameters 0..kSpanSamples of every non-empty span of the knot vector.
std::vector<double> span_samples(const std::vector<double>& knots, int degree) {
    std::vector<double> out;
    const std::size_t last = knots.size() - static_cast<std::size_t>(degree) - 1;
    for (std::size_t k = static_cast<std::size_t>(degree); k < last; ++k) {
        const double a = knots[k], b = knots[k + 1];
        if (!(b > a)) continue;
        for (int i = 0; i < kSpanSamples; ++i) out.push_back(a + (b - a) * i / kSpanSamples);
        out.push_back(b);  // exactly: a + (b - a) may round past the domain
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// The outward unit normal at (u, v), none where the partials are parallel (a pole: its neighbours judge).
std::optional<Vec3> unit_normal(const Vec3& su, const Vec3& sv) {
    const Vec3 n = cross(su, sv);
    const double length = norm(n);
    if (!(length > 1e-10 * (dot(su, su) + dot(sv, sv)))) return std::nullopt;
    return n / length;
}

// Whether the surface bends away from its outward normal at every sample: II negative semidefinite, each
// normal curvature II / I at most `flat` (1 / length) and the Gaussian curvature at least -flat^2.
bool bends_away(const NurbsSurface& s, double flat) {
    // All samples in one batched evaluation of the partials up to order two (surface_grid.hpp).
    const SurfaceGrid g = evaluate_grid(s, span_samples(s.knots_u(), s.degree_u()), span_samples(s.knots_v(), s.degree_v()),
                                        GridOutput::second_partials);
    for (std::size_t k = 0; k < g.points.size(); ++k) {
        const Vec3 su = g.du[k], sv = g.dv[k];
        const std::optional<Vec3> n = unit_normal(su, sv);
        if (!n) continue;
        const double E = dot(su, su), F = dot(su, sv), G = dot(sv, sv);
        const double L = dot(g.duu[k], *n), M = dot(g.duv[k], *n), N = dot(g.dvv[k], *n);
        if (L > flat * E || N > flat * G || L * N - M * M < -flat * flat * (E * G - F * F)) return false;
    }
    return true;
}

// The interior knots of multiplicity >= degree: where the surface may turn a corner inside the face (a
// revolved polyline's), or only look like it (the double knots of an exact rational circle).
std::vector<double> corner_knots(const std::vector<double>& knots, int degree) {
    std::vector<double> out;
    const std::size_t first = static_cast<std::size_t>(degree) + 1, last = knots.size() - static_cast<std::size_t>(degree) - 1;
    for (std::size_t k = first; k < last;) {
        std::size_t m = k;
        while (m < last && knots[m] == knots[k]) ++m;
        if (static_cast<int>(m - k) >= degree) out.push_back(knots[k]);
        k = m;
    }
    return out;
}

// Whether the surface's corners inside the face (corner_knots) bend away from the outward normal: across
// the knot line, each side's tangent leaving it does not rise above the other side's tangent plane, as
// for an edge between two faces (is_convex). The one-sided derivatives are taken 1e-7 of the span away:
// on a smooth convex joint that errs towards bending away.
bool corners_bend_away(const NurbsSurface& s) {
    const Interval du = s.domain_u(), dv = s.domain_v();
    const double eu = 1e-7 * (du.max - du.min), ev = 1e-7 * (dv.max - dv.min);
    const auto crease_is_convex = [](const Vec3& left_across, const Vec3& right_across, const Vec3& along) {
        // The line parts a left side from a right one; left_across and right_across point from left to right
        // on each side, and across x along is the outward normal.
        const std::optional<Vec3> nl = unit_normal(left_across, along), nr = unit_normal(right_across, along);
        if (!nl || !nr) return true;  // a pole: its neighbours judge
        return dot(right_across, *nl) <= 1e-9 * norm(right_across) && dot(-left_across, *nr) <= 1e-9 * norm(left_across);
    };
    // Each corner knot c as the parameters c - e, c, c + e of one batched evaluation of the partials
    // (surface_grid.hpp): the one-sided derivatives across the line either side, the one along it at c.
    auto either_side = [](const std::vector<double>& corners, double e) {
        std::vector<double> out;
        for (double c : corners) out.insert(out.end(), {c - e, c, c + e});
        return out;
    };
    const std::vector<double> corners_u = either_side(corner_knots(s.knots_u(), s.degree_u()), eu);
    if (!corners_u.empty()) {
        const std::vector<double> vs = span_samples(s.knots_v(), s.degree_v());
        const SurfaceGrid g = evaluate_grid(s, corners_u, vs, GridOutput::partials);
        for (std::size_t a = 0; a < corners_u.size(); a += 3)
            for (std::size_t j = 0; j < vs.size(); ++j)
                if (!crease_is_convex(g.partial_u(a, j), g.partial_u(a + 2, j), g.partial_v(a + 1, j))) return false;
    }
    const std::vector<double> corners_v = either_side(corner_knots(s.knots_v(), s.degree_v()), ev);
    if (!corners_v.empty()) {
        const std::vector<double> us = span_samples(s.knots_u(), s.degree_u());
        const SurfaceGrid g = evaluate_grid(s, us, corners_v, GridOutput::partials);
        for (std::size_t i = 0; i < us.size(); ++i)
            for (std::size_t b = 0; b < corners_v.size(); b += 3)
                // Across a v line by -S_v (from the side above the knot to the side below), so that across x
                // along = -S_v x S_u is the outward normal S_u x S_v.
                if (!crease_is_convex(-g.partial_v(i, b + 2), -g.partial_v(i, b), g.partial_u(i, b + 1))) return false;
    }
    return true;
}

// A face at a point of one of its edges: its outward normal and the tangent leaving the edge into the face.
struct EdgeSide {
    Vec3 normal, inward;
};

// The side of `face` at parameter t of the edge of its coedge c; none where the face has no normal there.
std::optional<EdgeSide> edge_side(const Face& face, const Coedge& c, std::size_t side_index, double t) {
    const double direction = c.reversed ? -1.0 : 1.0;  // the loop runs the edge against t
    if (face.kind() == Face::Kind::planar) {
        // The loop runs counterclockwise seen from the normal: the face lies to the left, n x T.
        const Vec3 n = face.plane().normal, tangent = c.edge->curve.derivative(t) * direction;
        return EdgeSide{n, cross(n, tangent)};
    }
    const NurbsSurface& s = face.surface();
    double u = 0, v = 0;
    Vec3 uv_left{};  // the direction into the face in (u, v)
    if (face.kind() == Face::Kind::trimmed) {
        // Loops run counterclockwise in (u, v) (holes clockwise): the face lies to the left of the p-curve.
        const Interval dp = c.pcurve->domain();
        const double tp = std::clamp(t, dp.min, dp.max);
        const Vec3 p = c.pcurve->point(tp), tangent = c.pcurve->derivative(tp) * direction;
        u = p.x, v = p.y, uv_left = {-tangent.y, tangent.x, 0};
    } else {
        // A side of the parameter rectangle; its edge is the isocurve with the same parameter or, run
        // against the side's counterclockwise direction, reparameterised t -> a + b - t (brep.hpp).
        const Side side = static_cast<Side>(side_index);
        const Interval du = s.domain_u(), dv = s.domain_v(), de = c.edge->curve.domain();
        const bool counterclockwise_increasing = side == Side::v_min || side == Side::u_max;
        const bool with_parameter = c.reversed != counterclockwise_increasing;
        const double p = with_parameter ? t : de.min + de.max - t;
        switch (side) {
            case Side::v_min: u = p, v = dv.min, uv_left = {0, 1, 0}; break;
            case Side::u_max: u = du.max, v = p, uv_left = {-1, 0, 0}; break;
            case Side::v_max: u = p, v = dv.max, uv_left = {0, -1, 0}; break;
            case Side::u_min: u = du.min, v = p, uv_left = {1, 0, 0}; break;
        }
    }
    const Interval du = s.domain_u(), dv = s.domain_v();
    u = std::clamp(u, du.min, du.max), v = std::clamp(v, dv.min, dv.max);
    const std::vector<std::vector<Vec3>> d = s.derivatives(u, v, 1);
    const Vec3 &su = d[1][0], &sv = d[0][1];
    const std::optional<Vec3> n = unit_normal(su, sv);
    if (!n) return std::nullopt;
    return EdgeSide{*n, su * uv_left.x + sv * uv_left.y};
}

}  // namespace

bool is_convex(const Solid& solid) {
    const Construction& record = solid.construction();
    if (record.get<Construction::Cylinder>() || record.get<Construction::Cone>() || record.get<Construction::Sphere>())
        return true;
    if (solid.shells().size() != 1) return false;
    const double size = solid.bounding_box().diagonal();
    if (!(size > 0)) return false;
    const double flat = 1e-9 / size;
    for (const Face& face : solid.faces())
        if (face.kind() != Face::Kind::planar && !(bends_away(face.surface(), flat) && corners_bend_away(face.surface())))
            return false;
    // Every face's side at 3 points of each of its edges; then each pair of sides at one point: the other
    // face's inward tangent may not rise above this face's tangent plane (by more than 1e-9 of its length).
    std::map<std::pair<const Edge*, int>, std::vector<EdgeSide>> sides;
    for (const Face& face : solid.faces()) {
        std::size_t index = 0;
        for_each_coedge(face, [&](const Coedge& c) {
            const std::size_t side_index = index++;
            if (c.edge->degenerate) return;
            const Interval d = c.edge->curve.domain();
            for (int k = 1; k <= 3; ++k)
                if (const auto side = edge_side(face, c, side_index, d.min + (d.max - d.min) * k / 4.0))
                    sides[{c.edge.get(), k}].push_back(*side);
        });
    }
    for (const auto& [where, at] : sides)
        for (const EdgeSide& a : at)
            for (const EdgeSide& b : at)
                if (dot(b.inward, a.normal) > 1e-9 * norm(b.inward)) return false;
    return true;
}

}  // namespace ratbez

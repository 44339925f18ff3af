// Face::trimmed: a NURBS surface bounded by loops of coedges with p-curves, validated as brep.hpp promises.
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/cubature.hpp"
#include "brep/consistency.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"

namespace ratbez {
namespace {

// Samples per knot span where the p-curve is held against its edge: the two curves are smooth inside a span
// and agree at its ends, so a few interior points see any disagreement larger than rounding.
constexpr int kSamplesPerSpan = 4;
// The sampling of a coedge is capped (a p-curve of 10^5 spans is checked at this many parameters).
constexpr std::size_t kMaxSamples = 512;

VertexPtr traversal_start(const Coedge& c) { return c.reversed ? c.edge->end : c.edge->start; }
VertexPtr traversal_end(const Coedge& c) { return c.reversed ? c.edge->start : c.edge->end; }

// The p-curve's (u, v) at t, clamped to the surface's domain (the check that it lies inside allows rounding).
std::pair<double, double> uv_at(const NurbsCurve& pcurve, double t, const Interval& du, const Interval& dv) {
    const Vec3 p = pcurve.point(std::clamp(t, pcurve.domain().min, pcurve.domain().max));
    return {std::clamp(p.x, du.min, du.max), std::clamp(p.y, dv.min, dv.max)};
}

// Where the face travels the p-curve from and to, in (u, v).
Vec3 traversal_start_uv(const Coedge& c) {
    return c.reversed ? c.pcurve->end_point() : c.pcurve->start_point();
}
Vec3 traversal_end_uv(const Coedge& c) { return c.reversed ? c.pcurve->start_point() : c.pcurve->end_point(); }

// The parameters at which a coedge's p-curve is compared with its edge: the knots of both curves and
// kSamplesPerSpan points inside each span between them, at most about kMaxSamples in all.
std::vector<double> check_parameters(const NurbsCurve& pcurve, const NurbsCurve& edge_curve) {
    std::vector<double> breaks = breakpoints(pcurve.degree(), pcurve.knots());
    const Interval d = pcurve.domain();
    for (double k : breakpoints(edge_curve.degree(), edge_curve.knots()))
        if (k > d.min && k < d.max) breaks.push_back(k);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const std::size_t spans = breaks.size() - 1;
    const int per_span = static_cast<int>(std::clamp<std::size_t>(kMaxSamples / std::max<std::size_t>(spans, 1), 1, kSamplesPerSpan));
    const std::size_t stride = std::max<std::size_t>(1, spans * static_cast<std::size_t>(per_span) / kMaxSamples);
    std::vector<double> ts;
    for (std::size_t k = 0; k < spans; k += stride) {
        for (int j = 0; j <= per_span; ++j) ts.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * j / (per_span + 1.0));
    }
    ts.push_back(d.max);
    return ts;
}

struct Gap {
    double distance = 0;
    double t = 0;  // where it is largest
};

// The largest distance between the surface along the coedge's p-curve and its edge, at check_parameters.
Gap largest_gap(const NurbsSurface& surface, const Coedge& c) {
    const Interval du = surface.domain_u(), dv = surface.domain_v(), ed = c.edge->curve.domain();
    Gap largest;
    for (double t : check_parameters(*c.pcurve, c.edge->curve)) {
        const auto [u, v] = uv_at(*c.pcurve, t, du, dv);
        const Vec3 on_edge = c.edge->degenerate ? c.edge->start->point : c.edge->curve.point(std::clamp(t, ed.min, ed.max));
        const double gap = distance(surface.point(u, v), on_edge);
        if (std::isnan(gap)) return {gap, t};  // beyond every tolerance
        if (gap > largest.distance) largest = {gap, t};
    }
    return largest;
}

}  // namespace

double pcurve_gap(const NurbsSurface& surface, const Coedge& coedge) {
    require(coedge.edge != nullptr && coedge.edge->start != nullptr && coedge.pcurve != nullptr, "coedge",
            "needs an edge with its vertices and a p-curve");
    return largest_gap(surface, coedge).distance;
}

Face Face::trimmed(NurbsSurface surface, std::vector<std::vector<Coedge>> loops, double tolerance) {
    const double size = surface.control_box().diagonal();
    require(size > 0 && std::isfinite(size), "surface", "must not collapse to a single point");
    require(std::isfinite(tolerance) && tolerance >= 0, "tolerance", "must be a finite number >= 0");
    require(!loops.empty(), "loops", "a trimmed face needs an outer loop");
    const double distance_tolerance = std::max(tolerance, detail::consistency_tolerance(surface.control_box()));
    const Interval du = surface.domain_u(), dv = surface.domain_v();
    const double domain_size = std::hypot(du.width(), dv.width());
    const double uv_tolerance = detail::kRelativeConsistency * domain_size;

    for (std::size_t l = 0; l < loops.size(); ++l) {
        const auto& loop = loops[l];
        require(!loop.empty(), "loops", "loop " + std::to_string(l) + " is empty");
        double signed_area = 0;
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const Coedge& c = loop[k];
            const std::string where = "loop " + std::to_string(l) + ", coedge " + std::to_string(k);
            require(c.edge != nullptr && c.edge->start != nullptr && c.edge->end != nullptr, "loops",
                    where + " has a missing edge or vertex");
            require(c.pcurve != nullptr, "loops", where + " has no p-curve (the edge in the face's (u, v))");
            const NurbsCurve& pcurve = *c.pcurve;
            const NurbsCurve& curve = c.edge->curve;
            const Interval pd = pcurve.domain(), ed = curve.domain();
            require(std::abs(pd.min - ed.min) <= 1e-12 * ed.width() + 1e-300 && std::abs(pd.max - ed.max) <= 1e-12 * ed.width() + 1e-300,
                    "loops", [&] {
                        return where + "'s p-curve must run over its edge's domain [" + detail::number(ed.min) + ", " +
                               detail::number(ed.max) + "], not [" + detail::number(pd.min) + ", " + detail::number(pd.max) + "]";
                    });
            const Box box = pcurve.control_box();
            require(box.min.z == 0 && box.max.z == 0, "loops", where + "'s p-curve must be 2D (z = 0)");
            require(box.min.x >= du.min - uv_tolerance && box.max.x <= du.max + uv_tolerance &&
                        box.min.y >= dv.min - uv_tolerance && box.max.y <= dv.max + uv_tolerance,
                    "loops", [&] {
                        return where + "'s p-curve leaves the surface's domain [" + detail::number(du.min) + ", " +
                               detail::number(du.max) + "] x [" + detail::number(dv.min) + ", " + detail::number(dv.max) + "]";
                    });
            const Gap gap = largest_gap(surface, c);
            require(gap.distance <= distance_tolerance, "loops", [&] {
                return where + ": the surface along the p-curve is " + detail::number(gap.distance) + " away from the edge at t = " +
                       detail::number(gap.t) + ", more than the face's tolerance " + detail::number(distance_tolerance);
            });
            const Coedge& next = loop[(k + 1) % loop.size()];
            require(traversal_end(c) == traversal_start(next), "loops",
                    where + " does not end at the Vertex object where the next coedge starts");
            require(next.pcurve != nullptr, "loops",
                    "loop " + std::to_string(l) + ", coedge " + std::to_string((k + 1) % loop.size()) + " has no p-curve");
            const double uv_gap = distance(traversal_end_uv(c), traversal_start_uv(next));
            require(uv_gap <= uv_tolerance, "loops", [&] {
                return where + "'s p-curve ends " + detail::number(uv_gap) +
                       " away (in (u, v)) from where the next one starts: the loop is open in the face's parameters";
            });
            // Green's theorem in (u, v): the signed area the loop encloses, to a margin far below the check.
            const double a = detail::green_area(pcurve, Vec3{}, Vec3{1, 0, 0}, Vec3{0, 1, 0},
                                                1e-13 * domain_size * domain_size, "loops");
            signed_area += c.reversed ? -a : a;
        }
        const double area_tolerance = 1e-12 * domain_size * domain_size;
        if (l == 0)
            require(signed_area > area_tolerance, "loops",
                    "the outer loop must run counterclockwise in the face's (u, v) and enclose an area");
        else
            require(signed_area < -area_tolerance, "loops",
                    "hole loop " + std::to_string(l) + " must run clockwise in the face's (u, v)");
    }

    Face face(Kind::trimmed, std::move(surface));
    face.loops_ = std::move(loops);
    face.tolerance_ = tolerance;
    return face;
}

}  // namespace ratbez

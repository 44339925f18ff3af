// Mesh-to-solid deviation (deviation.hpp).
//
// Every triangle is sampled on a barycentric lattice and each sample's distance to the solid's boundary
// is measured by point inversion: the nearest seed of a precomputed surface sampling (found through a
// uniform spatial grid) starts Newton's method on the two orthogonality conditions
// (S - P) . S_u = (S - P) . S_v = 0 (Piegl and Tiller, The NURBS Book, §6.1, Eq. 6.6–6.8), clamped to the
// face's domain, with a step-halving line search so it never walks uphill (point_inversion.hpp, shared
// with closest_point.hpp and the tessellator). Planar faces are handled exactly: the distance to the
// trimmed plane region is the distance to the plane where the foot lies inside the loops, else the distance
// to the nearest boundary curve (Newton on the curve from the nearest segment of its polyline, which
// segment_search.hpp finds, and the side, without a scan of every segment). Seeds are placed per
// weight-certified cell of each face (see detail::weight_cuts), and Newton also runs inside the cell of
// each nearby cell's best seed, so rational weights that crowd the geometry into a sliver of the parameter
// domain do not hide the foot.
//
// Trimmed faces are measured on their region: a foot whose (u, v) lies outside the region the p-curves bound
// (even-odd rule on a fine polyline of them) is replaced by the distance to the face's boundary curves, which
// bounds the distance to the region from above (an interior local minimum elsewhere in the region could
// only be nearer), so a mesh that strays over the trimmed-away part of a surface is measured, not excused.
//
// Only the maximum is wanted, so most samples are settled cheaply: the distance to any point of the
// surface bounds the true distance from above, and a warm start from the previous sample's foot gives
// such a point after a step or two. When that bound is already below the running maximum, the sample
// cannot raise it and the global search is skipped; the global search itself stops as soon as it
// finds a surface point within the running maximum. The result is still exact.

#include "ratbez/deviation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "analysis/point_inversion.hpp"
#include "geometry/subdivision.hpp"
#include "geometry/surface_evaluator.hpp"
#include "mesh/domain_triangulation.hpp"
#include "mesh/segment_search.hpp"
#include "mesh/triangle_grid.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez {
namespace {

using detail::ParameterBox;
using Foot = detail::ParameterFoot;

// The interior knot at t (up to rounding, where Newton settles on a corner), else NaN. Only a knot can
// be a corner of the curve; deciding the side there by the tangent of one span misjudged points
// inside the region near a polyline profile's corner as outside (seed 20262082, 5x the tolerance).
double interior_corner(const NurbsCurve& curve, double t) {
    const Interval d = curve.domain();
    const double near = 1e-9 * (d.max - d.min);
    for (double k : curve.knots())
        if (k > d.min && k < d.max && std::abs(k - t) <= near) return k;
    return std::numeric_limits<double>::quiet_NaN();
}

// The curve's one-sided tangent directions at interior knot k: the last leg of the control polygon of
// the Bézier segment ending there and the first leg of the one starting there (A5.6; a rational
// segment's end tangent is parallel to its end leg). Legs of zero length (repeated control points)
// are skipped.
std::pair<Vec3, Vec3> knot_legs(const NurbsCurve& curve, double k) {
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    const auto at = std::find(breaks.begin(), breaks.end(), k);
    const std::vector<BezierCurve> segments = curve.bezier_segments();
    const auto b = static_cast<std::size_t>(at - breaks.begin());
    if (at == breaks.end() || b == 0 || b >= segments.size()) return {curve.derivative(k, 1), curve.derivative(k, 1)};
    const std::vector<Vec3> left = segments[b - 1].points(), right = segments[b].points();
    Vec3 in{}, out{};
    for (std::size_t i = left.size() - 1; i > 0 && !(norm(in) > 0); --i) in = left.back() - left[i - 1];
    for (std::size_t i = 1; i < right.size() && !(norm(out) > 0); ++i) out = right[i] - right.front();
    return {in, out};
}

// A planar face: the plane, its boundary curves in loop order and a fine polyline of them that locates
// the nearest curve quickly.
struct PlanarRegion {
    struct Curve {
        const NurbsCurve* curve;
        const Edge* edge;
        bool reversed;
        std::size_t loop, next, previous;  // neighbours in loop order (indices into curves)
    };
    struct Segment {
        detail::Point2 a, b;
        std::size_t curve;
        double ta, tb;
    };
    Plane plane;
    std::vector<Curve> curves;
    std::vector<Segment> segments;
    double band = 0;  // how far the curves stray from their polyline at most (sampled): the even-odd rule's margin
    detail::EvenOddBands sides;              // the even-odd rule on the segments (index())
    detail::NearestSegment nearest_segment;  // the segments in the plane, z = 0 (index())

    void index() {
        std::vector<std::array<double, 4>> flat;
        std::vector<std::array<Vec3, 2>> lines;
        for (const Segment& s : segments) {
            flat.push_back({s.a.x, s.a.y, s.b.x, s.b.y});
            lines.push_back({Vec3{s.a.x, s.a.y, 0}, Vec3{s.b.x, s.b.y, 0}});
        }
        sides = detail::EvenOddBands(std::move(flat));
        nearest_segment = detail::NearestSegment(std::move(lines));
    }

    detail::Point2 to_plane(const Vec3& p) const {
        const Vec3 d = p - plane.origin;
        return {dot(d, plane.x_axis), dot(d, plane.y_axis)};
    }
    // The loop's direction of travel at parameter t of a curve, in plane coordinates.
    detail::Point2 loop_tangent(std::size_t c, double t) const {
        const Vec3 d = curves[c].curve->derivative(t, 1) * (curves[c].reversed ? -1.0 : 1.0);
        return {dot(d, plane.x_axis), dot(d, plane.y_axis)};
    }

    double distance_to(const Vec3& p) const {
        const double height = dot(p - plane.origin, plane.normal);
        const detail::Point2 q = to_plane(p);
        const std::optional<detail::NearestSegment::Found> found = nearest_segment.nearest(Vec3{q.x, q.y, 0});
        if (!found) return std::abs(height);
        const double best = found->squared_distance, fraction = found->fraction;
        const Segment* nearest = &segments[found->index];
        std::size_t index = nearest->curve;
        double t = detail::newton_foot_on_curve(*curves[index].curve, p, curves[index].curve->domain(),
                                               nearest->ta + fraction * (nearest->tb - nearest->ta));
        Vec3 foot = curves[index].curve->point(t);
        {
            // A foot at an end of the curve is a corner of the loop only if the neighbouring curve does
            // not come closer just past the joint: where weights crowd that curve's end into a sliver of
            // its parameters its polyline runs the last stretch in one segment, the nearest segment
            // then lies on this curve, and the corner rule with the neighbour's end tangent judged a
            // point inside a cap as outside (seed 20266302: 9x the tolerance). Newton on the
            // neighbour from the joint settles that.
            const Interval d = curves[index].curve->domain();
            const double end = 1e-12 * (d.max - d.min);
            const bool first = t <= d.min + end, last = t >= d.max - end;
            if (first || last) {
                // The joint is the loop's arrival at this curve (previous neighbour) or its departure.
                const bool arrival = first != curves[index].reversed;
                const std::size_t other = arrival ? curves[index].previous : curves[index].next;
                const Curve& c = curves[other];
                const Interval od = c.curve->domain();
                // The neighbour's end at the joint: its loop end (arrival) or loop start (departure).
                const double joint = arrival != c.reversed ? od.max : od.min;
                const double other_t = detail::newton_foot_on_curve(*c.curve, p, od, joint);
                const Vec3 other_foot = c.curve->point(other_t);
                const double other_end = 1e-12 * (od.max - od.min);
                const bool interior = other_t > od.min + other_end && other_t < od.max - other_end;
                if (interior && distance(other_foot, p) <= distance(foot, p)) index = other, t = other_t, foot = other_foot;
            }
        }
        // Farther from the polyline than the curves stray from it, the even-odd rule decides exactly, whatever
        // the corners (a loop that doubles back on itself, as the spike where a gull-wing lead's arc meets a
        // short line retracing it, defeats the tangent rules below). Closer, the rules at the foot decide; a
        // wrong decision there errs by less than the band.
        if (std::sqrt(best) > 2 * band) return sides.inside(q.x, q.y) ? std::abs(height) : distance(p, foot);
        const Curve& curve = curves[index];
        const Interval dom = curve.curve->domain();
        const detail::Point2 f2 = to_plane(foot);
        const detail::Point2 offset{q.x - f2.x, q.y - f2.y};
        auto left_of = [&](const detail::Point2& tangent) { return tangent.x * offset.y - tangent.y * offset.x >= 0; };
        const double end_tolerance = 1e-12 * (dom.max - dom.min);
        const bool at_start = t <= dom.min + end_tolerance, at_end = t >= dom.max - end_tolerance;
        bool inside;
        const double corner = interior_corner(*curve.curve, t);
        if (!at_start && !at_end && !std::isnan(corner)) {
            // A corner inside the curve (a C0 knot of a polyline piece): the same rule as at a corner
            // between curves, with the one-sided tangents either side of the knot. They are taken from
            // the control polygons of the two Bézier segments meeting there (their end legs), not by
            // evaluating at a small parameter offset: where weights crowd a segment into a sliver of
            // its parameters, an offset of 1e-7 of the domain can already run far along the curve and
            // its tangent there need not be the one at the knot. Where the two legs are parallel the
            // knot is no corner and the tangent at the foot decides.
            const auto [leg_in, leg_out] = knot_legs(*curve.curve, corner);
            const detail::Point2 a{dot(leg_in, plane.x_axis), dot(leg_in, plane.y_axis)};
            const detail::Point2 b{dot(leg_out, plane.x_axis), dot(leg_out, plane.y_axis)};
            // In loop order: the reversed curve arrives along -leg_out and leaves along -leg_in.
            const detail::Point2 tin = curve.reversed ? detail::Point2{-b.x, -b.y} : a;
            const detail::Point2 tout = curve.reversed ? detail::Point2{-a.x, -a.y} : b;
            const double turn = tin.x * tout.y - tin.y * tout.x;
            const double scale = std::hypot(tin.x, tin.y) * std::hypot(tout.x, tout.y);
            const bool convex = turn >= 0;
            if (!(scale > 0) || (std::abs(turn) <= 1e-12 * scale && tin.x * tout.x + tin.y * tout.y > 0))
                inside = left_of(loop_tangent(index, t));
            else
                inside = convex ? (left_of(tin) && left_of(tout)) : (left_of(tin) || left_of(tout));
        } else if (!at_start && !at_end) {
            inside = left_of(loop_tangent(index, t));
        } else {
            // At a corner: the region is the intersection (convex corner) or union (reflex corner) of the
            // half-planes left of the incoming and outgoing directions.
            const bool loop_start = at_start != curve.reversed;  // the loop arrives at this curve's first point
            std::size_t in_curve, out_curve;
            double t_in, t_out;
            if (loop_start) {
                in_curve = curve.previous, out_curve = index;
                const Interval d_in = curves[in_curve].curve->domain();
                t_in = curves[in_curve].reversed ? d_in.min : d_in.max;
                t_out = t;
            } else {
                in_curve = index, out_curve = curve.next;
                const Interval d_out = curves[out_curve].curve->domain();
                t_in = t;
                t_out = curves[out_curve].reversed ? d_out.max : d_out.min;
            }
            const detail::Point2 tin = loop_tangent(in_curve, t_in), tout = loop_tangent(out_curve, t_out);
            const bool convex = tin.x * tout.y - tin.y * tout.x >= 0;
            inside = convex ? (left_of(tin) && left_of(tout)) : (left_of(tin) || left_of(tout));
        }
        return inside ? std::abs(height) : distance(p, foot);
    }
};

// The polyline of a planar face's boundary goes per weight-certified piece of each span, like the seeds
// (point_inversion.hpp): uniform parameters over a span crowded by its weights miss the crowded geometry.
// `count` parameters per certified piece of the span [t0, t1] (the piece's start included, its end not).
void add_certified_params(double t0, double t1, const std::vector<double>& cuts, int count, std::vector<double>& out) {
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
        for (int i = 0; i < count; ++i) {
            const double s = cuts[c] + (cuts[c + 1] - cuts[c]) * i / count;
            out.push_back(t0 + (t1 - t0) * s);
        }
}

PlanarRegion make_region(const Face& face) {
    PlanarRegion region;
    region.plane = face.plane();
    for (std::size_t l = 0; l < face.loops().size(); ++l) {
        const auto& loop = face.loops()[l];
        const std::size_t first = region.curves.size();
        for (const Coedge& coedge : loop) {
            if (coedge.edge->degenerate) continue;
            region.curves.push_back({&coedge.edge->curve, coedge.edge.get(), coedge.reversed, l, 0, 0});
        }
        const std::size_t count = region.curves.size() - first;
        for (std::size_t k = 0; k < count; ++k) {
            region.curves[first + k].next = first + (k + 1) % count;
            region.curves[first + k].previous = first + (k + count - 1) % count;
        }
    }
    for (std::size_t c = 0; c < region.curves.size(); ++c) {
        const NurbsCurve& curve = *region.curves[c].curve;
        const Interval d = curve.domain();
        // 64 segments per knot span (at least 8 per weight-certified piece of it): fine enough that the
        // nearest segment lies on the nearest curve.
        std::vector<double> params;
        const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
        const std::vector<BezierCurve> segments = curve.bezier_segments();
        for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
            std::vector<double> weights;
            for (const Vec4& pw : segments[b].homogeneous_points()) weights.push_back(pw.w);
            const std::vector<double> cuts = detail::weight_cuts({weights}, detail::kMaxHalvings);
            const int count = std::max(8, 64 / static_cast<int>(cuts.size() - 1));
            add_certified_params(breaks[b], breaks[b + 1], cuts, count, params);
        }
        params.push_back(d.max);
        // The polyline's ends are the edge's vertices, which the loop's neighbouring edges share: the loop's
        // polyline then closes exactly, which the even-odd rule of planar_samples needs (edge curves that meet
        // 1e-13 apart put a row through a corner on both sides of it, and a hole's inside counted as face).
        const Edge& edge = *region.curves[c].edge;
        const auto at = [&](std::size_t k) {
            if (k == 0) return region.to_plane(edge.start->point);
            if (k + 1 == params.size()) return region.to_plane(edge.end->point);
            return region.to_plane(curve.point(params[k]));
        };
        for (std::size_t k = 0; k + 1 < params.size(); ++k) {
            region.segments.push_back({at(k), at(k + 1), c, params[k], params[k + 1]});
            const detail::Point2 a = region.segments.back().a, b = region.segments.back().b;
            for (double f : {0.25, 0.5, 0.75}) {
                const detail::Point2 m = region.to_plane(curve.point(params[k] + f * (params[k + 1] - params[k])));
                const double cx = a.x + f * (b.x - a.x) - m.x, cy = a.y + f * (b.y - a.y) - m.y;
                region.band = std::max(region.band, std::hypot(cx, cy));
            }
        }
    }
    region.index();
    return region;
}

// A trimmed face's region: its p-curves as a polyline in (u, v) for the inside test, and its boundary edges
// as 3D polylines that locate the nearest edge for a foot outside the region.
struct TrimmedRegion {
    struct Segment2 {
        double u0, v0, u1, v1;
    };
    struct Segment3 {
        Vec3 a, b;
        const NurbsCurve* curve;
        double ta, tb;
    };
    std::vector<Segment2> uv;
    std::vector<Segment3> edges;

    bool empty() const { return uv.empty(); }

    // Even-odd rule on the p-curves' polyline.
    bool contains(double u, double v) const { return sides_.inside(u, v); }

    // The distance from p to the nearest boundary edge: the nearest polyline segment, then Newton on its curve.
    double boundary_distance(const Vec3& p) const {
        const std::optional<detail::NearestSegment::Found> found = nearest_.nearest(p);
        if (!found) return std::numeric_limits<double>::infinity();
        const Segment3& nearest = edges[found->index];
        const double t = detail::newton_foot_on_curve(*nearest.curve, p, nearest.curve->domain(),
                                                      nearest.ta + found->fraction * (nearest.tb - nearest.ta));
        return std::min(std::sqrt(found->squared_distance), distance(p, nearest.curve->point(t)));
    }

    // The search structures of the (u, v) and the 3D polylines.
    void index() {
        std::vector<std::array<double, 4>> flat;
        for (const Segment2& s : uv) flat.push_back({s.u0, s.v0, s.u1, s.v1});
        sides_ = detail::EvenOddBands(std::move(flat));
        std::vector<std::array<Vec3, 2>> lines;
        for (const Segment3& e : edges) lines.push_back({e.a, e.b});
        nearest_ = detail::NearestSegment(std::move(lines));
    }

private:
    detail::EvenOddBands sides_;
    detail::NearestSegment nearest_;
};

// 64 parameters per knot span of a curve (its end included), per weight-certified piece at least 8; a curve of
// many spans (a fitted p-curve of 800) 8 per span: its spans are short already.
std::vector<double> fine_params(const NurbsCurve& curve) {
    std::vector<double> params;
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    const std::vector<BezierCurve> segments = curve.bezier_segments();
    const int per_span = breaks.size() > 65 ? 8 : 64;
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
        std::vector<double> weights;
        for (const Vec4& pw : segments[b].homogeneous_points()) weights.push_back(pw.w);
        const std::vector<double> cuts = detail::weight_cuts({weights}, detail::kMaxHalvings);
        add_certified_params(breaks[b], breaks[b + 1], cuts, std::max(8, per_span / static_cast<int>(cuts.size() - 1)), params);
    }
    params.push_back(curve.domain().max);
    return params;
}

TrimmedRegion make_trimmed_region(const Face& face) {
    TrimmedRegion region;
    for (const auto& loop : face.loops()) {
        // One closed polyline per loop, in the loop's direction, each coedge's first point the previous one's
        // last (p-curves meet to rounding, and the even-odd rule needs an exactly closed polyline).
        std::vector<Vec3> chain;
        for (const Coedge& coedge : loop) {
            std::vector<double> ts = fine_params(*coedge.pcurve);
            if (coedge.reversed) std::reverse(ts.begin(), ts.end());
            for (std::size_t k = chain.empty() ? 0 : 1; k < ts.size(); ++k) chain.push_back(coedge.pcurve->point(ts[k]));
        }
        chain.back() = chain.front();
        for (std::size_t k = 0; k + 1 < chain.size(); ++k)
            region.uv.push_back({chain[k].x, chain[k].y, chain[k + 1].x, chain[k + 1].y});
        for (const Coedge& coedge : loop) {
            if (coedge.edge->degenerate) continue;
            const std::vector<double> es = fine_params(coedge.edge->curve);
            for (std::size_t k = 0; k + 1 < es.size(); ++k)
                region.edges.push_back({coedge.edge->curve.point(es[k]), coedge.edge->curve.point(es[k + 1]),
                                        &coedge.edge->curve, es[k], es[k + 1]});
        }
    }
    region.index();
    return region;
}

struct Seed {
    Vec3 point;
    std::uint32_t face;
    double u, v;
    std::uint32_t patch;  // the face's cell (pair of weight-certified pieces, detail::SeedParams) the seed lies in
};

// Uniform grid over seeds: nearest-seed and radius queries visit only nearby cells. It puts the seeds, which
// its owner keeps, in the order of their cells, so a query reads them in runs.
class SeedGrid {
public:
    SeedGrid(std::span<Seed> seeds, double cell) : seeds_(seeds) {
        lo_ = hi_ = seeds.front().point;
        for (const Seed& s : seeds) {
            lo_ = {std::min(lo_.x, s.point.x), std::min(lo_.y, s.point.y), std::min(lo_.z, s.point.z)};
            hi_ = {std::max(hi_.x, s.point.x), std::max(hi_.y, s.point.y), std::max(hi_.z, s.point.z)};
        }
        const double extent = std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z, 1e-300});
        // At most 128 cells along the box and about as many cells as seeds: a class of a few small faces in a large
        // solid keeps a few cells, not 128^3 offsets (100 MB for a pulley's classes).
        cell_ = std::max(cell, extent / 128);
        const auto cells = [&] {
            double n = 1;
            for (int a = 0; a < 3; ++a) n *= 1 + std::floor(((&hi_.x)[a] - (&lo_.x)[a]) / cell_);
            return n;
        };
        while (cells() > 2.0 * static_cast<double>(seeds.size()) + 8) cell_ *= 1.25;
        for (int a = 0; a < 3; ++a) dims_[a] = 1 + static_cast<int>(((&hi_.x)[a] - (&lo_.x)[a]) / cell_);
        start_.assign(static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
        for (const Seed& s : seeds) ++start_[flat(cell_of(s.point)) + 1];
        for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
        const std::vector<Seed> unsorted(seeds.begin(), seeds.end());
        std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
        for (const Seed& s : unsorted) seeds[fill[flat(cell_of(s.point))]++] = s;
    }

    // Calls visit(seed) for every seed in the cells overlapping the box of half-width r around p.
    template <class Visit>
    void for_each_near(const Vec3& p, double r, Visit&& visit) const {
        std::array<int, 3> a{}, b{};
        for (int k = 0; k < 3; ++k) {
            a[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] - r - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
            b[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] + r - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
        }
        for (int x = a[0]; x <= b[0]; ++x)
            for (int y = a[1]; y <= b[1]; ++y)
                for (int z = a[2]; z <= b[2]; ++z) {
                    const std::size_t c = flat({x, y, z});
                    for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) visit(seeds_[k]);
                }
    }

    // The distance from p to its nearest seed (grows the search box until it holds the answer), or a
    // distance above `within` when no seed lies within `within`.
    double nearest_distance(const Vec3& p, double within = std::numeric_limits<double>::infinity()) const {
        for (double r = cell_;; r *= 2) {
            double best = std::numeric_limits<double>::infinity();
            for_each_near(p, r, [&](const Seed& s) { best = std::min(best, distance(s.point, p)); });
            if (best <= r || r > within || r > 4 * (norm(hi_ - lo_) + distance(p, 0.5 * (lo_ + hi_)) + cell_)) return best;
        }
    }

private:
    std::array<int, 3> cell_of(const Vec3& p) const {
        std::array<int, 3> c{};
        for (int k = 0; k < 3; ++k)
            c[k] = std::clamp(static_cast<int>(std::floor(((&p.x)[k] - (&lo_.x)[k]) / cell_)), 0, dims_[k] - 1);
        return c;
    }
    std::size_t flat(const std::array<int, 3>& c) const {
        return static_cast<std::size_t>((c[0] * dims_[1] + c[1]) * dims_[2] + c[2]);
    }
    std::span<const Seed> seeds_;  // in the order of their cells
    std::vector<std::size_t> start_;
    Vec3 lo_, hi_;
    double cell_ = 1;
    std::array<int, 3> dims_{1, 1, 1};
};

class DeviationMeter {
public:
    explicit DeviationMeter(const Solid& solid) {
        std::vector<Seed> seeds;
        const auto& faces = solid.faces();
        regions_.resize(faces.size());
        trimmed_.resize(faces.size());
        evaluators_.resize(faces.size());
        cells_.resize(faces.size());
        cell_spacing_.resize(faces.size());
        cell_box_.resize(faces.size());
        face_spacing_.assign(faces.size(), 0.0);
        slot_.assign(faces.size(), kNoSlot);
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const Face& face = faces[f];
            const auto id = static_cast<std::uint32_t>(f);
            if (face.kind() != Face::Kind::planar) evaluators_[f] = std::make_unique<detail::SurfaceEvaluator>(face.surface());
            if (face.kind() == Face::Kind::trimmed) trimmed_[f] = make_trimmed_region(face);
            if (face.kind() == Face::Kind::planar) {
                regions_[f] = make_region(face);
                for (const auto& s : regions_[f].segments) {
                    seeds.push_back({regions_[f].curves[s.curve].curve->point(s.ta), id, 0, 0, 0});
                    face_spacing_[f] = std::max(face_spacing_[f], std::hypot(s.b.x - s.a.x, s.b.y - s.a.y));
                }
            }
            // Surface faces, and the plane patch of planar faces (its interior seeds lie in the region's box).
            const NurbsSurface& s = face.surface();
            const Interval du = s.domain_u(), dv = s.domain_v();
            const std::vector<std::vector<BezierSurface>> patches = s.bezier_patches();
            const detail::SeedParams seeds_u = detail::seed_params(patches, true, s.knots_u(), s.degree_u());
            const detail::SeedParams seeds_v = detail::seed_params(patches, false, s.knots_v(), s.degree_v());
            const std::vector<double>& us = seeds_u.params;
            const std::vector<double>& vs = seeds_v.params;
            cells_[f] = {seeds_u.pieces, seeds_v.pieces};
            cell_spacing_[f].assign(seeds_u.pieces.size() * seeds_v.pieces.size(), 0.0);
            cell_box_[f].assign(seeds_u.pieces.size() * seeds_v.pieces.size(), Box{});
            const std::size_t nu = us.size() - 1, nv = vs.size() - 1;
            // "The same point" up to rounding relative to the face's size: evaluating a pole row at
            // different u gives points that differ in the last bits, and bit equality missed them.
            const double coincident = 1e-12 * (norm(s.point(du.max, dv.max) - s.point(du.min, dv.min)) +
                                               norm(s.point((du.min + du.max) / 2, (dv.min + dv.max) / 2)) + 1e-300);
            auto same = [coincident](const Vec3& a, const Vec3& b) { return distance(a, b) <= coincident; };
            std::vector<Vec3> row_previous;
            const auto pieces_v = static_cast<std::uint32_t>(seeds_v.pieces.size());
            for (std::size_t i = 0; i <= nu; ++i) {
                std::vector<Vec3> row;
                for (std::size_t j = 0; j <= nv; ++j) {
                    const double u = us[i], v = vs[j];
                    const Vec3 p = s.point(u, v);
                    // No seeds on a collapsed row (a pole): there every u gives the same point, Newton
                    // cannot turn u, and the seeds of the first ring around it start better.
                    const bool collapsed_u = (i > 0 && same(p, row_previous[j])) || (i == 0 && same(p, s.point(us[1], v)));
                    const bool collapsed_v = !row.empty() && same(p, row.back());
                    const std::uint32_t cell = seeds_u.piece[i] * pieces_v + seeds_v.piece[j];
                    if (!collapsed_u && !collapsed_v) seeds.push_back({p, id, u, v, cell});
                    cell_box_[f][cell].add(p);
                    // A gap between neighbouring seeds counts for the cells of both.
                    auto gap = [&](double d, std::uint32_t other) {
                        face_spacing_[f] = std::max(face_spacing_[f], d);
                        cell_spacing_[f][cell] = std::max(cell_spacing_[f][cell], d);
                        cell_spacing_[f][other] = std::max(cell_spacing_[f][other], d);
                    };
                    if (j > 0) gap(distance(p, row.back()), seeds_u.piece[i] * pieces_v + seeds_v.piece[j - 1]);
                    if (i > 0) gap(distance(p, row_previous[j]), seeds_u.piece[i - 1] * pieces_v + seeds_v.piece[j]);
                    row.push_back(p);
                }
                row_previous = std::move(row);
            }
        }
        // The seeds in classes of their faces' spacing, powers of two apart, each class in its own grid.
        double finest = std::numeric_limits<double>::infinity();
        for (const double h : face_spacing_)
            if (h > 0) finest = std::min(finest, h);
        const auto class_of = [&](const Seed& seed) {
            return std::isfinite(finest) ? std::ilogb(std::max(face_spacing_[seed.face], finest)) : 0;
        };
        std::stable_sort(seeds.begin(), seeds.end(), [&](const Seed& a, const Seed& b) { return class_of(a) < class_of(b); });
        seeds_ = std::move(seeds);
        for (std::size_t first = 0, last = 0; first < seeds_.size(); first = last) {
            double reach = 0;
            for (last = first; last < seeds_.size() && class_of(seeds_[last]) == class_of(seeds_[first]); ++last)
                reach = std::max(reach, face_spacing_[seeds_[last].face]);
            classes_.push_back({reach, SeedGrid(std::span(seeds_).subspan(first, last - first), reach)});
        }
    }

    // The exact distance from p to the solid's boundary; `warm` is set to the winning face and foot.
    // The search stops once it has a surface point within `enough` (the caller's running maximum: the
    // sample cannot raise it); the result is then that point's distance, an upper bound.
    double distance_to_solid(const Vec3& p, std::uint32_t& face, Foot& warm, double enough = -1) const {
        double nearest = std::numeric_limits<double>::infinity();
        for (const SeedClass& c : classes_) nearest = std::min(nearest, c.grid.nearest_distance(p, nearest));
        // The few best seeds of every face with a seed within reach of the nearest one. Several, not one:
        // at a seam the nearest seed may sit on the far side of the parameter domain (u = 0 for a point at
        // u = 0.98), where Newton's step is clamped away; a neighbouring seed starts on the right side.
        // And the best seed of every cell within reach: the distance has a local minimum in each
        // patch the point faces (a polyline profile), and only a start in the right patch finds it.
        constexpr std::size_t kSeedsPerFace = 4;
        using Candidate = std::pair<double, const Seed*>;
        // The faces within reach, few of a solid's many (a keyboard case's 991): a short list, found through
        // slot_ (a face's place in it, cleared again on return). A search of the list for every seed took 43 % of
        // a faceted pulley's export, hundreds of its 2,688 faces within reach of each point.
        std::vector<std::pair<std::uint32_t, std::vector<Candidate>>> best;
        const SlotsCleared cleared{slot_, best};
        const auto best_of = [&](std::uint32_t f) -> std::vector<Candidate>& {
            std::uint32_t& slot = slot_[f];
            if (slot == kNoSlot) {
                slot = static_cast<std::uint32_t>(best.size());
                best.emplace_back(f, std::vector<Candidate>{});
            }
            return best[slot].second;
        };
        std::unordered_map<std::uint64_t, std::vector<Candidate>> per_cell;
        // A face's foot lies within about twice its own seed spacing of one of its seeds (a cell's corner): a
        // face whose seeds here are all farther than nearest + 3 of its spacing cannot hold it. One large face sent
        // every query to all 1481 small faces of a Voron lock body (10.9 s for 2,242 triangles) before the seeds
        // were held to that, and still through them all (a faceted pulley: 3 cylinders beside 2,685 small planes,
        // most of what was left of its export) before each class of spacing was searched only as far as its reach.
        const auto visit = [&](const Seed& s) {
            const double d = distance(s.point, p);
            if (d > nearest + 3 * face_spacing_[s.face]) return;
            per_cell[(std::uint64_t{s.face} << 32) | s.patch].emplace_back(d, &s);
            auto& list = best_of(s.face);
            if (list.size() == kSeedsPerFace && d >= list.back().first) return;
            if (list.size() == kSeedsPerFace) list.pop_back();
            list.insert(std::upper_bound(list.begin(), list.end(), std::make_pair(d, &s),
                                         [](const auto& a, const auto& b) { return a.first < b.first; }),
                        {d, &s});
        };
        for (const SeedClass& c : classes_) c.grid.for_each_near(p, nearest + 3 * c.reach, visit);
        double result = std::numeric_limits<double>::infinity();
        // Keeps the better foot; true once the result is within `enough`.
        auto take = [&](std::size_t f, Foot foot) {
            foot = on_region(f, p, foot);
            if (foot.distance < result) result = foot.distance, face = static_cast<std::uint32_t>(f), warm = foot;
            return result <= enough;
        };
        std::sort(best.begin(), best.end(), [](const auto& a, const auto& b) { return a.first < b.first; });  // in face order
        for (std::size_t k = 0; k < best.size(); ++k) slot_[best[k].first] = static_cast<std::uint32_t>(k);
        for (const auto& [f, seeds] : best) {
            if (!regions_[f].curves.empty()) {
                if (take(f, Foot{0, 0, regions_[f].distance_to(p)})) return result;
                continue;
            }
            const detail::SurfaceEvaluator& s = *evaluators_[f];
            for (const auto& [seed_distance, seed] : seeds)
                if (take(f, detail::newton_foot_on_surface(s, p, {s.domain_u(), s.domain_v()}, seed->u, seed->v, {50, enough}))) return result;
        }
        // Each cell's best seed, with Newton over the whole face and kept inside the cell. Where extreme
        // weights crowd a face into a thin band of parameters, the distance is a long narrow valley in
        // (u, v), and Newton from a seed outside the band crawls along it (seed 20261262: 50 iterations
        // ended 33x farther than the foot; 2000 got there). In a weight-certified cell the
        // parameterisation is tame and Newton usually converges; a foot in another cell is found from
        // that cell's seed. Neither start alone found every foot of the round trip test's first 1000
        // cases at weights 10^+-3; both did. Every result is the distance to a surface point, so the
        // smallest is an upper bound of the distance and, with all the starts, the distance itself.
        // Every point of a cell lies within its seed spacing of the box of its seeds, so the distance to
        // that box minus twice the spacing (a margin) bounds the distance to the cell from below. Cells
        // are taken by that bound and skipped once it reaches the best distance found: most cells of a
        // face that extreme weights cut into many sit where the surface all but stops, at one place.
        // Within a cell the distance can still have several local minima (seed 20268472: Newton from the
        // cell's nearest seed stopped on the cell's edge 172 away from a foot at distance 0, which the
        // cell's second seed found), so every seed of the cell within reach starts a Newton run in the
        // cell, nearest first, until the cell's lower bound reaches the best distance found.
        std::vector<std::pair<double, std::vector<Candidate>*>> cells;
        for (auto& [key, candidates] : per_cell) {
            const Seed& seed = *candidates.front().second;
            if (!regions_[seed.face].curves.empty()) continue;
            std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            const double margin = 2 * cell_spacing_[seed.face][seed.patch];
            cells.emplace_back(cell_box_[seed.face][seed.patch].distance_to(p) - margin, &candidates);
        }
        std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [lower_bound, candidates] : cells) {
            if (lower_bound >= result) break;
            const Seed& first = *candidates->front().second;
            const detail::SurfaceEvaluator& s = *evaluators_[first.face];
            const ParameterBox box = cell_box(first.face, first.patch);
            for (const auto& [seed_distance, seed_pointer] : *candidates) {
                if (lower_bound >= result) break;
                const Seed& seed = *seed_pointer;
                if (take(seed.face, detail::newton_foot_on_surface(s, p, box, seed.u, seed.v, {50, enough}))) return result;
            }
            const auto& firsts = best_of(first.face);
            if (std::none_of(firsts.begin(), firsts.end(), [&](const Candidate& c) { return c.second == &first; }))
                if (take(first.face, detail::newton_foot_on_surface(s, p, {s.domain_u(), s.domain_v()}, first.u, first.v, {50, enough}))) return result;
        }
        return result;
    }

    // An upper bound of the distance from p to the solid, cheap when the warm start is close: the
    // distance to the face `face` reached from `warm` (refined in place), stopping at `enough`.
    double upper_bound(const Vec3& p, std::uint32_t face, Foot& warm, double enough) const {
        if (!regions_[face].curves.empty()) return regions_[face].distance_to(p);
        const detail::SurfaceEvaluator& s = *evaluators_[face];
        warm = detail::newton_foot_on_surface(s, p, {s.domain_u(), s.domain_v()}, warm.u, warm.v, {8, enough});
        return on_region(face, p, warm).distance;
    }

private:
    static constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();
    // Clears the slots of the faces a query listed, however it returns.
    struct SlotsCleared {
        std::vector<std::uint32_t>& slot;
        const std::vector<std::pair<std::uint32_t, std::vector<std::pair<double, const Seed*>>>>& listed;
        ~SlotsCleared() {
            for (const auto& entry : listed) slot[entry.first] = kNoSlot;
        }
    };

    // A foot on a trimmed face's surface outside its region counts as the distance to its boundary edges.
    Foot on_region(std::size_t f, const Vec3& p, const Foot& foot) const {
        if (trimmed_[f].empty() || trimmed_[f].contains(foot.u, foot.v)) return foot;
        return Foot{foot.u, foot.v, std::max(foot.distance, trimmed_[f].boundary_distance(p))};
    }

    // The parameter box of cell `cell` of face f (Seed::patch).
    ParameterBox cell_box(std::size_t f, std::uint32_t cell) const {
        const auto& [pieces_u, pieces_v] = cells_[f];
        return {pieces_u[cell / pieces_v.size()], pieces_v[cell % pieces_v.size()]};
    }

    std::vector<PlanarRegion> regions_;
    std::vector<TrimmedRegion> trimmed_;  // trimmed faces
    // Per face: the weight-certified pieces along u and along v, whose products are its cells.
    std::vector<std::pair<std::vector<Interval>, std::vector<Interval>>> cells_;
    // Per face and cell: the largest distance between neighbouring seeds of the cell (or its edge), and
    // the box of its seed points.
    std::vector<std::vector<double>> cell_spacing_;
    std::vector<std::vector<Box>> cell_box_;
    std::vector<std::unique_ptr<detail::SurfaceEvaluator>> evaluators_;  // surface faces
    // The seeds of the faces whose spacing is within a power of two, in a grid of that spacing; `reach` is the
    // largest spacing of those faces.
    struct SeedClass {
        double reach;
        SeedGrid grid;
    };
    std::vector<Seed> seeds_;  // by class, then (SeedGrid) by cell
    std::vector<SeedClass> classes_;
    // Per face, its place in a query's list of faces within reach (kNoSlot outside a query): scratch of
    // distance_to_solid, so one query at a time (max_deviation's loop).
    mutable std::vector<std::uint32_t> slot_;
    std::vector<double> face_spacing_;  // per face, the largest distance between neighbouring seeds
};

}  // namespace

namespace {

void require_valid(const Mesh& mesh, const DeviationOptions& options) {
    require(options.samples_per_edge >= 1 && options.samples_per_edge <= 1000, "options.samples_per_edge",
            "must be in [1, 1000]");
    for (const Vec3& v : mesh.vertices) require(is_finite(v), "mesh", "has a vertex with non-finite coordinates");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t index : mesh.triangles[t])
            require(index < mesh.vertices.size(), "mesh", [&] {
                return "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(index) + " of " +
                       std::to_string(mesh.vertices.size());
            });
}

// Parameters along one direction of a surface at a spacing of about h in space: every weight-certified
// piece of every knot span (seed_params) cut into as many equal parts as its longest isocurve, measured
// along a few isocurves of the other direction, is long in units of h.
std::vector<double> coverage_params(const NurbsSurface& s, const std::vector<std::vector<BezierSurface>>& patches,
                                    bool along_u, double h) {
    const detail::SeedParams pieces = along_u ? detail::seed_params(patches, true, s.knots_u(), s.degree_u())
                                              : detail::seed_params(patches, false, s.knots_v(), s.degree_v());
    const Interval other = along_u ? s.domain_v() : s.domain_u();
    std::vector<double> params{pieces.pieces.front().min};
    for (const Interval& piece : pieces.pieces) {
        double length = 0;
        for (int q = 0; q <= 4; ++q) {
            // The ends exactly (an affine step past the last can land an ulp outside the domain).
            const double w = q == 4 ? other.max : other.min + (other.max - other.min) * q / 4.0;
            auto at = [&](double t) { return along_u ? s.point(t, w) : s.point(w, t); };
            double l = 0;
            Vec3 previous = at(piece.min);
            for (int k = 1; k <= 8; ++k) {
                const Vec3 p = at(k == 8 ? piece.max : piece.min + (piece.max - piece.min) * k / 8.0);
                l += distance(p, previous);
                previous = p;
            }
            length = std::max(length, l);
        }
        const int parts = static_cast<int>(std::clamp(std::ceil(length / h), 1.0, 1e5));
        for (int k = 1; k <= parts; ++k) params.push_back(k == parts ? piece.max : piece.min + (piece.max - piece.min) * k / parts);
    }
    return params;
}

// Points of a planar face's region at a spacing of about h: its boundary curves' polyline (make_region)
// and a grid of rows in the plane filled between the crossings of each row with the polyline (even-odd).
std::vector<Vec3> planar_samples(const PlanarRegion& region, double h) {
    std::vector<Vec3> out;
    auto to_space = [&](double x, double y) { return region.plane.origin + region.plane.x_axis * x + region.plane.y_axis * y; };
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& seg : region.segments) {
        const double length = std::hypot(seg.b.x - seg.a.x, seg.b.y - seg.a.y);
        const int parts = static_cast<int>(std::clamp(std::ceil(length / h), 1.0, 1e5));
        for (int k = 0; k < parts; ++k) {
            const double f = static_cast<double>(k) / parts;
            out.push_back(to_space(seg.a.x + f * (seg.b.x - seg.a.x), seg.a.y + f * (seg.b.y - seg.a.y)));
        }
        x0 = std::min({x0, seg.a.x, seg.b.x}), x1 = std::max({x1, seg.a.x, seg.b.x});
        y0 = std::min({y0, seg.a.y, seg.b.y}), y1 = std::max({y1, seg.a.y, seg.b.y});
    }
    if (!(x1 > x0 && y1 > y0)) return out;
    const int rows = static_cast<int>(std::clamp(std::ceil((y1 - y0) / h), 1.0, 1e5));
    std::vector<double> crossings;
    for (int r = 0; r < rows; ++r) {
        const double y = y0 + (y1 - y0) * (r + 0.5) / rows;
        crossings.clear();
        for (const auto& seg : region.segments)
            if ((seg.a.y <= y) != (seg.b.y <= y)) crossings.push_back(seg.a.x + (y - seg.a.y) / (seg.b.y - seg.a.y) * (seg.b.x - seg.a.x));
        std::sort(crossings.begin(), crossings.end());
        for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
            for (double x = crossings[k]; x <= crossings[k + 1]; x += h) out.push_back(to_space(x, y));
    }
    return out;
}

}  // namespace

double max_surface_to_mesh_distance(const Solid& solid, const Mesh& mesh, const DeviationOptions& options) {
    require_valid(mesh, options);
    if (mesh.triangles.empty()) return std::numeric_limits<double>::infinity();
    const detail::TriangleGrid grid(mesh);
    // As many samples as max_deviation takes on the mesh: (n + 1)(n + 2) / 2 per triangle.
    const double n = options.samples_per_edge;
    const double samples = static_cast<double>(mesh.triangles.size()) * (n + 1) * (n + 2) / 2;
    const double h = std::sqrt(std::max(mesh.area(), 1e-300) / samples);
    double worst = 0;
    SurfaceGrid points;
    for (const Face& face : solid.faces()) {
        if (face.kind() == Face::Kind::planar) {
            for (const Vec3& p : planar_samples(make_region(face), h)) worst = std::max(worst, grid.distance(p));
            continue;
        }
        const NurbsSurface& s = face.surface();
        const auto patches = s.bezier_patches();
        const std::vector<double> us = coverage_params(s, patches, true, h), vs = coverage_params(s, patches, false, h);
        // A trimmed face: the grid points inside its region and its boundary edges at the spacing h.
        const TrimmedRegion region = face.kind() == Face::Kind::trimmed ? make_trimmed_region(face) : TrimmedRegion{};
        for (const auto& segment : region.edges) {
            const int parts = static_cast<int>(std::clamp(std::ceil(distance(segment.a, segment.b) / h), 1.0, 1e5));
            for (int k = 0; k < parts; ++k)
                worst = std::max(worst, grid.distance(segment.curve->point(segment.ta + (segment.tb - segment.ta) * k / parts)));
        }
        // A row of the grid at a time, so memory stays with the row, not the face.
        for (double u : us) {
            evaluate_grid(s, std::span<const double>(&u, 1), vs, GridOutput::points, points);
            for (std::size_t k = 0; k < points.points.size(); ++k)
                if (region.empty() || region.contains(u, vs[k])) worst = std::max(worst, grid.distance(points.points[k]));
        }
    }
    return worst;
}

double max_deviation(const Solid& solid, const Mesh& mesh, const DeviationOptions& options) {
    require_valid(mesh, options);
    if (mesh.triangles.empty()) return 0;

    const DeviationMeter meter(solid);
    const int n = options.samples_per_edge;
    double worst = 0;
    std::uint32_t face = 0;
    Foot warm;
    bool have_warm = false;
    // A triangle's samples can each take a region search over many faces (a lock body's 1481: 2 ms a triangle),
    // so the progress, and with it Ctrl-C, is polled every few triangles.
    constexpr std::size_t kTrianglesPerReport = 16;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        if (options.progress && k % kTrianglesPerReport == 0)
            options.progress(static_cast<double>(k) / static_cast<double>(mesh.triangles.size()));
        const auto& t = mesh.triangles[k];
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double wb = static_cast<double>(i) / n, wc = static_cast<double>(j) / n;
                const Vec3 p = a * (1 - wb - wc) + b * wb + c * wc;
                if (have_warm && meter.upper_bound(p, face, warm, worst) <= worst) continue;
                worst = std::max(worst, meter.distance_to_solid(p, face, warm, worst));
                have_warm = true;
            }
    }
    if (options.progress) options.progress(1.0);
    return worst;
}

}  // namespace ratbez

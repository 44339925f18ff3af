// Point inversion from a start, and the certified seed parameters (point_inversion.hpp).

#include "analysis/point_inversion.hpp"

#include <array>
#include <cmath>

#include "geometry/subdivision.hpp"
#include "ratbez/bspline_basis.hpp"

namespace ratbez::detail {
namespace {

// A descent step (step_u, step_v) for F = |S - P|^2 / 2 from the 2x2 system [a b; b c] (du, dv) = -(f, g),
// where (f, g) = (S - P) . (S_u, S_v) is F's gradient. A parameter sitting on its bound with the gradient
// pushing it out of the domain is held there and the system solved for the other one (the active set of
// projected Newton, Bertsekas 1982): the full step would be clamped back and could then point uphill,
// which stalled the search on faces whose nearest point lies on their boundary (a profile joint).
struct Step {
    double u = 0, v = 0;
};
Step descent_step(double a, double b, double c, double f, double g, bool hold_u, bool hold_v) {
    // Marquardt damping, relative to each diagonal entry, keeps the solve finite where a partial
    // vanishes (poles, apexes). A damping shared by both (1e-12 (a + c)) swamped the smaller entry where
    // extreme weights make one partial 1e8 times the other (a profile span crowded into 1e-8 of its
    // parameters): the step along the other direction all but vanished and Newton stopped 10x the
    // tolerance from the foot (seed 20268482).
    const double floor = 1e-20 * (a + c) + 1e-300;
    a += 1e-12 * a + floor, c += 1e-12 * c + floor;
    if (hold_u && hold_v) return {};
    if (hold_u) return {0, -g / c};
    if (hold_v) return {-f / a, 0};
    // Solved with the diagonal scaled to 1 (Jacobi), so that a * c - b * b does not lose the
    // determinant to cancellation when the two partials differ by many orders of magnitude.
    const double su = std::sqrt(a), sv = std::sqrt(c);
    const double r = b / (su * sv);
    const double det = 1 - r * r;
    if (!(det > 0)) return {};
    const double fu = f / su, gv = g / sv;
    return {-(fu - r * gv) / det / su, -(gv - r * fu) / det / sv};
}

}  // namespace

ParameterFoot newton_foot_on_surface(const SurfaceEvaluator& s, const Vec3& p, const ParameterBox& box, double u,
                                     double v, const NewtonStop& stop) {
    const Interval du = box.u, dv = box.v;
    ParameterFoot best{u, v, distance(s.point(u, v), p)};
    // Tries the step from best (S there: `at`); true when it lowered the distance by a visible move.
    auto try_step = [&](Step step, const Vec3& at, const Vec3& su, const Vec3& sv, bool& moved) {
        double reach = norm(su * step.u + sv * step.v);
        if (!(reach > 0) || !std::isfinite(reach)) return false;
        const double shrink = std::min(1.0, 2 * best.distance / reach);
        step.u *= shrink, step.v *= shrink, reach *= shrink;
        const double noise = 1e-15 * (norm(at) + best.distance);
        for (int halving = 0; halving < 40 && (!stop.at_rounding || reach > noise); ++halving, reach *= 0.5) {
            const double nu = std::clamp(best.u + step.u, du.min, du.max);
            const double nv = std::clamp(best.v + step.v, dv.min, dv.max);
            const double dist = distance(s.point(nu, nv), p);
            if (dist < best.distance) {
                moved = std::abs(nu - best.u) + std::abs(nv - best.v) > 1e-15 * ((du.max - du.min) + (dv.max - dv.min));
                best = {nu, nv, dist};
                return true;
            }
            step.u *= 0.5, step.v *= 0.5;
        }
        return false;
    };
    for (int iteration = 0; iteration < stop.max_iterations && best.distance > stop.good_enough; ++iteration) {
        const SurfaceJet d = s.jet(best.u, best.v);
        const DistanceGradient e = distance_gradient(d.s, d.su, d.sv, p);
        const bool hold_u = (best.u <= du.min && e.f > 0) || (best.u >= du.max && e.f < 0);
        const bool hold_v = (best.v <= dv.min && e.g > 0) || (best.v >= dv.max && e.g < 0);
        // Newton's matrix: the Gauss-Newton one plus the terms in the second derivatives (Eq. 6.8).
        const double ha = e.a + dot(e.r, d.suu), hb = e.b + dot(e.r, d.suv), hc = e.c + dot(e.r, d.svv);
        bool moved = false;
        // Only the free parameters' part of Newton's matrix must be positive definite: on a side (one
        // parameter held) a saddle across it does not stop the 1D Newton step along it (random rational
        // bicubics otherwise fell back to Gauss-Newton there, whose step along the side was twice too
        // long, and oscillated about the side's minimum for all 50 iterations, stopping 2e-3 short).
        const bool definite = hold_u ? (hold_v || hc > 0) : hold_v ? ha > 0 : ha > 0 && hc > 0 && ha * hc - hb * hb > 0;
        const bool newton_ok = definite && try_step(descent_step(ha, hb, hc, e.f, e.g, hold_u, hold_v), d.s, d.su, d.sv, moved);
        if (!newton_ok && !try_step(descent_step(e.a, e.b, e.c, e.f, e.g, hold_u, hold_v), d.s, d.su, d.sv, moved)) break;
        if (!moved) break;
    }
    return best;
}

// The step is halved up to 60 times (not 12): where weights crowd a span into a sliver of its
// parameters, the curve turns through a half circle within 1e-6 of the domain, a step of 1/4096 of the
// Newton step still overshot, and the search stopped at a knot that was no foot, where the side test of
// deviation.cpp's planar regions then judged a point inside a cap as outside (seed 20268692: 16x the
// tolerance).
double newton_foot_on_curve(const NurbsCurve& curve, const Vec3& p, const Interval& box, double t,
                            const NewtonStop& stop) {
    const Interval d = box;
    // The start inside the box: callers interpolate it between parameters, which can round past an end.
    t = std::clamp(t, d.min, d.max);
    double best_t = t, best = distance(curve.point(t), p);
    for (int iteration = 0; iteration < stop.max_iterations; ++iteration) {
        std::array<Vec3, 3> der;
        curve.derivatives(best_t, der);
        const Vec3 r = der[0] - p;
        const double f = dot(r, der[1]);
        double fp = dot(der[1], der[1]) + dot(r, der[2]);
        if (fp <= 0) fp = dot(der[1], der[1]);
        if (!(fp > 0)) break;
        double step = -f / fp;
        bool improved = false;
        const double noise = 1e-15 * (norm(der[0]) + best);
        for (int halving = 0; halving < 60 && (!stop.at_rounding || std::abs(step) * norm(der[1]) > noise); ++halving) {
            const double nt = std::clamp(best_t + step, d.min, d.max);
            const double dist = distance(curve.point(nt), p);
            if (dist < best) {
                improved = std::abs(nt - best_t) > 1e-15 * (d.max - d.min);
                best = dist, best_t = nt;
                break;
            }
            step *= 0.5;
        }
        if (!improved) break;
    }
    return best_t;
}

SeedParams seed_params(const std::vector<std::vector<BezierSurface>>& patches, bool along_u,
                       const std::vector<double>& knots, int degree) {
    const std::vector<double> breaks = breakpoints(degree, knots);
    const std::size_t spans = breaks.size() - 1;
    const auto per_span = static_cast<int>(std::clamp<std::size_t>(96 / spans, 2, static_cast<std::size_t>(3 * std::max(degree, 1) + 3)));
    SeedParams out;
    for (std::size_t k = 0; k < spans; ++k) {
        // The weight lines of span k along the direction: every row (along v) or column (along u) of
        // every patch in that span.
        std::vector<std::vector<double>> lines;
        const std::size_t others = along_u ? patches[k].size() : patches.size();
        for (std::size_t o = 0; o < others; ++o) {
            const BezierSurface& patch = along_u ? patches[k][o] : patches[o][k];
            const int rows = patch.degree_u() + 1, columns = patch.degree_v() + 1;
            const int line_count = along_u ? columns : rows, length = along_u ? rows : columns;
            for (int line = 0; line < line_count; ++line) {
                std::vector<double> weights;
                for (int i = 0; i < length; ++i) {
                    const int r = along_u ? i : line, c = along_u ? line : i;
                    weights.push_back(patch.homogeneous_points()[static_cast<std::size_t>(r * columns + c)].w);
                }
                lines.push_back(std::move(weights));
            }
        }
        const std::vector<double> cuts = weight_cuts(lines, kMaxHalvings);
        const int count = cuts.size() == 2 ? per_span : std::max(2, per_span / 2);
        const double t0 = breaks[k], t1 = breaks[k + 1];
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            const double a = c == 0 ? t0 : t0 + (t1 - t0) * cuts[c];
            const double b = c + 2 == cuts.size() ? t1 : t0 + (t1 - t0) * cuts[c + 1];
            for (int i = 0; i < count; ++i) {
                out.params.push_back(a + (b - a) * i / count);
                out.piece.push_back(static_cast<std::uint32_t>(out.pieces.size()));
            }
            // A span's last piece stops one rounding short of the next span: at the knot itself the
            // evaluator takes the next span's derivatives, and Newton, clamped to this piece, read a
            // gradient pushing out of it there and stalled on the piece's end (seed 20261482: S_v
            // 2e5 inside the piece, 5 at the knot).
            const bool before_knot = c + 2 == cuts.size() && k + 1 < spans;
            out.pieces.push_back({a, before_knot ? std::nextafter(b, a) : b});
            out.span.push_back(static_cast<std::uint32_t>(k));
            out.fraction.push_back({cuts[c], cuts[c + 1]});
        }
    }
    out.params.push_back(breaks.back());  // the domain's end exactly
    out.piece.push_back(static_cast<std::uint32_t>(out.pieces.size() - 1));
    return out;
}

}  // namespace ratbez::detail

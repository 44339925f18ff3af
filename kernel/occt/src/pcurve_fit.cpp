// P-curves of imported trimmed faces (pcurve_fit.hpp).

#include "pcurve_fit.hpp"

#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt::detail {
namespace {

// The breakpoints of a curve with `per_span` equal steps inside each span (the domain's end included).
std::vector<double> span_samples(const NurbsCurve& curve, int per_span) {
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    std::vector<double> ts;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
        for (int j = 0; j < per_span; ++j) ts.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * j / per_span);
    ts.push_back(breaks.back());
    return ts;
}

// Rounds of refinement of a fit, and samples at most: a smooth p-curve converges in a few (cubic interpolation
// errs as h^4); a p-curve of 10^4 spans is sampled per span already.
constexpr int kMaxRounds = 12;
constexpr std::size_t kMaxSamples = 20'000;

}  // namespace

PcurveFitter::PcurveFitter(const NurbsSurface& surface, double size)
    : surface_(surface), size_(size), occt_(to_occt(surface)) {}

gp_Pnt2d PcurveFitter::clamped(const gp_Pnt2d& uv) const {
    const Interval du = surface_.domain_u(), dv = surface_.domain_v();
    return {std::clamp(uv.X(), du.min, du.max), std::clamp(uv.Y(), dv.min, dv.max)};
}

gp_Pnt2d PcurveFitter::project(const gp_Pnt& p, const gp_Pnt2d& guess) {
    // Newton's method on the foot conditions (S - P) . S_u = (S - P) . S_v = 0 in its Gauss–Newton form (the
    // first fundamental form as the matrix; The NURBS Book §6.1), from the guess, clamped to the domain, each
    // step halved until the distance decreases. Local on purpose: a global search would land a point of a
    // seam on either side of it, the guess knows which.
    const Interval du = surface_.domain_u(), dv = surface_.domain_v();
    gp_Pnt2d uv = clamped(guess);
    gp_Pnt s;
    gp_Vec su, sv;
    occt_->D1(uv.X(), uv.Y(), s, su, sv);
    double best = s.SquareDistance(p);
    const double stop = 1e-14 * std::max(1.0, du.width() + dv.width());
    for (int iteration = 0; iteration < 40; ++iteration) {
        const gp_Vec r(p, s);
        const double a = su.SquareMagnitude(), b = su.Dot(sv), c = sv.SquareMagnitude();
        const double f = r.Dot(su), g = r.Dot(sv);
        // Along a pole one direction has no length: step in the other alone (its parameter stays the guess's).
        const double scale = std::max(a, c);
        double step_u = 0, step_v = 0;
        if (a <= 1e-14 * scale) {
            step_v = c > 0 ? -g / c : 0;
        } else if (c <= 1e-14 * scale) {
            step_u = -f / a;
        } else {
            const double det = a * c - b * b;
            if (!(std::abs(det) > 1e-14 * a * c)) break;
            step_u = (-f * c + g * b) / det;
            step_v = (-g * a + f * b) / det;
        }
        bool improved = false;
        for (int halving = 0; halving < 20; ++halving) {
            const gp_Pnt2d next(std::clamp(uv.X() + step_u, du.min, du.max), std::clamp(uv.Y() + step_v, dv.min, dv.max));
            gp_Pnt ns;
            gp_Vec nsu, nsv;
            occt_->D1(next.X(), next.Y(), ns, nsu, nsv);
            const double d = ns.SquareDistance(p);
            if (d < best) {
                const double moved = std::abs(next.X() - uv.X()) + std::abs(next.Y() - uv.Y());
                uv = next, s = ns, su = nsu, sv = nsv, best = d, improved = true;
                if (moved <= stop) return uv;
                break;
            }
            step_u *= 0.5, step_v *= 0.5;
        }
        if (!improved) break;
    }
    return uv;
}

double PcurveFitter::deviation(const NurbsCurve& candidate, const NurbsCurve& edge) const {
    const Interval d = edge.domain();
    double worst = 0;
    for (double t : span_samples(candidate, 4)) {
        const Vec3 uv = candidate.point(std::clamp(t, candidate.domain().min, candidate.domain().max));
        const gp_Pnt2d q = clamped(gp_Pnt2d(uv.x, uv.y));
        worst = std::max(worst, distance(surface_.point(q.X(), q.Y()), edge.point(std::clamp(t, d.min, d.max))));
    }
    for (double t : span_samples(edge, 4)) {
        const Vec3 uv = candidate.point(std::clamp(t, candidate.domain().min, candidate.domain().max));
        const gp_Pnt2d q = clamped(gp_Pnt2d(uv.x, uv.y));
        worst = std::max(worst, distance(surface_.point(q.X(), q.Y()), edge.point(t)));
    }
    return worst;
}

FittedPcurve PcurveFitter::fit(const NurbsCurve& edge, const std::function<gp_Pnt2d(double)>& guess,
                               const NurbsCurve* exact_candidate, double tolerance, bool guess_exact) {
    const Interval d = edge.domain();
    if (exact_candidate != nullptr) {
        const Interval c = exact_candidate->domain();
        const Box box = exact_candidate->control_box();
        const Interval du = surface_.domain_u(), dv = surface_.domain_v();
        const double slack = 1e-9 * std::hypot(du.width(), dv.width());
        if (std::abs(c.min - d.min) <= 1e-12 * d.width() && std::abs(c.max - d.max) <= 1e-12 * d.width() &&
            box.min.x >= du.min - slack && box.max.x <= du.max + slack && box.min.y >= dv.min - slack &&
            box.max.y <= dv.max + slack) {
            const double gap = deviation(*exact_candidate, edge);
            if (gap <= std::max(tolerance, 1e-9 * size_)) return {exact_candidate->reparameterized(d.min, d.max), gap, true};
        }
    }

    // Samples: every span of the edge in 4, then the middles of the intervals where the fit strays.
    std::vector<double> ts = span_samples(edge, edge.degree() <= 1 ? 2 : 4);
    if (ts.size() < 9) {
        ts.clear();
        for (int k = 0; k <= 8; ++k) ts.push_back(k == 8 ? d.max : d.min + d.width() * k / 8.0);
    }
    std::vector<gp_Pnt2d> uvs;
    const auto sample = [&](double t) { return project(to_occt_point(edge.point(std::clamp(t, d.min, d.max))), guess(t)); };
    for (double t : ts) uvs.push_back(sample(t));
    // Where the fit must agree with the projections: far below the face's tolerance, above rounding.
    const double fit_tolerance = std::max(1e-3 * tolerance, 1e-10 * size_);
    // The cubic through the samples (A9.1), over the edge's domain; none where two samples sit on one place.
    const auto interpolated = [&](const std::vector<double>& at, const std::vector<gp_Pnt2d>& through) -> std::optional<NurbsCurve> {
        const int n = static_cast<int>(at.size());
        Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, n);
        Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, n);
        for (int k = 0; k < n; ++k) {
            points->SetValue(k + 1, through[static_cast<std::size_t>(k)]);
            parameters->SetValue(k + 1, at[static_cast<std::size_t>(k)]);
        }
        try {
            Geom2dAPI_Interpolate interpolate(points, parameters, Standard_False, 1e-15 * std::max(1.0, d.width()));
            interpolate.Perform();
            if (!interpolate.IsDone()) return std::nullopt;
            // The ends exactly where the samples are (OCCT's knots carry the parameters as given; the ends of
            // the domain are the first and last sample).
            return from_occt_2d(interpolate.Curve()).reparameterized(d.min, d.max);
        } catch (const Standard_Failure&) {
            return std::nullopt;
        }
    };
    std::optional<NurbsCurve> best;
    for (int round = 0; round < kMaxRounds; ++round) {
        std::optional<NurbsCurve> through = interpolated(ts, uvs);
        if (!through) break;  // the best fit so far, if any
        NurbsCurve candidate = std::move(*through);
        // Check the middle of every interval against the projection there; refine where they differ.
        std::vector<double> added_t;
        std::vector<gp_Pnt2d> added_uv;
        for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
            const double t = 0.5 * (ts[k] + ts[k + 1]);
            const Vec3 fitted = candidate.point(t);
            const gp_Pnt2d projected = sample(t);
            const gp_Pnt2d q = clamped(gp_Pnt2d(fitted.x, fitted.y));
            if (distance(surface_.point(q.X(), q.Y()), surface_.point(projected.X(), projected.Y())) > fit_tolerance)
                added_t.push_back(t), added_uv.push_back(projected);
        }
        best = std::move(candidate);
        if (added_t.empty() || ts.size() + added_t.size() > kMaxSamples) break;
        // Merge the new samples in order.
        std::vector<double> merged_t;
        std::vector<gp_Pnt2d> merged_uv;
        std::size_t a = 0;
        for (std::size_t k = 0; k < ts.size(); ++k) {
            merged_t.push_back(ts[k]), merged_uv.push_back(uvs[k]);
            if (a < added_t.size() && k + 1 < ts.size() && added_t[a] > ts[k] && added_t[a] < ts[k + 1])
                merged_t.push_back(added_t[a]), merged_uv.push_back(added_uv[a]), ++a;
        }
        ts = std::move(merged_t), uvs = std::move(merged_uv);
    }
    if (!best && guess_exact) {
        // The edge's projection folds (two samples land on one place): its 3D curve keeps far from the surface, as
        // far as the file's tolerance for it (a Voron LED mount's 0.4 mm sliver face, its circle 0.36 off it at
        // tolerance 0.56). The file's own p-curve, then, fitted as it is, where it keeps within the face's tolerance
        // of the edge (the file says the edge may be that far from its face); the deviation records the gap.
        std::vector<gp_Pnt2d> guesses;
        for (double t : ts) guesses.push_back(guess(t));
        best = interpolated(ts, guesses);
        if (best && !(deviation(*best, edge) <= tolerance)) best.reset();
    }
    require(best.has_value(), "shape", "an edge's curve on its face could not be fitted (its projection is not smooth)");
    // Inside the surface's domain (a fit may overshoot it by rounding where the edge runs along a side).
    std::vector<Vec4> poles = best->homogeneous_points();
    const Interval du = surface_.domain_u(), dv = surface_.domain_v();
    for (Vec4& p : poles) {
        p.x = std::clamp(p.x / p.w, du.min, du.max) * p.w;
        p.y = std::clamp(p.y / p.w, dv.min, dv.max) * p.w;
        p.z = 0;
    }
    NurbsCurve curve = NurbsCurve::from_homogeneous(best->degree(), best->knots(), std::move(poles), best->is_rational());
    const double gap = deviation(curve, edge);
    return {std::move(curve), gap, false};
}

}  // namespace ratbez::occt::detail

// Joining curves end to start into one NURBS curve; see join.hpp.
#include "ratbez/join.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/clamping.hpp"
#include "geometry/knot_removal.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/compatible_curves.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// Relative joint tolerance, as Profile's: above the rounding of exact constructions, below any real gap.
constexpr double kRelativeTolerance = 1e-9;

}  // namespace

NurbsCurve join(const std::vector<NurbsCurve>& input) {
    require(!input.empty(), "curves", "must contain at least one curve");
    int p = 0;
    Box box;
    for (std::size_t k = 0; k < input.size(); ++k) {
        require(input[k].degree() >= 1, "curves", [&] { return "curve " + std::to_string(k) + " has degree 0 (a point)"; });
        require(input[k].control_box().diagonal() > 0, "curves",
                [&] { return "curve " + std::to_string(k) + " is a single point"; });
        p = std::max(p, input[k].degree());
        box.add(input[k].control_box());
    }
    const double tolerance = kRelativeTolerance * box.diagonal();

    // Each curve keeps the width of its domain, unless the widths are so far apart that doubles cannot
    // hold one curve's domain after the others' (a curve of width 1 after one of 1e300: 1e300 + 1 == 1e300,
    // and the internal name of reparameterized()'s bound came out, issue 29): then every curve gets a domain
    // of width 1, [k, k + 1]. A curve whose own knots cannot be spread over that either is refused by name.
    std::size_t placing = 0;
    const auto build = [&](bool unit_widths) {
        std::vector<double> knots;
        std::vector<Vec4> points;
        std::vector<double> joints;  // the parameters where curve k meets curve k + 1
        bool rational = false;
        for (std::size_t k = 0; k < input.size(); ++k) {
            placing = k;
            NurbsCurve curve = elevate_degree(detail::clamped_ends(input[k]), p - input[k].degree());
            rational = rational || curve.is_rational();
            if (k == 0) {
                if (unit_widths) curve = curve.reparameterized(0.0, 1.0);
                knots = curve.knots();
                points = curve.homogeneous_points();
                continue;
            }
            const Vec3 previous_end = project(points.back());
            const double gap = distance(previous_end, curve.start_point());
            require(gap <= tolerance, "curves", [&] {
                return "curve " + std::to_string(k) + " starts at " + detail::format_point(curve.start_point()) + ", " +
                       detail::number(gap) + " away from the end " + detail::format_point(previous_end) + " of curve " +
                       std::to_string(k - 1) + " (curves must meet end to start)";
            });
            // Continue the domain: [end, end + width].
            const Interval d = curve.domain();
            const double start = knots.back();
            const double width = unit_widths ? 1.0 : d.width();
            // The width as it lands after `start`: one that rounding shrinks by more than a part in 1e9 would move
            // the curve's inner knots (reparameterized() refuses merged ones), so the widths are given up for 1.
            if (!unit_widths && !(std::abs((start + width) - start - width) <= 1e-9 * width))
                throw Error("b", "the domains' widths are too far apart");
            curve = curve.reparameterized(start, start + width);
            // One homogeneous polygon: scale the weights so that the shared point has the previous weight.
            std::vector<Vec4> pw = curve.homogeneous_points();
            const double scale = points.back().w / pw.front().w;
            for (Vec4& q : pw) q *= scale;
            joints.push_back(start);
            knots.pop_back();  // the end knot of multiplicity p + 1 becomes an interior knot of multiplicity p
            knots.insert(knots.end(), curve.knots().begin() + p + 1, curve.knots().end());
            points.insert(points.end(), pw.begin() + 1, pw.end());
        }
        // The last knot written for the domain end must be exact: reparameterized() maps ends exactly.
        const double homogeneous = detail::homogeneous_tolerance(points, tolerance);
        for (const double u : joints) detail::remove_knot(p, knots, points, u, p, homogeneous);
        if (!rational)
            for (Vec4& q : points) q.w = 1.0;
        return NurbsCurve::from_homogeneous(p, std::move(knots), std::move(points), rational);
    };
    try {
        return build(false);
    } catch (const Error& e) {
        if (e.argument() != "b") throw;
    }
    try {
        return build(true);
    } catch (const Error& e) {
        if (e.argument() != "b") throw;
        throw Error("curves", "curve " + std::to_string(placing) +
                                  "'s knots cannot be spread over a domain of width 1 after the others' (its knot "
                                  "spans are too unequal to continue the joined curve's domain)");
    }
}

}  // namespace ratbez

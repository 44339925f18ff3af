// Joining curves end to start into one NURBS curve; see join.hpp.
#include "ratbez/join.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry_internal.hpp"
#include "numeric_internal.hpp"
#include "ratbez/compatible_curves.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// Relative joint tolerance, as Profile's: above the rounding of exact constructions, below any real gap.
constexpr double kRelativeTolerance = 1e-9;

double distance4(const Vec4& a, const Vec4& b) {
    const Vec4 d = a - b;
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + d.w * d.w);
}

// A5.8 (RemoveCurveKnot): removes the interior knot u up to `num` times from (knots, pw) in place, as long
// as the curve moves by at most `tolerance` (in 4D; see the caller). Returns how many times it was removed.
int remove_knot(int p, std::vector<double>& U, std::vector<Vec4>& Pw, double u, int num, double tolerance) {
    const int n = static_cast<int>(Pw.size()) - 1;
    const int m = n + p + 1;
    const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;  // last index of u
    const int s = static_cast<int>(std::count(U.begin(), U.end(), u));
    const int ord = p + 1;
    const int fout = (2 * r - s - p) / 2;  // first control point out
    int last = r - s, first = r - p;
    std::vector<Vec4> temp(to_size(2 * p + 1));
    int t = 0;
    for (; t < num; ++t) {
        // Eq. 5.28: new control points from both ends towards the middle.
        const int off = first - 1;  // index difference between temp and Pw
        temp[0] = Pw[to_size(off)];
        temp[to_size(last + 1 - off)] = Pw[to_size(last + 1)];
        int i = first, j = last, ii = 1, jj = last - off;
        while (j - i > t) {
            const double alfi = (u - U[to_size(i)]) / (U[to_size(i + ord + t)] - U[to_size(i)]);
            const double alfj = (u - U[to_size(j - t)]) / (U[to_size(j + ord)] - U[to_size(j - t)]);
            temp[to_size(ii)] = (Pw[to_size(i)] - (1.0 - alfi) * temp[to_size(ii - 1)]) * (1.0 / alfi);
            temp[to_size(jj)] = (Pw[to_size(j)] - alfj * temp[to_size(jj + 1)]) * (1.0 / (1.0 - alfj));
            ++i, ++ii;
            --j, --jj;
        }
        bool removable;
        if (j - i < t) {
            removable = distance4(temp[to_size(ii - 1)], temp[to_size(jj + 1)]) <= tolerance;
        } else {
            const double alfi = (u - U[to_size(i)]) / (U[to_size(i + ord + t)] - U[to_size(i)]);
            removable = distance4(Pw[to_size(i)], alfi * temp[to_size(ii + t + 1)] + (1.0 - alfi) * temp[to_size(ii - 1)]) <=
                        tolerance;
        }
        if (!removable) break;
        i = first;
        j = last;
        while (j - i > t) {
            Pw[to_size(i)] = temp[to_size(i - off)];
            Pw[to_size(j)] = temp[to_size(j - off)];
            ++i;
            --j;
        }
        --first;
        ++last;
    }
    if (t == 0) return 0;
    for (int k = r + 1; k <= m; ++k) U[to_size(k - t)] = U[to_size(k)];
    U.resize(U.size() - to_size(t));
    int j = fout, i = j;  // Pw[j] .. Pw[i] are overwritten
    for (int k = 1; k < t; ++k)
        if (k % 2 == 1)
            ++i;
        else
            --j;
    for (int k = i + 1; k <= n; ++k) Pw[to_size(j++)] = Pw[to_size(k)];
    Pw.resize(Pw.size() - to_size(t));
    return t;
}

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

    std::vector<double> knots;
    std::vector<Vec4> points;
    std::vector<double> joints;  // the parameters where curve k meets curve k + 1
    bool rational = false;
    for (std::size_t k = 0; k < input.size(); ++k) {
        NurbsCurve curve = elevate_degree(detail::clamped_ends(input[k]), p - input[k].degree());
        rational = rational || curve.is_rational();
        if (k == 0) {
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
        curve = curve.reparameterized(start, start + d.width());
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
    // A5.8's tolerance is in homogeneous space: d w_min / (1 + |P|_max) keeps the Euclidean change below d.
    double w_min = points.front().w, p_max = 0;
    for (const Vec4& q : points) {
        w_min = std::min(w_min, q.w);
        p_max = std::max(p_max, norm(project(q)));
    }
    const double homogeneous_tolerance = tolerance * w_min / (1.0 + p_max);
    for (const double u : joints) remove_knot(p, knots, points, u, p, homogeneous_tolerance);
    if (!rational)
        for (Vec4& q : points) q.w = 1.0;
    return NurbsCurve::from_homogeneous(p, std::move(knots), std::move(points), rational);
}

}  // namespace ratbez

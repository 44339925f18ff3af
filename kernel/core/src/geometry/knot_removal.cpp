// Knot removal (A5.8); see knot_removal.hpp.
#include "geometry/knot_removal.hpp"

#include <algorithm>
#include <cmath>

#include "math/numeric_internal.hpp"

namespace ratbez::detail {

namespace {

double distance4(const Vec4& a, const Vec4& b) {
    const Vec4 d = a - b;
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + d.w * d.w);
}

}  // namespace

int remove_knot(int p, std::vector<double>& U, std::vector<Vec4>& Pw, double u, int num, double tolerance) {
    // A5.8 with the book's names: r the last index of u, s its multiplicity, temp the new points.
    const int n = static_cast<int>(Pw.size()) - 1;
    const int m = n + p + 1;
    const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
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

double homogeneous_tolerance(const std::vector<Vec4>& pw, double tolerance) {
    double w_min = pw.front().w, p_max = 0;
    for (const Vec4& q : pw) {
        w_min = std::min(w_min, q.w);
        p_max = std::max(p_max, norm(project(q)));
    }
    return tolerance * w_min / (1.0 + p_max);
}

NurbsCurve without_removable_knots(const NurbsCurve& curve, double tolerance) {
    const int p = curve.degree();
    std::vector<double> knots = curve.knots();
    std::vector<Vec4> pw = curve.homogeneous_points();
    const double d = homogeneous_tolerance(pw, tolerance);
    const Interval domain = curve.domain();
    std::vector<double> interior;
    for (const double u : knots)
        if (u > domain.min && u < domain.max && (interior.empty() || interior.back() != u)) interior.push_back(u);
    for (const double u : interior) remove_knot(p, knots, pw, u, p, d);
    return NurbsCurve::from_homogeneous(p, std::move(knots), std::move(pw), curve.is_rational());
}

}  // namespace ratbez::detail

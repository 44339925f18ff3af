// Degree elevation (A5.9) and knot-vector merging: see compatible_curves.hpp.
#include "ratbez/compatible_curves.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/clamping.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

using detail::binomial;
using detail::to_size;

// Knots of different curves closer than this (on the common domain [0, 1]) are one knot.
constexpr double kKnotMergeDistance = 1e-12;

}  // namespace

NurbsCurve elevate_degree(const NurbsCurve& input, int times) {
    require(times >= 0, "times", [&] { return "must be >= 0, got " + std::to_string(times); });
    if (times == 0) return input;
    // A5.9 works on a clamped knot vector; clamping changes the representation only.
    const NurbsCurve curve = detail::clamped_ends(input);
    if (curve.degree() == 0) {
        // A constant: the same point t + 1 times on the domain's ends (A5.9 needs a span to walk).
        const Interval d = curve.domain();
        std::vector<double> knots(to_size(times + 1), d.min);
        knots.insert(knots.end(), to_size(times + 1), d.max);
        return NurbsCurve::from_homogeneous(times, std::move(knots),
                                            std::vector<Vec4>(to_size(times + 1), curve.homogeneous_points().front()),
                                            curve.is_rational());
    }
    const int p = curve.degree(), t = times, ph = p + t, ph2 = ph / 2;
    const std::vector<double>& U = curve.knots();
    const std::vector<Vec4>& Pw = curve.homogeneous_points();
    const int m = static_cast<int>(U.size()) - 1;

    // The Bézier degree elevation coefficients: bezalfs[i][j] = C(p, j) C(t, i - j) / C(ph, i).
    std::vector<std::vector<double>> bezalfs(to_size(ph + 1), std::vector<double>(to_size(p + 1), 0.0));
    bezalfs[0][0] = bezalfs[to_size(ph)][to_size(p)] = 1.0;
    for (int i = 1; i <= ph2; ++i) {
        const double inv = 1.0 / binomial(ph, i);
        for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
            bezalfs[to_size(i)][to_size(j)] = inv * binomial(p, j) * binomial(t, i - j);
    }
    for (int i = ph2 + 1; i <= ph - 1; ++i)
        for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
            bezalfs[to_size(i)][to_size(j)] = bezalfs[to_size(ph - i)][to_size(p - j)];

    std::vector<double> Uh;
    std::vector<Vec4> Qw;
    Uh.reserve(U.size() * to_size(t + 1));
    Qw.reserve(Pw.size() * to_size(t + 1));
    std::vector<Vec4> bpts(to_size(p + 1)), ebpts(to_size(ph + 1)), next_bpts(to_size(std::max(p - 1, 1)));
    std::vector<double> alfs(to_size(std::max(p - 1, 1)));

    int r = -1, a = p, b = p + 1;
    double ua = U[0];
    Qw.push_back(Pw[0]);
    Uh.assign(to_size(ph + 1), ua);
    for (int i = 0; i <= p; ++i) bpts[to_size(i)] = Pw[to_size(i)];
    while (b < m) {
        // The next break point ub and its multiplicity.
        const int first_of_run = b;
        while (b < m && U[to_size(b)] == U[to_size(b + 1)]) ++b;
        const int mul = b - first_of_run + 1;
        const double ub = U[to_size(b)];
        const int oldr = r;
        r = p - mul;
        // Insert ub r times (A5.1 in place on the segment) to finish the Bézier segment [ua, ub].
        const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
        const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
        if (r > 0) {
            const double numer = ub - ua;
            for (int k = p; k > mul; --k) alfs[to_size(k - mul - 1)] = numer / (U[to_size(a + k)] - ua);
            for (int j = 1; j <= r; ++j) {
                const int save = r - j, s = mul + j;
                for (int k = p; k >= s; --k)
                    bpts[to_size(k)] = alfs[to_size(k - s)] * bpts[to_size(k)] + (1.0 - alfs[to_size(k - s)]) * bpts[to_size(k - 1)];
                next_bpts[to_size(save)] = bpts[to_size(p)];
            }
        }
        // Elevate the Bézier segment (only points lbz..ph are used below).
        for (int i = lbz; i <= ph; ++i) {
            ebpts[to_size(i)] = Vec4{};
            for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
                ebpts[to_size(i)] += bezalfs[to_size(i)][to_size(j)] * bpts[to_size(j)];
        }
        if (oldr > 1) {
            // Remove the knot ua oldr - 1 times again: the elevated curve keeps its continuity there.
            const int kind = static_cast<int>(Uh.size());  // A5.9's kind and cind are Uh.size() and Qw.size()
            int first = kind - 2, last = kind;
            const double den = ub - ua;
            const double bet = (ub - Uh[to_size(kind - 1)]) / den;
            for (int tr = 1; tr < oldr; ++tr) {
                int i = first, j = last, kj = j - kind + 1;
                while (j - i > tr) {
                    if (i < static_cast<int>(Qw.size())) {
                        const double alf = (ub - Uh[to_size(i)]) / (ua - Uh[to_size(i)]);
                        Qw[to_size(i)] = alf * Qw[to_size(i)] + (1.0 - alf) * Qw[to_size(i - 1)];
                    }
                    if (j >= lbz) {
                        if (j - tr <= kind - ph + oldr) {
                            const double gam = (ub - Uh[to_size(j - tr)]) / den;
                            ebpts[to_size(kj)] = gam * ebpts[to_size(kj)] + (1.0 - gam) * ebpts[to_size(kj + 1)];
                        } else {
                            ebpts[to_size(kj)] = bet * ebpts[to_size(kj)] + (1.0 - bet) * ebpts[to_size(kj + 1)];
                        }
                    }
                    ++i;
                    --j;
                    --kj;
                }
                --first;
                ++last;
            }
        }
        if (a != p)  // load the knot ua
            for (int i = 0; i < ph - oldr; ++i) Uh.push_back(ua);
        for (int j = lbz; j <= rbz; ++j) Qw.push_back(ebpts[to_size(j)]);
        if (b < m) {
            for (int j = 0; j < r; ++j) bpts[to_size(j)] = next_bpts[to_size(j)];
            for (int j = r; j <= p; ++j) bpts[to_size(j)] = Pw[to_size(b - p + j)];
            a = b;
            ++b;
            ua = ub;
        } else {
            for (int i = 0; i <= ph; ++i) Uh.push_back(ub);
        }
    }
    if (!curve.is_rational())
        for (Vec4& q : Qw) q.w = 1.0;
    return NurbsCurve::from_homogeneous(ph, std::move(Uh), std::move(Qw), curve.is_rational());
}

std::vector<NurbsCurve> make_compatible(const std::vector<NurbsCurve>& curves, const std::string& argument) {
    require(!curves.empty(), argument, "must contain at least one curve");
    int degree = 0;
    for (const NurbsCurve& c : curves) degree = std::max(degree, c.degree());

    // Same degree and domain [0, 1], clamped (so that the ends are control points).
    std::vector<NurbsCurve> result;
    result.reserve(curves.size());
    for (const NurbsCurve& c : curves)
        result.push_back(elevate_degree(detail::clamped_ends(c), degree - c.degree()).reparameterized(0.0, 1.0));

    // The union of the knot vectors, each knot with its largest multiplicity; near-equal knots merged.
    struct Knot {
        double value;
        int multiplicity;
    };
    std::vector<Knot> merged;  // interior knots only, ascending
    auto interior_knots = [](const NurbsCurve& c) {
        std::vector<Knot> knots;
        for (const double u : c.knots()) {
            if (u <= 0.0 || u >= 1.0) continue;
            if (!knots.empty() && knots.back().value == u)
                ++knots.back().multiplicity;
            else
                knots.push_back({u, 1});
        }
        return knots;
    };
    for (NurbsCurve& c : result) {
        std::vector<Knot> own = interior_knots(c);
        bool moved = false;
        for (Knot& k : own) {
            const auto near = std::find_if(merged.begin(), merged.end(),
                                           [&](const Knot& m) { return std::abs(m.value - k.value) <= kKnotMergeDistance; });
            if (near == merged.end()) {
                merged.push_back(k);
                continue;
            }
            if (near->value != k.value) {
                k.value = near->value;
                moved = true;
            }
            near->multiplicity = std::max(near->multiplicity, k.multiplicity);
        }
        std::sort(merged.begin(), merged.end(), [](const Knot& x, const Knot& y) { return x.value < y.value; });
        if (moved) {
            // Rewrite the curve's knots onto the merged values (a shift below 1e-12 of the domain).
            std::vector<double> knots(to_size(degree + 1), 0.0);
            for (const Knot& k : own) knots.insert(knots.end(), to_size(k.multiplicity), k.value);
            knots.insert(knots.end(), to_size(degree + 1), 1.0);
            c = NurbsCurve::from_homogeneous(degree, std::move(knots), c.homogeneous_points(), c.is_rational());
        }
    }
    for (NurbsCurve& c : result) {
        const std::vector<Knot> own = interior_knots(c);
        for (const Knot& k : merged) {
            const auto it = std::find_if(own.begin(), own.end(), [&](const Knot& o) { return o.value == k.value; });
            const int have = it == own.end() ? 0 : it->multiplicity;
            if (k.multiplicity > have) c = c.insert_knot(k.value, k.multiplicity - have);
        }
    }
    return result;
}

}  // namespace ratbez

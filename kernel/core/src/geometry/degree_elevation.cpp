// Degree elevation of NURBS curves (A5.9, DegreeElevateCurve) and surfaces (A5.9 on every line of the net);
// see degree_elevation.hpp.
#include "ratbez/degree_elevation.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/clamping.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

using detail::binomial;
using detail::to_size;

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

namespace {

// The weight of a line of homogeneous points at its domain's start, sum_i N_i(a) w_i (A2.2).
double start_weight(int degree, const std::vector<double>& knots, const std::vector<Vec4>& line) {
    const double a = knot_domain(degree, knots).min;
    const int span = find_span(degree, knots, a);
    std::vector<double> basis(to_size(degree + 1));
    basis_functions(span, a, degree, knots, basis);
    double w = 0;
    for (int j = 0; j <= degree; ++j) w += basis[to_size(j)] * line[to_size(span - degree + j)].w;
    return w;
}

// Every line of the net along one direction elevated as a curve (A5.9 depends on the knots only, so all
// lines get the same new knots).
NurbsSurface elevate_net(const NurbsSurface& surface, int times, bool along_u) {
    require(times >= 0, along_u ? "times_u" : "times_v", [&] { return "must be >= 0, got " + std::to_string(times); });
    if (times == 0) return surface;
    const int rows = surface.rows(), columns = surface.columns();
    const int lines = along_u ? columns : rows, length = along_u ? rows : columns;
    const int degree = along_u ? surface.degree_u() : surface.degree_v();
    const std::vector<double>& knots = along_u ? surface.knots_u() : surface.knots_v();
    std::vector<std::vector<Vec4>> elevated(to_size(lines));
    std::vector<double> new_knots;
    for (int l = 0; l < lines; ++l) {
        std::vector<Vec4> line(to_size(length));
        for (int k = 0; k < length; ++k)
            line[to_size(k)] = along_u ? surface.homogeneous_point(k, l) : surface.homogeneous_point(l, k);
        const double weight = start_weight(degree, knots, line);
        const NurbsCurve curve = elevate_degree(NurbsCurve::from_homogeneous(degree, knots, std::move(line), true), times);
        // NurbsCurve keeps its weights scaled by a power of two of its own (nurbs_curve.hpp); the lines of
        // one net must share the net's scale, so each is scaled back by the power of two that maps its
        // homogeneous start point (unchanged by A5.9 up to that scale) onto the one it had.
        const double factor = std::exp2(std::round(std::log2(weight / curve.homogeneous_point(curve.domain().min).w)));
        std::vector<Vec4> pw = curve.homogeneous_points();
        for (Vec4& q : pw) q *= factor;
        elevated[to_size(l)] = std::move(pw);
        if (l == 0) new_knots = curve.knots();
    }
    const std::size_t count = elevated.front().size(), stride = to_size(lines);
    std::vector<Vec4> net(stride * count);
    for (std::size_t l = 0; l < stride; ++l)
        for (std::size_t k = 0; k < count; ++k) (along_u ? net[k * stride + l] : net[l * count + k]) = elevated[l][k];
    if (!surface.is_rational())
        for (Vec4& q : net) q.w = 1.0;
    return along_u ? NurbsSurface::from_homogeneous(degree + times, surface.degree_v(), std::move(new_knots),
                                                    surface.knots_v(), std::move(net), surface.is_rational())
                   : NurbsSurface::from_homogeneous(surface.degree_u(), degree + times, surface.knots_u(),
                                                    std::move(new_knots), std::move(net), surface.is_rational());
}

}  // namespace

NurbsSurface elevate_degree_u(const NurbsSurface& surface, int times) { return elevate_net(surface, times, true); }
NurbsSurface elevate_degree_v(const NurbsSurface& surface, int times) { return elevate_net(surface, times, false); }

}  // namespace ratbez

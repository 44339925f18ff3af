#include "geometry/surface_evaluator.hpp"

#include <algorithm>
#include <array>

#include "ratbez/error.hpp"

namespace ratbez::detail {
namespace {

constexpr int kMaxDegree = kMaxEvaluatorDegree;

// B_{i,n}(s) and its derivatives up to Order (at most two) for i = 0..n, by the triangular scheme (A1.3)
// built in place in b, keeping the rows of degree n-2 and n-1 that the derivative formulas need. Point
// evaluation (Order 0) is the hot path of tessellation and deviation checks: it neither keeps the lower
// rows nor forms derivatives, and nothing is initialised beyond the entries the scheme writes.
template <int Order>
void bernstein_with_derivatives(int n, double s, double* b, double* db, double* ddb) {
    std::array<double, kMaxDegree + 1> lower1, lower2;  // rows n-1 (n entries) and n-2 (n-1 entries)
    b[0] = 1;
    const double t = 1 - s;
    for (int degree = 1; degree <= n; ++degree) {
        // b holds degree - 1 here: keep the two rows the derivative formulas need.
        if constexpr (Order >= 2) if (degree - 1 == n - 2) std::copy_n(b, degree, lower2.data());
        if constexpr (Order >= 1) if (degree - 1 == n - 1) std::copy_n(b, degree, lower1.data());
        double saved = 0;
        for (int k = 0; k < degree; ++k) {
            const double temp = b[k];
            b[k] = saved + t * temp;
            saved = s * temp;
        }
        b[degree] = saved;
    }
    auto at = [](const std::array<double, kMaxDegree + 1>& a, int i, int size) { return i < 0 || i >= size ? 0.0 : a[static_cast<std::size_t>(i)]; };
    for (int i = 0; i <= n; ++i) {
        if constexpr (Order >= 1) db[i] = n >= 1 ? n * (at(lower1, i - 1, n) - at(lower1, i, n)) : 0.0;
        if constexpr (Order >= 2)
            ddb[i] = n >= 2 ? n * (n - 1) * (at(lower2, i - 2, n - 1) - 2 * at(lower2, i - 1, n - 1) + at(lower2, i, n - 1)) : 0.0;
    }
}

std::vector<double> distinct_knots(const std::vector<double>& knots, Interval domain) {
    std::vector<double> b;
    for (double k : knots)
        if (k >= domain.min && k <= domain.max && (b.empty() || k > b.back())) b.push_back(k);
    return b;
}

}  // namespace

SurfaceEvaluator::SurfaceEvaluator(const NurbsSurface& surface)
    : degree_u_(surface.degree_u()), degree_v_(surface.degree_v()) {
    require(degree_u_ <= kMaxDegree && degree_v_ <= kMaxDegree, "surface", "degree above 25 is not supported (OpenCASCADE's limit too)");
    breaks_u_ = distinct_knots(surface.knots_u(), surface.domain_u());
    breaks_v_ = distinct_knots(surface.knots_v(), surface.domain_v());
    const auto patches = surface.bezier_patches();
    require(patches.size() + 1 == breaks_u_.size() && !patches.empty() && patches[0].size() + 1 == breaks_v_.size(), "surface",
            "Bézier patches do not match the knot spans");
    for (const auto& row : patches)
        for (const BezierSurface& patch : row) patches_.insert(patches_.end(), patch.homogeneous_points().begin(), patch.homogeneous_points().end());
}

SurfaceEvaluator::Located SurfaceEvaluator::locate(double u, double v) const {
    auto span = [](const std::vector<double>& breaks, double x) {
        const auto it = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, x);
        return static_cast<std::size_t>(it - breaks.begin()) - 1;
    };
    const std::size_t a = span(breaks_u_, u), b = span(breaks_v_, v);
    const double hu = breaks_u_[a + 1] - breaks_u_[a], hv = breaks_v_[b + 1] - breaks_v_[b];
    const std::size_t patch_size = static_cast<std::size_t>((degree_u_ + 1) * (degree_v_ + 1));
    return {&patches_[(a * (breaks_v_.size() - 1) + b) * patch_size], std::clamp((u - breaks_u_[a]) / hu, 0.0, 1.0),
            std::clamp((v - breaks_v_[b]) / hv, 0.0, 1.0), 1 / hu, 1 / hv};
}

namespace {

// The homogeneous sum S^w of one patch and its partials up to Order in local parameters.
struct HomogeneousJet {
    Vec4 h, hu, hv, huu, huv, hvv;
};

// S^w = sum B_i(s) B_j(t) P^w_ij: the net is contracted in t row by row, then in s. P and Q >= 0 fix the
// degrees at compile time (see homogeneous_jet_of_degree); -1 takes them from the arguments.
template <int Order, int P = -1, int Q = -1>
HomogeneousJet homogeneous_jet(const Vec4* net, int runtime_degree_u, int runtime_degree_v, double s, double t) {
    const int degree_u = P >= 0 ? P : runtime_degree_u, degree_v = Q >= 0 ? Q : runtime_degree_v;
    // Written by bernstein_with_derivatives up to the degree and Order used; not initialised (the point
    // evaluation would otherwise clear six arrays of 26 per call).
    std::array<double, kMaxDegree + 1> bu, dbu, ddbu, bv, dbv, ddbv;
    bernstein_with_derivatives<Order>(degree_u, s, bu.data(), dbu.data(), ddbu.data());
    bernstein_with_derivatives<Order>(degree_v, t, bv.data(), dbv.data(), ddbv.data());
    HomogeneousJet jet;
    for (int i = 0; i <= degree_u; ++i) {
        Vec4 r0, r1, r2;  // the row summed against B(t), B'(t), B''(t)
        for (int j = 0; j <= degree_v; ++j) {
            const Vec4& p = net[i * (degree_v + 1) + j];
            const auto k = static_cast<std::size_t>(j);
            r0 += p * bv[k];
            if constexpr (Order >= 1) r1 += p * dbv[k];
            if constexpr (Order >= 2) r2 += p * ddbv[k];
        }
        const auto k = static_cast<std::size_t>(i);
        jet.h += r0 * bu[k];
        if constexpr (Order >= 1) {
            jet.hu += r0 * dbu[k];
            jet.hv += r1 * bu[k];
        }
        if constexpr (Order >= 2) {
            jet.huu += r0 * ddbu[k];
            jet.huv += r1 * dbu[k];
            jet.hvv += r2 * bu[k];
        }
    }
    return jet;
}

// homogeneous_jet with the degrees as template arguments when both are 1 to 3 (lines, conics and cubics:
// most surfaces the kernel builds), so that the Bernstein triangles and the contraction unroll; the same
// arithmetic in the same order, so the same result bit for bit. Tessellation checks and deviation
// measurement evaluate points by the million.
template <int Order>
HomogeneousJet homogeneous_jet_of_degree(const Vec4* net, int degree_u, int degree_v, double s, double t) {
    if (degree_u >= 1 && degree_u <= 3 && degree_v >= 1 && degree_v <= 3) {
        switch (degree_u * 4 + degree_v) {
            case 1 * 4 + 1: return homogeneous_jet<Order, 1, 1>(net, degree_u, degree_v, s, t);
            case 1 * 4 + 2: return homogeneous_jet<Order, 1, 2>(net, degree_u, degree_v, s, t);
            case 1 * 4 + 3: return homogeneous_jet<Order, 1, 3>(net, degree_u, degree_v, s, t);
            case 2 * 4 + 1: return homogeneous_jet<Order, 2, 1>(net, degree_u, degree_v, s, t);
            case 2 * 4 + 2: return homogeneous_jet<Order, 2, 2>(net, degree_u, degree_v, s, t);
            case 2 * 4 + 3: return homogeneous_jet<Order, 2, 3>(net, degree_u, degree_v, s, t);
            case 3 * 4 + 1: return homogeneous_jet<Order, 3, 1>(net, degree_u, degree_v, s, t);
            case 3 * 4 + 2: return homogeneous_jet<Order, 3, 2>(net, degree_u, degree_v, s, t);
            case 3 * 4 + 3: return homogeneous_jet<Order, 3, 3>(net, degree_u, degree_v, s, t);
            default: break;
        }
    }
    return homogeneous_jet<Order>(net, degree_u, degree_v, s, t);
}

}  // namespace

SurfaceFirstDerivatives bezier_patch_first_derivatives(const Vec4* net, int degree_u, int degree_v, double s, double t) {
    const HomogeneousJet h = homogeneous_jet<1>(net, degree_u, degree_v, s, t);
    return project_first_derivatives(h.h, h.hu, h.hv);
}

Vec3 SurfaceEvaluator::point(double u, double v) const {
    const Located l = locate(u, v);
    return project(homogeneous_jet_of_degree<0>(l.net, degree_u_, degree_v_, l.s, l.t).h);
}

SurfaceFirstDerivatives SurfaceEvaluator::first_derivatives(double u, double v) const {
    const Located l = locate(u, v);
    const HomogeneousJet h = homogeneous_jet_of_degree<1>(l.net, degree_u_, degree_v_, l.s, l.t);
    // The quotient rule in the patch's parameters, then the chain rule to the surface's own.
    SurfaceFirstDerivatives d = project_first_derivatives(h.h, h.hu, h.hv);
    d.su *= l.scale_u;
    d.sv *= l.scale_v;
    return d;
}

SurfaceJet SurfaceEvaluator::jet(double u, double v) const {
    const Located l = locate(u, v);
    const HomogeneousJet h = homogeneous_jet<2>(l.net, degree_u_, degree_v_, l.s, l.t);
    // Quotient rule: S = A / w and its partials (Leibniz on A = w S).
    const double w = h.h.w;
    SurfaceJet j;
    j.s = weighted_part(h.h) / w;
    j.su = (weighted_part(h.hu) - j.s * h.hu.w) / w;
    j.sv = (weighted_part(h.hv) - j.s * h.hv.w) / w;
    j.suu = (weighted_part(h.huu) - j.su * (2 * h.hu.w) - j.s * h.huu.w) / w;
    j.suv = (weighted_part(h.huv) - j.su * h.hv.w - j.sv * h.hu.w - j.s * h.huv.w) / w;
    j.svv = (weighted_part(h.hvv) - j.sv * (2 * h.hv.w) - j.s * h.hvv.w) / w;
    // Chain rule to the surface's own parameters.
    j.su *= l.scale_u;
    j.sv *= l.scale_v;
    j.suu *= l.scale_u * l.scale_u;
    j.suv *= l.scale_u * l.scale_v;
    j.svv *= l.scale_v * l.scale_v;
    return j;
}

}  // namespace ratbez::detail

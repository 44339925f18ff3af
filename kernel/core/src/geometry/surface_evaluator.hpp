#pragma once
// A fast evaluator for a NURBS surface, for the inner loops of tessellation and deviation measurement
// (millions of evaluations): the surface is split once into its rational Bézier patches (A5.7, via
// NurbsSurface::bezier_patches), and each evaluation finds the patch by binary search, evaluates the
// Bernstein basis and its derivatives directly (000 §1.3; derivative of B_{i,n} = n (B_{i-1,n-1} -
// B_{i,n-1})) and applies the rational quotient rule to the homogeneous sums (Eq. 1.28 generalised).
// No allocation per call. Same geometry as NurbsSurface::point / derivatives.

#include <vector>

#include "ratbez/limits.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// S and its first partial derivatives at one (u, v).
struct SurfaceFirstDerivatives {
    Vec3 s, su, sv;
};

// S and its partial derivatives up to order two at one (u, v).
struct SurfaceJet {
    Vec3 s, su, sv, suu, suv, svv;
};

// S, S_u, S_v from the homogeneous point S^w = (A, w) and its partials: S = A / w and the quotient rule
// S_u = (A_u - w_u S) / w (Eq. 1.28 differentiated), likewise in v.
inline SurfaceFirstDerivatives project_first_derivatives(const Vec4& h, const Vec4& hu, const Vec4& hv) {
    SurfaceFirstDerivatives d;
    d.s = project(h);
    d.su = (weighted_part(hu) - d.s * hu.w) / h.w;
    d.sv = (weighted_part(hv) - d.s * hv.w) / h.w;
    return d;
}

// The library's degree limit (limits.hpp, OpenCASCADE's Geom_BSplineSurface::MaxDegree()): no surface has more.
inline constexpr int kMaxEvaluatorDegree = limits::max_degree;

// S, S_s, S_t of ONE rational Bézier patch at local (s, t) in [0, 1]^2: `net` holds its
// (degree_u + 1) x (degree_v + 1) homogeneous points row-major (i along s). The partials are in the
// patch's own parameters (no chain rule); degree_v = 0 makes it a curve in s (S_t = 0). Used by the
// adaptive quadrature of properties.cpp on deCasteljau sub-patches.
SurfaceFirstDerivatives bezier_patch_first_derivatives(const Vec4* net, int degree_u, int degree_v, double s, double t);

class SurfaceEvaluator {
public:
    explicit SurfaceEvaluator(const NurbsSurface& surface);

    Interval domain_u() const { return {breaks_u_.front(), breaks_u_.back()}; }
    Interval domain_v() const { return {breaks_v_.front(), breaks_v_.back()}; }
    // (u, v) must lie in the domain (callers clamp); no validation in the hot path.
    Vec3 point(double u, double v) const;
    SurfaceFirstDerivatives first_derivatives(double u, double v) const;
    SurfaceJet jet(double u, double v) const;

private:
    struct Located {
        const Vec4* net;  // the patch's (p+1) x (q+1) homogeneous points, row-major
        double s, t;      // local parameters in [0, 1]
        double scale_u, scale_v;  // d(s)/du, d(t)/dv
    };
    Located locate(double u, double v) const;
    int degree_u_ = 0, degree_v_ = 0;
    std::vector<double> breaks_u_, breaks_v_;
    std::vector<Vec4> patches_;  // patch (a, b) at ((a * spans_v + b) * (p+1) * (q+1))
};

}  // namespace ratbez::detail

// Area and volume by Gauss–Legendre quadrature on every knot span of every face.
//
// Surface faces: area = ∫∫ |S_u x S_v| du dv, volume contribution = (1/3) ∫∫ (S - c) · (S_u x S_v) du dv
// (divergence theorem with div(x - c) = 3; any reference point c gives the same total over a closed
// shell, and the centre of the control box keeps the integrand small and well conditioned).
// Planar faces: area by Green's theorem on their loops in the plane frame, A = (1/2) ∮ (x dy - y dx);
// on a plane (S - c) · n is the constant (origin - c) · n, so the volume contribution is
// (1/3) ((origin - c) · n) A.
//
// Each span is integrated with an adaptive 12 x 12 point rule: a panel is accepted when the rule on it
// and on its four quarters agree to 1e-14 of the solid's size (squared or cubed). The integrands are
// rational functions without poles near the real spans (weights are positive), so Gauss–Legendre
// converges geometrically and the acceptance test is reliable.
#include "ratbez/properties.hpp"

#include <cmath>

#include "ratbez/bezier_surface.hpp"

#include "geometry_internal.hpp"

namespace ratbez {

namespace {

constexpr double kRelativeQuadratureTolerance = 1e-14;

// S, S_u and S_v on one Bézier patch of a face (A5.7 extraction), from its homogeneous net: the
// Bernstein values of degree n - 1 by the triangular scheme (A1.3), one more step for degree n, their
// derivatives n (B_{i-1,n-1} - B_{i,n-1}) (003), the homogeneous sums A, A_u, A_v, w, w_u, w_v and the
// quotient rule S_u = (A_u - w_u S) / w. The quadrature evaluates thousands of points per span, so this
// avoids the general k-th-order machinery and every allocation per point.
struct FirstDerivatives {
    Vec3 point, du, dv;
};

class PatchEvaluator {
public:
    PatchEvaluator(const BezierSurface& patch, double u0, double u1, double v0, double v1)
        : patch_(patch), u0_(u0), v0_(v0), inverse_du_(1.0 / (u1 - u0)), inverse_dv_(1.0 / (v1 - v0)),
          bu_(static_cast<std::size_t>(patch.degree_u() + 1)), dbu_(bu_.size()),
          bv_(static_cast<std::size_t>(patch.degree_v() + 1)), dbv_(bv_.size()) {}

    FirstDerivatives operator()(double u, double v) const {
        bernstein_with_derivatives((u - u0_) * inverse_du_, bu_, dbu_);
        bernstein_with_derivatives((v - v0_) * inverse_dv_, bv_, dbv_);
        Vec4 a{}, a_u{}, a_v{};
        for (std::size_t i = 0; i < bu_.size(); ++i) {
            Vec4 row{}, row_v{};
            for (std::size_t j = 0; j < bv_.size(); ++j) {
                const Vec4& pw = patch_.homogeneous_point(static_cast<int>(i), static_cast<int>(j));
                row += pw * bv_[j];
                row_v += pw * dbv_[j];
            }
            a += row * bu_[i];
            a_u += row * dbu_[i];
            a_v += row_v * bu_[i];
        }
        a_u *= inverse_du_;
        a_v *= inverse_dv_;
        const Vec3 point = project(a);
        return {point, (weighted_part(a_u) - point * a_u.w) / a.w, (weighted_part(a_v) - point * a_v.w) / a.w};
    }

private:
    static void bernstein_with_derivatives(double t, std::vector<double>& b, std::vector<double>& db) {
        const std::size_t n = b.size() - 1;
        // Degree n - 1 first (A1.3), kept in b[0..n-1].
        b[0] = 1.0;
        for (std::size_t k = 1; k < n; ++k) {
            double saved = 0.0;
            for (std::size_t i = 0; i < k; ++i) {
                const double temp = b[i];
                b[i] = saved + (1.0 - t) * temp;
                saved = t * temp;
            }
            b[k] = saved;
        }
        const double degree = static_cast<double>(n);
        for (std::size_t i = 0; i <= n; ++i) {
            const double left = i > 0 ? b[i - 1] : 0.0, right = i < n ? b[i] : 0.0;
            db[i] = degree * (left - right);
        }
        // One more step to degree n.
        double saved = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double temp = b[i];
            b[i] = saved + (1.0 - t) * temp;
            saved = t * temp;
        }
        b[n] = saved;
        if (n == 0) { b[0] = 1.0; db[0] = 0.0; }
    }

    const BezierSurface& patch_;
    double u0_, v0_, inverse_du_, inverse_dv_;
    mutable std::vector<double> bu_, dbu_, bv_, dbv_;
};

struct SpanGrid {
    std::vector<double> u, v;
};

SpanGrid spans(const NurbsSurface& s) {
    return {detail::breakpoints(s.degree_u(), s.knots_u()), detail::breakpoints(s.degree_v(), s.knots_v())};
}

// The integral of integrand(S, S_u, S_v) over the face's parameter rectangle, span by span.
double integrate_over_spans(const NurbsSurface& surface, const std::function<double(const FirstDerivatives&)>& integrand,
                            double absolute_tolerance, int points, int max_depth) {
    const SpanGrid grid = spans(surface);
    const auto patches = surface.bezier_patches();
    const std::size_t span_count = (grid.u.size() - 1) * (grid.v.size() - 1);
    double total = 0;
    for (std::size_t a = 0; a + 1 < grid.u.size(); ++a)
        for (std::size_t b = 0; b + 1 < grid.v.size(); ++b) {
            const PatchEvaluator evaluate(patches[a][b], grid.u[a], grid.u[a + 1], grid.v[b], grid.v[b + 1]);
            total += detail::integrate([&](double u, double v) { return integrand(evaluate(u, v)); }, grid.u[a],
                                       grid.u[a + 1], grid.v[b], grid.v[b + 1],
                                       absolute_tolerance / static_cast<double>(span_count), points, max_depth);
        }
    return total;
}

double face_size(const Face& face) {
    if (face.kind() == Face::Kind::surface) return detail::control_box(face.surface()).diagonal();
    detail::Box box;
    for (const auto& loop : face.loops())
        for (const Coedge& c : loop) box.add(detail::control_box(c.edge->curve));
    return box.diagonal();
}

double planar_area(const Face& face, double absolute_tolerance, int points, int max_depth) {
    const Plane& plane = face.plane();
    double area = 0;
    for (const auto& loop : face.loops())
        for (const Coedge& c : loop) {
            const double a = detail::green_area(c.edge->curve, plane.origin, plane.x_axis, plane.y_axis,
                                                absolute_tolerance, points, max_depth);
            area += c.reversed ? -a : a;
        }
    return area;
}

double face_area(const Face& face, double absolute_tolerance, int points, int max_depth) {
    if (face.kind() == Face::Kind::planar) return planar_area(face, absolute_tolerance, points + 4, max_depth + 6);
    const NurbsSurface& s = face.surface();
    return integrate_over_spans(
        s,
        [](const FirstDerivatives& d) { return norm(cross(d.du, d.dv)); },
        absolute_tolerance, points, max_depth);
}

double volume_of_faces(const std::vector<Face>& faces, int points, int max_depth, double relative_tolerance) {
    detail::Box box;
    for (const Face& face : faces) box.add(detail::control_box(face.surface()));
    const Vec3 c = (box.min + box.max) * 0.5;
    const double size = box.diagonal();
    const double volume_tolerance = relative_tolerance * size * size * size / static_cast<double>(faces.size());
    const double area_tolerance = relative_tolerance * size * size / static_cast<double>(faces.size());
    double volume = 0;
    for (const Face& face : faces) {
        if (face.kind() == Face::Kind::planar) {
            const Plane& plane = face.plane();
            volume += dot(plane.origin - c, plane.normal) * face_area(face, area_tolerance, points, max_depth) / 3.0;
        } else {
            const NurbsSurface& s = face.surface();
            volume += integrate_over_spans(
                          s,
                          [&c](const FirstDerivatives& d) { return dot(d.point - c, cross(d.du, d.dv)); },
                          volume_tolerance, points, max_depth) /
                      3.0;
        }
    }
    return volume;
}

}  // namespace

double detail::signed_volume(const std::vector<Face>& faces, bool quick) {
    return quick ? volume_of_faces(faces, 6, 0, 1e-6) : volume_of_faces(faces, 12, 6, kRelativeQuadratureTolerance);
}

double surface_area(const Face& face) {
    const double size = face_size(face);
    return face_area(face, kRelativeQuadratureTolerance * size * size, 12, 6);
}

double surface_area(const Solid& solid) {
    const double size = solid.bounding_box().diagonal();
    const double tolerance = kRelativeQuadratureTolerance * size * size / static_cast<double>(solid.faces().size());
    double area = 0;
    for (const Face& face : solid.faces()) area += face_area(face, tolerance, 12, 6);
    return area;
}

double enclosed_volume(const Solid& solid) { return detail::signed_volume(solid.faces(), false); }

}  // namespace ratbez

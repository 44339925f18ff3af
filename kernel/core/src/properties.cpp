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


#include "geometry_internal.hpp"
#include "ratbez/error.hpp"
#include "surface_evaluator.hpp"

namespace ratbez {

namespace {

constexpr double kRelativeQuadratureTolerance = 1e-14;

struct SpanGrid {
    std::vector<double> u, v;
};

SpanGrid spans(const NurbsSurface& s) {
    return {detail::breakpoints(s.degree_u(), s.knots_u()), detail::breakpoints(s.degree_v(), s.knots_v())};
}

// The integral of integrand(S, S_u, S_v) over the face's parameter rectangle, span by span.
// The quadrature evaluates thousands of points per span: detail::SurfaceEvaluator works on the Bézier
// patches (A5.7) directly, without the general k-th-order machinery or any allocation per point.
double integrate_over_spans(const NurbsSurface& surface,
                            const std::function<double(const detail::SurfaceFirstDerivatives&)>& integrand,
                            double absolute_tolerance, int points, int max_depth) {
    const SpanGrid grid = spans(surface);
    const detail::SurfaceEvaluator evaluator(surface);
    const std::size_t span_count = (grid.u.size() - 1) * (grid.v.size() - 1);
    double total = 0;
    for (std::size_t a = 0; a + 1 < grid.u.size(); ++a)
        for (std::size_t b = 0; b + 1 < grid.v.size(); ++b) {
            total += detail::integrate([&](double u, double v) { return integrand(evaluator.first_derivatives(u, v)); }, grid.u[a],
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
        [](const detail::SurfaceFirstDerivatives& d) { return norm(cross(d.su, d.sv)); },
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
                          [&c](const detail::SurfaceFirstDerivatives& d) { return dot(d.s - c, cross(d.su, d.sv)); },
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
    require(std::isfinite(area), "solid", "its area is not a finite double (the solid is too large to measure)");
    return area;
}

double enclosed_volume(const Solid& solid) {
    const double volume = detail::signed_volume(solid.faces(), false);
    // A solid of size 1e150 has a volume past the double range: say so rather than return inf.
    require(std::isfinite(volume), "solid", "its volume is not a finite double (the solid is too large to measure)");
    return volume;
}

}  // namespace ratbez

#pragma once
// Affine maps x -> L x + t of curves and surfaces, exact for rational geometry. Rational Bézier and NURBS
// curves and surfaces are affinely invariant (000 §1.4, P1.14 / Exercise 1.4): the rational basis
// functions R_i(u) = w_i B_i(u) / sum_j w_j B_j(u) sum to 1, so A(sum R_i P_i) = sum R_i A(P_i). The image
// is the curve with control points A(P_i), the same weights and the same knots; on homogeneous points
// P^w = (w P, w) that is (L (w P) + w t, w). Nothing is approximated: the only error is the rounding of
// the map's own arithmetic. (A projective map would change the weights; those are refused.)

#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

class AffineMap {
public:
    // The identity.
    AffineMap() = default;
    // x -> x + offset.
    static AffineMap translation(const Vec3& offset);
    // The right-handed rotation by angle_deg about the line through axis_point along axis_dir (normalised;
    // a zero axis throws Error naming "axis_dir"). Multiples of 90 degrees have exact cosines and sines.
    static AffineMap rotation(const Vec3& axis_point, const Vec3& axis_dir, double angle_deg);
    // x -> center + factor (x - center); factor finite and not 0 (negative: a point reflection).
    static AffineMap scaling(double factor, const Vec3& center);
    // The reflection in the plane through plane_point with normal plane_normal (normalised).
    static AffineMap mirror(const Vec3& plane_point, const Vec3& plane_normal);
    // From a row-major 3 x 4 matrix [L | t] (12 entries) or 4 x 4 (16 entries) whose last row is
    // (0, 0, 0, 1) to 1e-12. Throws Error naming `argument` for non-finite entries, a projective last
    // row, or a singular L (|det L| at most 1e-12 of the product of its row lengths).
    static AffineMap from_matrix(std::span<const double> entries, std::size_t rows, const char* argument = "matrix");

    Vec3 operator()(const Vec3& point) const { return apply_linear(point) + offset_; }
    Vec3 apply_linear(const Vec3& vector) const;
    // The rows of L, and t.
    const std::array<Vec3, 3>& linear() const { return rows_; }
    const Vec3& offset() const { return offset_; }
    double determinant() const;
    // A reflecting map (det L < 0) turns right-handed frames left-handed: outward normals computed as
    // S_u x S_v would point inward, so faces and solids are reoriented (solid_transform.hpp).
    bool reflects() const { return determinant() < 0; }
    // L^-T n: the normal of the image of a plane with normal n (unnormalised).
    Vec3 normal_image(const Vec3& normal) const;
    // s when L^T L = s^2 I to 1e-12 relative (rigid motions, mirrors and uniform scalings: the maps that
    // keep circles circles), else nullopt.
    std::optional<double> similarity_scale() const;
    // this after `first`: x -> this(first(x)).
    AffineMap after(const AffineMap& first) const;

    // P^w = (w P, w) -> (L (w P) + w t, w).
    Vec4 homogeneous(const Vec4& point) const;

private:
    std::array<Vec3, 3> rows_{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    Vec3 offset_{};
};

// The images under `map`: same degrees, knots and weights, control points mapped.
BezierCurve transformed(const BezierCurve& curve, const AffineMap& map);
NurbsCurve transformed(const NurbsCurve& curve, const AffineMap& map);
BezierSurface transformed(const BezierSurface& surface, const AffineMap& map);
NurbsSurface transformed(const NurbsSurface& surface, const AffineMap& map);

}  // namespace ratbez

// Affine maps of curves and surfaces (affine_map.hpp).

#include "ratbez/affine_map.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "math/degrees.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {
namespace {

void require_point(const Vec3& p, const char* argument) {
    require(is_finite(p), argument, "must have finite coordinates");
}

std::vector<Vec4> mapped(const std::vector<Vec4>& points, const AffineMap& map) {
    std::vector<Vec4> result;
    result.reserve(points.size());
    for (const Vec4& p : points) result.push_back(map.homogeneous(p));
    return result;
}

}  // namespace

AffineMap AffineMap::translation(const Vec3& offset) {
    require_point(offset, "v");
    AffineMap map;
    map.offset_ = offset;
    return map;
}

AffineMap AffineMap::rotation(const Vec3& axis_point, const Vec3& axis_dir, double angle_deg) {
    require_point(axis_point, "axis_point");
    require_finite(angle_deg, "angle_deg");
    const Vec3 k = frame_from_axis({}, axis_dir, "axis_dir").z_axis;
    // Rodrigues: R = cos I + sin [k]x + (1 - cos) k k^T.
    const double c = detail::cos_deg(angle_deg), s = detail::sin_deg(angle_deg), t = 1 - c;
    AffineMap map;
    map.rows_ = {Vec3{c + t * k.x * k.x, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
                 Vec3{t * k.y * k.x + s * k.z, c + t * k.y * k.y, t * k.y * k.z - s * k.x},
                 Vec3{t * k.z * k.x - s * k.y, t * k.z * k.y + s * k.x, c + t * k.z * k.z}};
    // x -> p + R (x - p): the axis point stays where it is.
    map.offset_ = axis_point - map.apply_linear(axis_point);
    return map;
}

AffineMap AffineMap::scaling(double factor, const Vec3& center) {
    require(std::isfinite(factor) && factor != 0, "factor", "must be a finite number other than 0");
    require_point(center, "center");
    AffineMap map;
    map.rows_ = {Vec3{factor, 0, 0}, Vec3{0, factor, 0}, Vec3{0, 0, factor}};
    map.offset_ = center * (1 - factor);
    return map;
}

AffineMap AffineMap::mirror(const Vec3& plane_point, const Vec3& plane_normal) {
    require_point(plane_point, "plane_point");
    const Vec3 n = frame_from_axis({}, plane_normal, "plane_normal").z_axis;
    // x -> x - 2 ((x - p) . n) n: L = I - 2 n n^T, t = 2 (p . n) n.
    AffineMap map;
    map.rows_ = {Vec3{1 - 2 * n.x * n.x, -2 * n.x * n.y, -2 * n.x * n.z},
                 Vec3{-2 * n.y * n.x, 1 - 2 * n.y * n.y, -2 * n.y * n.z},
                 Vec3{-2 * n.z * n.x, -2 * n.z * n.y, 1 - 2 * n.z * n.z}};
    map.offset_ = n * (2 * dot(plane_point, n));
    return map;
}

AffineMap AffineMap::from_matrix(std::span<const double> entries, std::size_t rows, const char* argument) {
    require(rows == 3 || rows == 4, argument, "must have 3 or 4 rows of 4 numbers");
    require(entries.size() == 4 * rows, argument, "must have rows of 4 numbers");
    require_finite(entries, argument);
    if (rows == 4) {
        constexpr double tolerance = 1e-12;
        require(std::abs(entries[12]) <= tolerance && std::abs(entries[13]) <= tolerance &&
                    std::abs(entries[14]) <= tolerance && std::abs(entries[15] - 1) <= tolerance,
                argument, [&] {
                    return "the last row must be (0, 0, 0, 1) for an affine map; (" + exact_number(entries[12]) +
                           ", " + exact_number(entries[13]) + ", " + exact_number(entries[14]) + ", " +
                           exact_number(entries[15]) + ") is projective, which would change the weights";
                });
    }
    AffineMap map;
    for (std::size_t r = 0; r < 3; ++r) map.rows_[r] = {entries[4 * r], entries[4 * r + 1], entries[4 * r + 2]};
    map.offset_ = {entries[3], entries[7], entries[11]};
    const double lengths = norm(map.rows_[0]) * norm(map.rows_[1]) * norm(map.rows_[2]);
    require(std::isfinite(lengths) && std::abs(map.determinant()) > 1e-12 * lengths, argument,
            "the linear part is singular: the map would flatten the geometry");
    return map;
}

Vec3 AffineMap::apply_linear(const Vec3& v) const { return {dot(rows_[0], v), dot(rows_[1], v), dot(rows_[2], v)}; }

double AffineMap::determinant() const { return dot(rows_[0], cross(rows_[1], rows_[2])); }

Vec3 AffineMap::normal_image(const Vec3& normal) const {
    // L^-1 has the columns r1 x r2, r2 x r0, r0 x r1 (over det L), r_i the rows of L; so those cross
    // products are the rows of L^-T.
    const Vec3 c0 = cross(rows_[1], rows_[2]), c1 = cross(rows_[2], rows_[0]), c2 = cross(rows_[0], rows_[1]);
    return Vec3{dot(c0, normal), dot(c1, normal), dot(c2, normal)} / determinant();
}

std::optional<double> AffineMap::similarity_scale() const {
    // Columns of L orthogonal with equal lengths <=> rows too (L L^T = s^2 I <=> L^T L = s^2 I).
    const double s2 = (dot(rows_[0], rows_[0]) + dot(rows_[1], rows_[1]) + dot(rows_[2], rows_[2])) / 3;
    constexpr double tolerance = 1e-12;
    for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = a; b < 3; ++b)
            if (std::abs(dot(rows_[a], rows_[b]) - (a == b ? s2 : 0.0)) > tolerance * s2) return std::nullopt;
    return std::sqrt(s2);
}

AffineMap AffineMap::after(const AffineMap& first) const {
    AffineMap map;
    // (this o first)(x) = L (L1 x + t1) + t: rows of L L1, offset L t1 + t.
    const auto& f = first.rows_;
    for (std::size_t r = 0; r < 3; ++r) {
        const Vec3& row = rows_[r];
        map.rows_[r] = {row.x * f[0].x + row.y * f[1].x + row.z * f[2].x, row.x * f[0].y + row.y * f[1].y + row.z * f[2].y,
                        row.x * f[0].z + row.y * f[1].z + row.z * f[2].z};
    }
    map.offset_ = (*this)(first.offset_);
    return map;
}

Vec4 AffineMap::homogeneous(const Vec4& point) const {
    const Vec3 image = apply_linear(weighted_part(point)) + offset_ * point.w;
    return {image.x, image.y, image.z, point.w};
}

BezierCurve transformed(const BezierCurve& curve, const AffineMap& map) {
    return BezierCurve::from_homogeneous(mapped(curve.homogeneous_points(), map), curve.is_rational());
}

NurbsCurve transformed(const NurbsCurve& curve, const AffineMap& map) {
    return NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), mapped(curve.homogeneous_points(), map),
                                        curve.is_rational());
}

BezierSurface transformed(const BezierSurface& surface, const AffineMap& map) {
    return BezierSurface::from_homogeneous(surface.degree_u() + 1, surface.degree_v() + 1,
                                           mapped(surface.homogeneous_points(), map), surface.is_rational());
}

NurbsSurface transformed(const NurbsSurface& surface, const AffineMap& map) {
    return NurbsSurface::from_homogeneous(surface.degree_u(), surface.degree_v(), surface.knots_u(), surface.knots_v(),
                                          mapped(surface.homogeneous_points(), map), surface.is_rational());
}

}  // namespace ratbez

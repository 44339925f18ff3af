#pragma once
// The input limits of the library, one set for every entry point (constructors, evaluators, solids, the
// command's spec, the Python module): whatever exceeds them is refused with a ratbez::Error naming the
// argument and the limit, before any work grows with it. The README lists them.

#include <cstddef>
#include <string>
#include <string_view>

#include "ratbez/error.hpp"

namespace ratbez::limits {

// The highest degree of every basis, curve, surface and solid: OpenCASCADE's Geom_BSplineCurve::MaxDegree(),
// so nothing ratbez accepts is refused when it is exported; a Bézier curve has at most 26 control points.
inline constexpr int max_degree = 25;
// Control points of one curve, and of all the pieces of one profile together.
inline constexpr std::size_t max_curve_points = 100'000;
// Control points of one surface (rows x columns): a profile at max_curve_points revolved has 9 rows.
inline constexpr std::size_t max_surface_points = 1'000'000;
// Sections of one loft (skin, loft_surface, loft): the solve across them is linear in their number (a banded
// system, geometry/interpolation.hpp), and so is everything after; 20,000 circles loft and measure in 19 s.
inline constexpr std::size_t max_loft_sections = 100'000;
// The highest derivative order asked of an evaluator (curves: C^(k); surfaces: k = du + dv).
inline constexpr int max_derivative_order = 100;

// The scale of a solid: every coordinate at most max_solid_coordinate in magnitude and its size (the
// diagonal of its box) at least min_solid_size, so that its area and volume are finite, non-zero doubles
// (a sphere of radius 1e308 or 1e-300 has neither); and its size at least min_relative_solid_size of its
// distance from the origin, where the spacing of doubles still resolves it (a unit sphere at 1e17 is a
// point: neighbouring doubles there are 16 apart).
inline constexpr double max_solid_coordinate = 1e100;
inline constexpr double min_solid_size = 1e-100;
inline constexpr double min_relative_solid_size = 1e-9;

// The smallest feature of a primitive or extrusion against its largest dimension: a cylinder's radius and
// height against each other, a cone's radii that are not 0 (an apex) and its height, a torus's tube and the
// hole it leaves at the axis, an extrusion's distance and its profile's size against each other. Below it a
// face's side would be shorter than the B-rep's consistency tolerance (1e-9 of a face's size) and taken
// for a collapsed point (cone(1, 1e-12, 1) was refused naming the internal `sides`; torus(1, 1 - 1e-11)
// built and then failed to mesh).
inline constexpr double min_relative_feature = 1e-8;

// Throws Error(argument) unless 0 <= degree <= max_degree.
inline void require_degree(int degree, std::string_view argument) {
    require(degree >= 0, argument, [&] { return "the degree must be >= 0, got " + std::to_string(degree); });
    require(degree <= max_degree, argument, [&] {
        return "degree " + std::to_string(degree) + " is above the limit " + std::to_string(max_degree) +
               " (OpenCASCADE's limit too)";
    });
}

// Throws Error(argument) unless a Bézier curve or surface direction of `count` control points has a degree
// (count - 1) within max_degree. The count is checked before anything is built from the points.
inline void require_bezier_count(std::size_t count, std::string_view argument, std::string_view what = "control points") {
    require(count <= static_cast<std::size_t>(max_degree) + 1, argument, [&] {
        return "has " + std::to_string(count) + " " + std::string(what) + " (degree " + std::to_string(count - 1) +
               "), above the degree limit " + std::to_string(max_degree) + ": at most " +
               std::to_string(max_degree + 1);
    });
}

// Throws Error(argument) when a curve (or profile) has more than max_curve_points control points.
inline void require_curve_points(std::size_t count, std::string_view argument) {
    require(count <= max_curve_points, argument, [&] {
        return "has " + std::to_string(count) + " control points, above the limit " + std::to_string(max_curve_points);
    });
}

// Throws Error(argument) when a rows x columns net has more than max_surface_points control points.
inline void require_surface_points(std::size_t rows, std::size_t columns, std::string_view argument) {
    require(columns == 0 || rows <= max_surface_points / columns, argument, [&] {
        return "has " + std::to_string(rows) + " x " + std::to_string(columns) + " control points, above the limit " +
               std::to_string(max_surface_points);
    });
}

// Throws Error(argument) when a loft has more than max_loft_sections sections.
inline void require_loft_sections(std::size_t count, std::string_view argument) {
    require(count <= max_loft_sections, argument, [&] {
        return "has " + std::to_string(count) + " sections, above the limit " + std::to_string(max_loft_sections) +
               " of one loft";
    });
}

// Throws Error(argument) unless 0 <= order <= max_derivative_order.
inline void require_derivative_order(int order, std::string_view argument) {
    require(order >= 0, argument, [&] { return "the derivative order must be >= 0, got " + std::to_string(order); });
    require(order <= max_derivative_order, argument, [&] {
        return "the derivative order " + std::to_string(order) + " is above the limit " +
               std::to_string(max_derivative_order);
    });
}

// The orders of a surface's partial d^(du+dv) S / du^du dv^dv: each and their sum as above, named "du", "dv"
// and "du + dv".
inline void require_partial_orders(int du, int dv) {
    require_derivative_order(du, "du");
    require_derivative_order(dv, "dv");
    require_derivative_order(du + dv, "du + dv");
}

}  // namespace ratbez::limits

// The scale rule of limits.hpp for solids (solid_scale.hpp).
#include "math/solid_scale.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez::detail {

void require_solid_scale(double size, double reach, std::string_view size_argument, std::string_view position_argument,
                         double largest_size) {
    using limits::max_solid_coordinate, limits::min_solid_size, limits::min_relative_solid_size;
    require(std::isfinite(size) && size <= largest_size, size_argument, [&] {
        return "gives a solid of size " + number(size) + ", above the limit " + number(largest_size) +
               " (its area and volume must be finite numbers)";
    });
    require(std::isfinite(reach) && reach <= max_solid_coordinate, position_argument, [&] {
        return "gives a solid with coordinates up to " + number(reach) + ", above the limit " +
               number(max_solid_coordinate);
    });
    require(size >= min_solid_size, size_argument, [&] {
        return "gives a solid of size " + number(size) + ", below the limit " + number(min_solid_size) +
               " (its area and volume must be non-zero numbers)";
    });
    require(size >= min_relative_solid_size * reach, size_argument, [&] {
        return "gives a solid of size " + number(size) + " at " + number(reach) +
               " from the origin, where neighbouring doubles are " + number(reach * 0x1p-52) +
               " apart: a solid must be at least " + number(min_relative_solid_size) + " of its distance from the origin";
    });
}

void require_feature(double feature, double size, std::string_view argument, std::string_view what) {
    require(feature >= limits::min_relative_feature * size, argument, [&] {
        return "gives " + std::string(what) + " of " + number(feature) + ", below " + number(limits::min_relative_feature) +
               " of the solid's size " + number(size) + " (a face's side that short is indistinguishable from a point)";
    });
}

void require_feature_ratio(double longest, double shortest, std::string_view argument, std::string_view what) {
    require(shortest >= limits::min_relative_feature * longest, argument, [&] {
        return "is " + number(longest) + ", more than " + number(1 / limits::min_relative_feature) + " times " +
               std::string(what) + " " + number(shortest) +
               " (next to faces that long its sides would be indistinguishable from points)";
    });
}

double reach_of(const Box& box) {
    double reach = 0;
    for (const Vec3& corner : {box.min, box.max})
        reach = std::max({reach, std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)});
    return reach;
}

}  // namespace ratbez::detail

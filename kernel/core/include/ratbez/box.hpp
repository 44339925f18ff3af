#pragma once
// An axis-aligned box in 3D. Empty until a point is added (min above max); a curve or surface lies in
// the box of its control points (convex hull property), which is how every box here is made.

#include <algorithm>
#include <limits>

#include "ratbez/vec.hpp"

namespace ratbez {

struct Box {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    Vec3 min{kInfinity, kInfinity, kInfinity};
    Vec3 max{-kInfinity, -kInfinity, -kInfinity};

    constexpr bool empty() const { return min.x > max.x; }
    constexpr void add(const Vec3& p) {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
    constexpr void add(const Box& b) {
        if (b.empty()) return;
        add(b.min);
        add(b.max);
    }
    constexpr Vec3 center() const { return (min + max) * 0.5; }
    // The length of the diagonal, the size every relative tolerance of the kernel is measured against; 0 when empty.
    double diagonal() const { return empty() ? 0.0 : norm(max - min); }
    // The distance from p to the box, 0 inside; infinite for an empty box.
    double distance_to(const Vec3& p) const {
        if (empty()) return kInfinity;
        return norm(Vec3{std::max({min.x - p.x, 0.0, p.x - max.x}), std::max({min.y - p.y, 0.0, p.y - max.y}),
                         std::max({min.z - p.z, 0.0, p.z - max.z})});
    }
};

}  // namespace ratbez

// The zipper (kernel/core/src/mesh/strip_zipper.hpp): every rail segment used once, counterclockwise
// triangles, the greedy choice following the cost.

#include "mesh/strip_zipper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ratbez::detail {
namespace {

struct P {
    double x, y;
};

double twice_area(const P& a, const P& b, const P& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Zips rails at y = 0 and y = 1 with the Euclidean diagonal length as cost; returns the points too.
std::vector<std::array<std::size_t, 3>> zip(const std::vector<double>& lower, const std::vector<double>& upper,
                                            std::vector<P>& points) {
    points.clear();
    for (double x : lower) points.push_back({x, 0});
    for (double x : upper) points.push_back({x, 1});
    return zip_rails(lower.size(), upper.size(), [&](std::size_t i, std::size_t j) {
        return std::hypot(upper[j] - lower[i], 1.0);
    });
}

TEST(StripZipper, MismatchedRailsCloseTheStrip) {
    std::vector<P> points;
    const std::vector<double> lower{0, 0.1, 0.2, 0.5, 0.9, 1}, upper{0, 0.5, 1};
    const auto t = zip(lower, upper, points);
    ASSERT_EQ(t.size(), lower.size() + upper.size() - 2);
    double area = 0;
    for (const auto& tri : t) {
        const double a = twice_area(points[tri[0]], points[tri[1]], points[tri[2]]);
        EXPECT_GT(a, 0);
        area += a / 2;
    }
    EXPECT_NEAR(area, 1.0, 1e-15);  // the unit square exactly covered
}

TEST(StripZipper, ShortestDiagonalsOnAShiftedGrid) {
    std::vector<P> points;
    // Upper samples shifted right: the greedy rule must choose lower-rail advances where they are short.
    const auto t = zip({0, 1, 2, 3}, {0, 1.1, 2.1, 3}, points);
    ASSERT_EQ(t.size(), 6u);
    for (const auto& tri : t) {
        double longest = 0;
        for (int k = 0; k < 3; ++k) {
            const P &a = points[tri[k]], &b = points[tri[(k + 1) % 3]];
            longest = std::max(longest, std::hypot(a.x - b.x, a.y - b.y));
        }
        EXPECT_LT(longest, std::hypot(1.1, 1.0) + 1e-12);
    }
}

TEST(StripZipper, SinglePointRailIsAFan) {
    std::vector<P> points;
    const auto t = zip({0.5}, {0, 0.25, 0.5, 0.75, 1}, points);
    ASSERT_EQ(t.size(), 4u);
    for (const auto& tri : t) {
        EXPECT_EQ(tri[0], 0u);  // every triangle has the pole
        EXPECT_GT(twice_area(points[tri[0]], points[tri[1]], points[tri[2]]), 0);
    }
}

TEST(StripZipper, TooFewPointsGiveNothing) {
    std::vector<P> points;
    EXPECT_TRUE(zip({0}, {0}, points).empty());
    EXPECT_TRUE(zip({}, {0, 1}, points).empty());
}

}  // namespace
}  // namespace ratbez::detail

// Searching boundary polylines (kernel/core/src/mesh/segment_search.hpp): the answers of a scan of every segment,
// for points near the polylines, inside and far outside them.

#include "mesh/segment_search.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

namespace ratbez::detail {
namespace {

// A closed wavy ring of `n` points about the origin, radius 1 to 1.5, and a smaller one inside it (a hole).
std::vector<std::array<double, 4>> rings(int n, std::mt19937& random) {
    std::uniform_real_distribution<double> wobble(0.0, 0.5);
    std::vector<std::array<double, 4>> segments;
    for (const double scale : {1.0, 0.3}) {
        std::vector<std::array<double, 2>> points;
        for (int k = 0; k < n; ++k) {
            const double angle = 2 * std::numbers::pi * k / n, r = scale * (1 + wobble(random));
            points.push_back({r * std::cos(angle), r * std::sin(angle)});
        }
        for (int k = 0; k < n; ++k) {
            const auto& a = points[static_cast<std::size_t>(k)];
            const auto& b = points[static_cast<std::size_t>((k + 1) % n)];
            segments.push_back({a[0], a[1], b[0], b[1]});
        }
    }
    return segments;
}

bool scanned_inside(const std::vector<std::array<double, 4>>& segments, double x, double y) {
    bool inside = false;
    for (const auto& [x0, y0, x1, y1] : segments)
        if ((y0 <= y) != (y1 <= y) && x < x0 + (y - y0) / (y1 - y0) * (x1 - x0)) inside = !inside;
    return inside;
}

TEST(SegmentSearch, TheEvenOddRuleAnswersAsAScanOfEverySegment) {
    std::mt19937 random(20261207);
    for (const int n : {10, 500}) {  // scanned below 64 segments, banded above
        const std::vector<std::array<double, 4>> segments = rings(n, random);
        const EvenOddBands bands(segments);
        std::uniform_real_distribution<double> coordinate(-2, 2);
        int inside = 0;
        for (int k = 0; k < 20000; ++k) {
            const double x = coordinate(random), y = coordinate(random);
            ASSERT_EQ(bands.inside(x, y), scanned_inside(segments, x, y)) << x << ", " << y;
            inside += bands.inside(x, y);
        }
        EXPECT_GT(inside, 2000);  // the ring holds points, the hole and the outside do not
        EXPECT_FALSE(bands.inside(0, 0));
    }
    EXPECT_FALSE(EvenOddBands().inside(0, 0));
}

TEST(SegmentSearch, TheNearestSegmentIsAScansNearestTiesToTheLowestIndex) {
    std::mt19937 random(20261208);
    for (const int n : {10, 400}) {  // scanned below 64 segments, searched in a grid above
        std::vector<std::array<Vec3, 2>> segments;
        for (const auto& [x0, y0, x1, y1] : rings(n, random)) segments.push_back({Vec3{x0, y0, 0.1 * x0}, Vec3{x1, y1, 0.1 * x1}});
        const NearestSegment search(segments);
        std::uniform_real_distribution<double> coordinate(-2, 2);
        for (int k = 0; k < 5000; ++k) {
            // Near the rings, and now and then far away: the search must still reach every segment.
            const double far = k % 10 == 0 ? 1e3 : 1;
            const Vec3 p{far * coordinate(random), coordinate(random), coordinate(random)};
            double best = INFINITY;
            std::size_t index = 0;
            for (std::size_t s = 0; s < segments.size(); ++s) {
                const Vec3 e = segments[s][1] - segments[s][0];
                const double f = std::clamp(dot(p - segments[s][0], e) / dot(e, e), 0.0, 1.0);
                const Vec3 d = segments[s][0] + e * f - p;
                if (dot(d, d) < best) best = dot(d, d), index = s;
            }
            const auto found = search.nearest(p);
            ASSERT_TRUE(found.has_value());
            ASSERT_EQ(found->index, index) << p.x << ", " << p.y << ", " << p.z;
            EXPECT_EQ(found->squared_distance, best);
        }
        EXPECT_FALSE(search.nearest(Vec3{NAN, 0, 0}).has_value());
    }
    // The same segment twice: the first.
    const NearestSegment twice({{Vec3{0, 0, 0}, Vec3{1, 0, 0}}, {Vec3{0, 0, 0}, Vec3{1, 0, 0}}});
    EXPECT_EQ(twice.nearest(Vec3{0.5, 1, 0})->index, 0u);
    EXPECT_FALSE(NearestSegment().nearest(Vec3{0, 0, 0}).has_value());
}

}  // namespace
}  // namespace ratbez::detail

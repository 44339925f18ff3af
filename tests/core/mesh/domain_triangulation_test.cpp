// Triangulations of plane regions (kernel/core/src/mesh/domain_triangulation.hpp). Polygons with holes: every
// boundary edge used once in its direction, interior edges twice in opposite directions, the areas adding up,
// no zero-area triangles. (The trimmed faces' refined regions are tested through tessellate, in
// tessellate_trimmed_test.cpp.)
#include "mesh/domain_triangulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <vector>
#include <numbers>
#include <string>
#include <utility>

#include "geometry/surface_evaluator.hpp"
#include "mesh/tessellator.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez::detail {
namespace {

using Triangles = std::vector<std::array<std::size_t, 3>>;

std::vector<Point2> flatten(const std::vector<std::vector<Point2>>& loops) {
    std::vector<Point2> all;
    for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
    return all;
}

double twice_area(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Checks orientation, positive areas, total area and edge usage; `expected_area` is the region's area.
void expect_valid(const std::vector<std::vector<Point2>>& loops, const Triangles& triangles, double expected_area) {
    const auto points = flatten(loops);
    std::size_t vertex_count = points.size();
    EXPECT_EQ(triangles.size(), vertex_count + 2 * (loops.size() - 1) - 2);
    double total = 0, smallest = 1e300;
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    for (const auto& t : triangles) {
        const double a = twice_area(points[t[0]], points[t[1]], points[t[2]]);
        smallest = std::min(smallest, a);
        total += a / 2;
        for (int k = 0; k < 3; ++k) ++directed[std::make_pair(t[k], t[(k + 1) % 3])];
    }
    EXPECT_GT(smallest, 0.0);
    EXPECT_NEAR(total, expected_area, 1e-12 * std::max(1.0, expected_area));
    // Boundary edges (in the normalised orientation: outer counterclockwise, holes clockwise) once,
    // every other edge paired with its reverse.
    std::size_t offset = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const bool ccw = twice_signed_area(loops[l]) > 0;
        const bool keep = ccw == (l == 0);
        const std::size_t n = loops[l].size();
        for (std::size_t k = 0; k < n; ++k) {
            std::size_t a = offset + k, b = offset + (k + 1) % n;
            if (!keep) std::swap(a, b);
            EXPECT_EQ(directed[std::make_pair(a, b)], 1) << "boundary edge " << a << "-" << b;
            EXPECT_EQ(directed.count(std::make_pair(b, a)), 0u);
            directed.erase(std::make_pair(a, b));
        }
        offset += n;
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1);
        const auto reverse = directed.find(std::make_pair(edge.second, edge.first));
        ASSERT_NE(reverse, directed.end()) << "unpaired interior edge";
        EXPECT_EQ(reverse->second, 1);
    }
}

TEST(PolygonTriangulation, SquareGivesTwoTriangles) {
    const std::vector<std::vector<Point2>> loops{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    const auto t = triangulate_polygon(loops);
    ASSERT_EQ(t.size(), 2u);
    expect_valid(loops, t, 1.0);
}

TEST(PolygonTriangulation, ClockwiseInputIsNormalised) {
    const std::vector<std::vector<Point2>> loops{{{0, 1}, {1, 1}, {1, 0}, {0, 0}}};
    expect_valid(loops, triangulate_polygon(loops), 1.0);
}

TEST(PolygonTriangulation, FinelySampledCircleHasNoSlivers) {
    std::vector<Point2> circle;
    const int n = 400;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        circle.push_back({std::cos(a), std::sin(a)});
    }
    const std::vector<std::vector<Point2>> loops{circle};
    const auto t = triangulate_polygon(loops);
    expect_valid(loops, t, n / 2.0 * std::sin(2 * std::numbers::pi / n));
    // Best-ear-first keeps the smallest angle far above the 0.45 degrees of a fan from one vertex.
    double smallest_angle = 180;
    for (const auto& tri : t)
        for (int k = 0; k < 3; ++k) {
            const Point2 &a = circle[tri[k]], &b = circle[tri[(k + 1) % 3]], &c = circle[tri[(k + 2) % 3]];
            const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
            smallest_angle = std::min(smallest_angle, std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / std::numbers::pi);
        }
    EXPECT_GT(smallest_angle, 0.9 * 180.0 / n);
}

TEST(PolygonTriangulation, NonConvexLShape) {
    const std::vector<std::vector<Point2>> loops{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
    expect_valid(loops, triangulate_polygon(loops), 3.0);
}

TEST(PolygonTriangulation, CombShapeWithManyReflexVertices) {
    std::vector<Point2> comb{{0, 0}, {10, 0}};
    for (int k = 9; k >= 0; --k) {  // teeth of width 0.5 and height 3 on a base of height 1
        comb.push_back({k + 1.0, 4});
        comb.push_back({k + 0.5, 4});
        comb.push_back({k + 0.5, 1});
        comb.push_back({k + 0.0, 1});
    }
    const std::vector<std::vector<Point2>> loops{comb};
    expect_valid(loops, triangulate_polygon(loops), 10.0 + 10 * 0.5 * 3);
}

TEST(PolygonTriangulation, SquareWithTwoHoles) {
    const std::vector<std::vector<Point2>> loops{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                                 {{2, 2}, {4, 2}, {4, 4}, {2, 4}},  // counterclockwise: flipped
                                                 {{6, 6}, {6, 8}, {8, 8}, {8, 6}}};
    expect_valid(loops, triangulate_polygon(loops), 100.0 - 4.0 - 4.0);
}

TEST(PolygonTriangulation, CircleWithCircularHole) {
    std::vector<Point2> outer, hole;
    for (int k = 0; k < 64; ++k) {
        const double a = 2 * std::numbers::pi * k / 64;
        outer.push_back({3 * std::cos(a), 3 * std::sin(a)});
        hole.push_back({1 + std::cos(-a), 0.5 + std::sin(-a)});
    }
    const std::vector<std::vector<Point2>> loops{outer, hole};
    expect_valid(loops, triangulate_polygon(loops), (std::abs(twice_signed_area(outer)) - std::abs(twice_signed_area(hole))) / 2);
}

TEST(PolygonTriangulation, CollinearSamplesOnOneSideGetNoZeroAreaTriangle) {
    // A triangle whose long side carries many samples (an edge sampled finer by its other face):
    // the only valid triangulation is the fan from the opposite corner.
    std::vector<Point2> loop;
    for (int k = 0; k <= 10; ++k) loop.push_back({k / 10.0, 0});
    loop.push_back({0.5, 1});
    const std::vector<std::vector<Point2>> loops{loop};
    expect_valid(loops, triangulate_polygon(loops), 0.5);
}

// A hole meeting the outer boundary at a corner of both: one vertex (one id), the triangles numbered by id.
// Two points in one place with different ids are a boundary touching itself by accident, refused.
TEST(PolygonTriangulation, LoopsSharingAVertexTouchThere) {
    const std::vector<std::vector<Point2>> loops{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 2}, {1.5, 0.8}, {0.8, 1.5}}};
    const std::vector<MeshVertexId> ids{10, 11, 12, 13, 12, 14, 15};
    const Triangles triangles = triangulate_polygon(loops, ids);
    double total = 0;
    std::map<std::size_t, Point2> at{{10, {0, 0}}, {11, {2, 0}}, {12, {2, 2}}, {13, {0, 2}}, {14, {1.5, 0.8}}, {15, {0.8, 1.5}}};
    for (const auto& t : triangles) {
        for (std::size_t id : t) ASSERT_EQ(at.count(id), 1u) << id;
        const double a = twice_area(at[t[0]], at[t[1]], at[t[2]]);
        EXPECT_GT(a, 0.0);
        total += a / 2;
    }
    const double hole = std::abs(twice_signed_area(loops[1])) / 2;
    EXPECT_NEAR(total, 4 - hole, 1e-12);
    std::vector<MeshVertexId> apart = ids;
    apart[4] = 16;
    EXPECT_THROW(triangulate_polygon(loops, apart), Error);
    EXPECT_THROW(triangulate_polygon(loops, std::vector<MeshVertexId>(ids.begin(), ids.end() - 1)), Error);
}

// The unit square of the plane z = 0 as a surface to triangulate, and the mesh vertices the triangulation makes
// (`add`). Not copied: `add` refers to it.
struct UnitSquareDomain {
    NurbsSurface plane{1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}}};
    SurfaceEvaluator evaluator{plane};
    std::vector<Vec3> points;
    std::function<MeshVertexId(const Vec3&)> add = [this](const Vec3& p) {
        points.push_back(p);
        return static_cast<MeshVertexId>(points.size() - 1);
    };
    UnitSquareDomain() = default;
    UnitSquareDomain(const UnitSquareDomain&) = delete;
    UnitSquareDomain& operator=(const UnitSquareDomain&) = delete;
};

// A boundary sample held off its surface by more than the tolerance (a file's vertex with a tolerance of its own,
// an Inventor extruder body): the triangles at it cannot come within the tolerance, and refining them toward it,
// round after round, put 182 mesh vertices in one place. A new vertex within a thousandth of the tolerance of a
// corner is not made, and the region is refused, naming the place.
TEST(TrimmedDomainTriangulation, ASampleOffItsSurfaceIsNotRefinedIntoOnePoint) {
    UnitSquareDomain domain;
    std::vector<BoundarySample> loop;
    for (const auto& [u, v] : {std::pair{0.1, 0.1}, std::pair{0.9, 0.1}, std::pair{0.9, 0.9}, std::pair{0.1, 0.9}})
        loop.push_back({u, v, domain.add({u, v, 0}), {u, v, 0}});
    loop[2].point.z = 0.05;  // five times the tolerance off the plane
    domain.points[loop[2].id].z = 0.05;
    TessellationSettings settings;
    settings.tolerance = 0.01;
    settings.max_triangles = 1'000'000;
    const std::vector<std::vector<BoundarySample>> loops{loop};
    try {
        triangulate_trimmed_domain(domain.evaluator, loops, settings, domain.add);
        ADD_FAILURE() << "a region no mesh follows within the tolerance was meshed";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("keeps further from its surface than the tolerance near (0.89"),
                  std::string::npos) << e.what();
    }
    EXPECT_LT(domain.points.size(), 1000u);
    for (std::size_t a = 0; a < domain.points.size(); ++a)
        for (std::size_t b = a + 1; b < domain.points.size(); ++b)
            EXPECT_GT(distance(domain.points[a], domain.points[b]), 1e-5 * settings.tolerance) << a << " " << b;
}

// Loops sampled too coarsely can pass each other without crossing: a band's inner circle, its samples straddling
// out from the wall beside it, all beyond the samples of its outer circle. The region between them is still
// bounded, but nested the wrong way round, and meshed it faced backwards (the mesh intersected itself). A hole
// must lie inside the first loop, as the tessellator's retry (CrossingLoops: sample finer) needs to hear.
TEST(PolygonTriangulation, AHoleOutsideItsOuterLoopIsRefused) {
    const std::vector<Point2> small{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, large{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
    EXPECT_THROW(triangulate_polygon({small, large}), CrossingLoops);
    expect_valid({large, small}, triangulate_polygon({large, small}), 9.0 - 1.0);
}

// A Creo touch screen's corner blend: the p-curve of its bottom edge runs 4.7e-7 past the corner in u, a few 1e-12
// into the face, and turns back to it (in space 5e-6, within the file's vertex tolerance of 1.3e-3). Its last
// sample then lay beyond the side edge rising from the corner, and the loop crossed itself at any sampling. Placed
// on the chord to the corner, the loop is simple and the face meshes; the mesh vertices stay as they were.
TEST(TrimmedDomainTriangulation, ASamplePastItsCornerIsPlacedBackOnTheChord) {
    UnitSquareDomain domain;
    // The unit square, counterclockwise from (0, 0), 8 samples a side; each side's samples start at its corner.
    std::vector<BoundarySample> loop;
    std::vector<std::size_t> corners;
    const Point2 corner_at[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int side = 0; side < 4; ++side) {
        corners.push_back(loop.size());
        const Point2 a = corner_at[side], b = corner_at[(side + 1) % 4];
        for (int k = 0; k < 8; ++k) {
            const double f = k / 8.0, u = a.x + f * (b.x - a.x), v = a.y + f * (b.y - a.y);
            loop.push_back({u, v, domain.add({u, v, 0}), {u, v, 0}});
        }
    }
    // The bottom side's last sample, its p-curve's, past the corner (1, 0) and into the face; its edge's point is
    // 5e-6 before the corner.
    BoundarySample& past = loop[corners[1] - 1];
    past.u = 1 + 4.7e-7;
    past.v = 4e-12;
    past.point = {1 - 5e-6, 0, 0};
    TessellationSettings settings;
    settings.tolerance = 0.01;
    settings.max_triangles = 1'000'000;
    EXPECT_THROW(triangulate_trimmed_domain(domain.evaluator, std::vector<std::vector<BoundarySample>>{loop}, settings, domain.add),
                 CrossingLoops);

    std::vector<BoundarySample> unhooked = loop;
    unhook_corners(unhooked, corners);
    const BoundarySample& placed = unhooked[corners[1] - 1];
    EXPECT_LT(placed.u, 1.0);
    EXPECT_NEAR(placed.u, 1 - 5e-6, 1e-9);  // as far along the chord from (7/8, 0) as its edge's point is
    EXPECT_NEAR(placed.v, 0.0, 1e-12);
    EXPECT_EQ(placed.id, past.id);
    for (std::size_t k = 0; k < loop.size(); ++k)  // nothing else moved: no other sample turns back
        EXPECT_TRUE(k == corners[1] - 1 || (unhooked[k].u == loop[k].u && unhooked[k].v == loop[k].v)) << k;
    // A step back a third as long as the chord before it is the edge's own turn in (u, v), not a hook: it stays.
    std::vector<BoundarySample> turning = loop;
    turning[corners[1] - 1].u = 1 + 0.04;
    unhook_corners(turning, corners);
    EXPECT_EQ(turning[corners[1] - 1].u, 1 + 0.04);
    const auto triangles =
        triangulate_trimmed_domain(domain.evaluator, std::vector<std::vector<BoundarySample>>{unhooked}, settings, domain.add);
    double area = 0;
    for (const auto& t : triangles) {
        const Vec3 p = domain.points[t[0]], q = domain.points[t[1]], r = domain.points[t[2]];
        EXPECT_GT(cross(q - p, r - p).z, 0.0);
        area += cross(q - p, r - p).z / 2;
    }
    EXPECT_NEAR(area, 1.0, 1e-9);
}

TEST(PolygonTriangulation, RejectsDegenerateInput) {
    EXPECT_THROW(triangulate_polygon({}), Error);
    EXPECT_THROW(triangulate_polygon({{{0, 0}, {1, 0}}}), Error);
    EXPECT_THROW(triangulate_polygon({{{0, 0}, {1, 0}, {0, std::nan("")}}}), Error);
}

}  // namespace
}  // namespace ratbez::detail

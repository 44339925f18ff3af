// max_deviation (deviation.hpp) against analytic values for meshes built by hand: it must be right
// for any mesh, not only ours.

#include "ratbez/deviation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez {
namespace {

constexpr double kPi = std::numbers::pi;

Mesh octahedron(double r) {
    Mesh m;
    m.vertices = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

TEST(MaxDeviation, OctahedronInscribedInSphere) {
    // The face centers are the points nearest the center: R / sqrt(3) from it, R (1 - 1/sqrt(3)) inside.
    // samples_per_edge = 6 puts a sample exactly on each center.
    const double r = 2.5;
    EXPECT_NEAR(max_deviation(sphere(r), octahedron(r)), r * (1 - 1 / std::sqrt(3.0)), 1e-9);
}

TEST(MaxDeviation, ScaledOctahedronAroundSphere) {
    // Vertices at 1.5 R outside: the farthest points are the vertices, 0.5 R off; the centers are at
    // 1.5 R / sqrt(3) = 0.866 R, 0.134 R inside.
    const double r = 1.0;
    EXPECT_NEAR(max_deviation(sphere(r), octahedron(1.5 * r)), 0.5 * r, 1e-9);
}

DeviationOptions samples_per_edge(int n) {
    DeviationOptions options;
    options.samples_per_edge = n;
    return options;
}

TEST(MaxDeviation, SphereOffCenterAndSampleCount) {
    Mesh m = octahedron(1.0);
    for (Vec3& v : m.vertices) v += Vec3{1, 2, 3};
    // With one sample per edge only the vertices are sampled: they lie on the sphere.
    EXPECT_NEAR(max_deviation(sphere(1.0, {1, 2, 3}), m, samples_per_edge(1)), 0.0, 1e-9);
    EXPECT_NEAR(max_deviation(sphere(1.0, {1, 2, 3}), m, samples_per_edge(3)), 1 - 1 / std::sqrt(3.0), 1e-9);
}

// A prism over a regular n-gon, between z = 0 and z = h, with its vertices at radius `rho`.
Mesh prism(int n, double rho, double h) {
    Mesh m;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * kPi * k / n;
        m.vertices.push_back({rho * std::cos(a), rho * std::sin(a), 0});
        m.vertices.push_back({rho * std::cos(a), rho * std::sin(a), h});
    }
    auto lo = [&](int k) { return static_cast<std::uint32_t>(2 * (k % n)); };
    auto hi = [&](int k) { return static_cast<std::uint32_t>(2 * (k % n) + 1); };
    for (int k = 0; k < n; ++k) {
        m.triangles.push_back({lo(k), lo(k + 1), hi(k + 1)});
        m.triangles.push_back({lo(k), hi(k + 1), hi(k)});
    }
    for (int k = 1; k + 1 < n; ++k) {
        m.triangles.push_back({lo(0), lo(k + 1), lo(k)});
        m.triangles.push_back({hi(0), hi(k), hi(k + 1)});
    }
    return m;
}

TEST(MaxDeviation, InscribedPrismInCylinder) {
    // The side midlines of the lateral rectangles are the farthest: 1 - cos(pi / n) inside. The caps
    // lie in the cap planes inside the circle: distance 0 there.
    const int n = 12;
    const Mesh m = prism(n, 1.0, 2.0);
    ASSERT_TRUE(m.is_closed());
    EXPECT_NEAR(max_deviation(cylinder(1.0, 2.0), m), 1 - std::cos(kPi / n), 1e-9);
}

TEST(MaxDeviation, CircumscribedPrismCornersOutsideTheCaps) {
    // Vertices at 1 / cos(pi / n): the cap corners lie in the cap plane but outside the disc, so their
    // distance is to the rim circle, 1 / cos(pi / n) - 1; the lateral midlines touch the cylinder.
    const int n = 8;
    const Mesh m = prism(n, 1.0 / std::cos(kPi / n), 2.0);
    EXPECT_NEAR(max_deviation(cylinder(1.0, 2.0), m), 1.0 / std::cos(kPi / n) - 1.0, 1e-9);
}

TEST(MaxDeviation, PointsAboveACapMeasureToThePlane) {
    // A flat triangle hovering 0.3 above the top cap, well inside the rim: distance 0.3 everywhere.
    Mesh m;
    m.vertices = {{0, 0, 2.3}, {0.3, 0, 2.3}, {0, 0.3, 2.3}};
    m.triangles = {{0, 1, 2}};
    EXPECT_NEAR(max_deviation(cylinder(1.0, 2.0), m), 0.3, 1e-12);
}

// A D of faces of very different sizes: 200 short sides round a half circle of radius 10, one long side across it
// and its two caps. The search for the nearest face reaches each class of faces (by their seeds' spacing) only as far as those
// faces can hold a foot; it must still find every foot. Checked sample by sample, as max_deviation takes them,
// against the exact distance to every face of a mesh whose vertices were moved off the solid.
TEST(MaxDeviation, FacesOfVeryDifferentSizesAreAllReached) {
    constexpr int kSides = 200;
    constexpr double kHeight = 0.5;
    std::vector<Vec3> corners;
    for (int k = 0; k <= kSides; ++k) corners.push_back({10 * std::cos(kPi * k / kSides), 10 * std::sin(kPi * k / kSides), 0});
    std::vector<NurbsCurve> pieces;
    for (std::size_t k = 0; k + 1 < corners.size(); ++k) pieces.push_back(line_segment(corners[k], corners[k + 1]));
    pieces.push_back(line_segment(corners.back(), corners.front()));
    corners.push_back(corners.front());  // the closed polygon
    const Solid d = extrude(Profile(pieces), {0, 0, 1}, kHeight);

    Mesh mesh = tessellate(d, 1e-3);
    std::uint64_t state = 20261208;
    const auto jitter = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return 0.02 * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
    };
    for (Vec3& v : mesh.vertices) v += Vec3{jitter(), jitter(), jitter()};

    // The exact distance to the D's boundary: its sides are segments times [0, h], its caps the polygon at 0 and h.
    const auto to_segment = [](double x, double y, const Vec3& a, const Vec3& b) {
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double t = std::clamp(((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        return std::hypot(x - a.x - t * dx, y - a.y - t * dy);
    };
    const auto exact = [&](const Vec3& p) {
        double to_boundary = std::numeric_limits<double>::infinity();
        bool inside = false;
        for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
            const Vec3 &a = corners[k], &b = corners[k + 1];
            to_boundary = std::min(to_boundary, to_segment(p.x, p.y, a, b));
            if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) inside = !inside;
        }
        const double below = std::max({0.0, -p.z, p.z - kHeight});
        const double sides = std::hypot(to_boundary, below);
        const double caps = std::min(std::abs(p.z), std::abs(p.z - kHeight));
        return std::min(sides, inside ? caps : std::hypot(to_boundary, caps));
    };
    DeviationOptions options;
    options.samples_per_edge = 3;
    double expected = 0;
    for (const auto& t : mesh.triangles)
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; i + j <= 3; ++j) {
                const double wb = i / 3.0, wc = j / 3.0;
                expected = std::max(expected, exact(mesh.vertices[t[0]] * (1 - wb - wc) + mesh.vertices[t[1]] * wb +
                                                    mesh.vertices[t[2]] * wc));
            }
    EXPECT_GT(expected, 0.005);
    EXPECT_NEAR(max_deviation(d, mesh, options), expected, 1e-9);

    // A small triangle 0.3 above the top cap just inside the round rim: the nearest seeds are the short sides'
    // along the rim, the cap's own lie farther, and the distance is 0.3 to the cap all over.
    Mesh above;
    above.vertices = {{0, 9.9, kHeight + 0.3}, {0.1, 9.8, kHeight + 0.3}, {-0.1, 9.8, kHeight + 0.3}};
    above.triangles = {{0, 1, 2}};
    EXPECT_NEAR(max_deviation(d, above), 0.3, 1e-12);
}

TEST(MaxDeviation, TorusTubeCircle) {
    // A tiny triangle at the torus center (0, 0, 0): the nearest surface points are on the inner
    // equator, R - r = 2 away.
    Mesh m;
    m.vertices = {{0, 0, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}};
    m.triangles = {{0, 1, 2}};
    EXPECT_NEAR(max_deviation(torus(3.0, 1.0), m), 2.0, 1e-9);
}

TEST(MaxDeviation, EmptyMeshIsZeroAndBadInputIsRejected) {
    EXPECT_EQ(max_deviation(sphere(1.0), Mesh{}), 0.0);
    Mesh bad = octahedron(1.0);
    bad.triangles.push_back({0, 1, 17});
    EXPECT_THROW(max_deviation(sphere(1.0), bad), Error);
    EXPECT_THROW(max_deviation(sphere(1.0), octahedron(1.0), samples_per_edge(0)), Error);
    Mesh nan_mesh = octahedron(1.0);
    nan_mesh.vertices[0].x = std::nan("");
    EXPECT_THROW(max_deviation(sphere(1.0), nan_mesh), Error);
}

// A triangle's samples may each search many faces (a part with 1481 of them took 2 ms a triangle): the progress,
// and with it Ctrl-C, comes every few triangles, not every thousand (2 s on that part).
TEST(MaxDeviation, ReportsProgressEveryFewTriangles) {
    const Solid solid = sphere(1.0);
    const Mesh mesh = tessellate(solid, 1e-3);
    ASSERT_GT(mesh.triangles.size(), 2000u);
    std::size_t calls = 0;
    double last = -1;
    DeviationOptions options;
    options.progress = [&](double fraction) {
        EXPECT_GE(fraction, last);
        last = fraction;
        ++calls;
    };
    max_deviation(solid, mesh, options);
    EXPECT_GE(calls, mesh.triangles.size() / 32);
    EXPECT_EQ(last, 1.0);
}

}  // namespace
}  // namespace ratbez

namespace ratbez {
namespace {

// Found by the demo (a sphere of radius 10): pole rows whose points differ only by rounding were kept as
// seeds that Newton cannot turn, so samples near a pole measured their distance to the pole. The measure
// must be scale-invariant: the same mesh scaled by k deviates k times as much.
TEST(MaxDeviation, IsScaleInvariantNearPoles) {
    const double unit = max_deviation(sphere(1.0), tessellate(sphere(1.0), 1e-2));
    for (double radius : {5.0, 10.0, 1000.0}) {
        const Solid scaled = sphere(radius);
        EXPECT_NEAR(max_deviation(scaled, tessellate(scaled, 1e-2 * radius)) / radius, unit, 1e-6 * unit)
            << "radius " << radius;
    }
}

}  // namespace
}  // namespace ratbez

#include "ratbez/properties.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "ratbez/curves.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/revolve.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

struct Expected {
    std::string name;
    Solid solid;
    double volume, area;
};

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

TEST(Properties, VolumeAndAreaMatchClosedForms) {
    const double r = 1.7, h = 2.3, r2 = 0.6, R = 4.1;
    const double slant = std::hypot(r - r2, h), apex_slant = std::hypot(r, h);
    const Vec3 c{3, -2, 5}, axis{1, 2, -0.5};
    std::vector<Expected> cases;
    cases.push_back({"sphere", sphere(r, c), 4.0 / 3.0 * pi * r * r * r, 4 * pi * r * r});
    cases.push_back({"cylinder", cylinder(r, h, c, axis), pi * r * r * h, 2 * pi * r * h + 2 * pi * r * r});
    cases.push_back({"cone", cone(r, 0, h, c, axis), pi * r * r * h / 3, pi * r * apex_slant + pi * r * r});
    cases.push_back({"inverted cone", cone(0, r, h, c, axis), pi * r * r * h / 3, pi * r * apex_slant + pi * r * r});
    cases.push_back({"frustum", cone(r, r2, h, c, axis), pi * h / 3 * (r * r + r * r2 + r2 * r2),
                     pi * (r + r2) * slant + pi * r * r + pi * r2 * r2});
    cases.push_back({"torus", torus(R, r, c, axis), 2 * pi * pi * R * r * r, 4 * pi * pi * R * r});
    double worst_volume = 0, worst_area = 0;
    for (const Expected& e : cases) {
        const double v = relative(enclosed_volume(e.solid), e.volume), a = relative(surface_area(e.solid), e.area);
        EXPECT_LT(v, 1e-10) << e.name;
        EXPECT_LT(a, 1e-10) << e.name;
        EXPECT_NEAR(e.solid.volume(), enclosed_volume(e.solid), 0.0) << e.name;
        worst_volume = std::max(worst_volume, v);
        worst_area = std::max(worst_area, a);
        std::cout << "[ measured ] " << e.name << ": volume error " << v << ", area error " << a << "\n";
    }
    std::cout << "[ measured ] primitives: largest relative volume error " << worst_volume << ", area error "
              << worst_area << "\n";
}

TEST(Properties, PappusGuldinusForRevolvedPolygonsAndCircles) {
    // A triangle and a quadrilateral in the xz half-plane, and a circle, revolved about z: V = 2π ρ̄ A and
    // (for the circle) area = 2π ρ̄ L, with ρ̄ the centroid's distance from the axis.
    double worst = 0;
    const std::vector<std::vector<Vec3>> polygons = {
        {{1, 0, 0}, {3, 0, 0.5}, {1.5, 0, 2}},
        {{0.5, 0, -1}, {2, 0, -1.5}, {2.5, 0, 1}, {1, 0, 2}},
    };
    for (const auto& poly : polygons) {
        std::vector<NurbsCurve> pieces;
        double area = 0, moment = 0;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec3& a = poly[i];
            const Vec3& b = poly[(i + 1) % poly.size()];
            pieces.push_back(line_segment(a, b));
            const double cross_term = a.x * b.z - b.x * a.z;
            area += cross_term / 2;
            moment += (a.x + b.x) * cross_term / 6;  // ∫∫ x dA
        }
        const Solid solid = revolve(Profile(pieces));
        const double expected = 2 * pi * std::abs(moment);
        const double error = relative(solid.volume(), expected);
        EXPECT_LT(error, 1e-10);
        worst = std::max(worst, error);
        EXPECT_EQ(solid.euler_characteristic(), 0);
        (void)area;
    }
    const double R = 2.5, r = 0.8;
    const Solid ring = revolve(Profile({circle(r, {R, 0, 0.3}, {0, 1, 0})}));
    const double v = relative(ring.volume(), 2 * pi * R * pi * r * r), a = relative(ring.area(), 2 * pi * R * 2 * pi * r);
    EXPECT_LT(v, 1e-10);
    EXPECT_LT(a, 1e-10);
    worst = std::max({worst, v, a});
    std::cout << "[ measured ] Pappus–Guldinus: largest relative error " << worst << "\n";
}

TEST(Properties, FaceAreasAddUpAndPlanarCapsAreDisks) {
    const Solid cyl = cylinder(2, 5);
    EXPECT_NEAR(surface_area(cyl.faces()[0]), 2 * pi * 2 * 5, 1e-11);
    EXPECT_NEAR(surface_area(cyl.faces()[1]), pi * 4, 1e-12);
    EXPECT_NEAR(surface_area(cyl.faces()[2]), pi * 4, 1e-12);
    EXPECT_NEAR(surface_area(cyl), 2 * pi * 2 * 5 + 8 * pi, 1e-11);
}

}  // namespace
}  // namespace ratbez

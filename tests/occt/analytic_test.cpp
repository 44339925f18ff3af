// Our primitives against OCCT's analytic surfaces: every point of our exact rational surfaces lies on
// OCCT's Geom_CylindricalSurface / Geom_ConicalSurface / Geom_SphericalSurface / Geom_ToroidalSurface of
// the same primitive (GeomAPI_ProjectPointOnSurf), and our surfaces and OCCT's own exact conversions
// (GeomConvert::SurfaceToBSplineSurface of the analytic surface trimmed to the same range) are the same
// point set: ours projected onto theirs, and theirs onto ours.

#include <gtest/gtest.h>

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>

#include <cmath>
#include <numbers>
#include <string>

#include "occt_test_support.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez::occt {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kGrid = 25;
constexpr double kTolerance = 1e-10;

gp_Ax3 frame_of(const Vec3& center, const Vec3& axis) {
    const Vec3 a = axis / norm(axis);
    return gp_Ax3(to_occt_point(center), gp_Dir(a.x, a.y, a.z));
}

// Largest distance from grid points of `from` (by its own bounds) to `onto`.
double max_projection_distance(const Handle(Geom_Surface)& from, const Handle(Geom_Surface)& onto,
                               double u0, double u1, double v0, double v1) {
    double from_u0, from_u1, from_v0, from_v1;
    from->Bounds(from_u0, from_u1, from_v0, from_v1);
    GeomAPI_ProjectPointOnSurf projector;
    projector.Init(onto, u0, u1, v0, v1, 1e-15);
    double worst = 0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const gp_Pnt p = from->Value(from_u0 + (from_u1 - from_u0) * i / (kGrid - 1),
                                         from_v0 + (from_v1 - from_v0) * j / (kGrid - 1));
            projector.Perform(p);
            EXPECT_TRUE(projector.IsDone() && projector.NbPoints() > 0) << "projection failed";
            if (projector.NbPoints() > 0) worst = std::max(worst, projector.LowerDistance());
        }
    return worst;
}

struct Case {
    std::string name;
    Solid solid;
    Handle(Geom_Surface) analytic;  // OCCT's analytic surface of the primitive
    double v0, v1;                  // the range of its v parameter our lateral face covers
};

std::vector<Case> cases() {
    const Vec3 c{0.5, -1, 2}, axis{1, 2, 2};
    const gp_Ax3 frame = frame_of(c, axis);
    std::vector<Case> out;
    out.push_back({"cylinder", cylinder(1.5, 4, c, axis), new Geom_CylindricalSurface(frame, 1.5), 0, 4});
    const double a = std::atan2(0.8 - 2.0, 3.0);
    out.push_back({"cone", cone(2, 0.8, 3, c, axis), new Geom_ConicalSurface(frame, a, 2), 0, 3 / std::cos(a)});
    const double apex_angle = std::atan2(1.5, 2.5);
    out.push_back({"cone with apex", cone(0, 1.5, 2.5, c, axis), new Geom_ConicalSurface(frame, apex_angle, 0), 0,
                   2.5 / std::cos(apex_angle)});
    const Vec3 sphere_center{3, 1, -2};
    out.push_back({"sphere", sphere(2, sphere_center), new Geom_SphericalSurface(frame_of(sphere_center, {0, 0, 1}), 2),
                   -kPi / 2, kPi / 2});
    out.push_back({"torus", torus(3, 0.75, c, axis), new Geom_ToroidalSurface(frame, 3, 0.75), 0, 2 * kPi});
    return out;
}

TEST(AnalyticSurfaces, PrimitivesLieOnOcctsAnalyticSurfaces) {
    testing::MaxTracker tracker("primitives: max distance to OCCT's analytic surface / size");
    for (const Case& c : cases()) {
        const double size = c.solid.bounding_box().diagonal();
        for (const Face& face : c.solid.faces()) {
            if (face.kind() != Face::Kind::surface) continue;
            const Handle(Geom_Surface) ours = to_occt(face.surface());
            const double d = max_projection_distance(ours, c.analytic, 0, 2 * kPi, c.v0 - 0.1, c.v1 + 0.1);
            tracker.add(d / size);
            EXPECT_LE(d, kTolerance * size) << c.name;
        }
    }
}

TEST(AnalyticSurfaces, PrimitivesEqualOcctsOwnExactConversions) {
    testing::MaxTracker ours_onto_theirs("primitives: max distance ours -> GeomConvert's / size");
    testing::MaxTracker theirs_onto_ours("primitives: max distance GeomConvert's -> ours / size");
    for (const Case& c : cases()) {
        const double size = c.solid.bounding_box().diagonal();
        const Handle(Geom_BSplineSurface) theirs = GeomConvert::SurfaceToBSplineSurface(
            new Geom_RectangularTrimmedSurface(c.analytic, 0, 2 * kPi, c.v0, c.v1));
        ASSERT_FALSE(theirs.IsNull()) << c.name;
        EXPECT_TRUE(theirs->IsURational() || theirs->IsVRational()) << c.name << ": the conversion of a circle is rational";
        double tu0, tu1, tv0, tv1;
        theirs->Bounds(tu0, tu1, tv0, tv1);
        for (const Face& face : c.solid.faces()) {
            if (face.kind() != Face::Kind::surface) continue;
            const Handle(Geom_BSplineSurface) ours = to_occt(face.surface());
            double u0, u1, v0, v1;
            ours->Bounds(u0, u1, v0, v1);
            const double a = max_projection_distance(ours, theirs, tu0, tu1, tv0, tv1);
            const double b = max_projection_distance(theirs, ours, u0, u1, v0, v1);
            ours_onto_theirs.add(a / size);
            theirs_onto_ours.add(b / size);
            EXPECT_LE(a, kTolerance * size) << c.name;
            EXPECT_LE(b, kTolerance * size) << c.name;
        }
    }
}

}  // namespace
}  // namespace ratbez::occt

// Tessellation of trimmed faces (tessellate.hpp, domain_triangulation.hpp): the kernel's solids rebuilt with
// trimmed faces (trimmed_test_support.hpp) mesh closed, outward, within the tolerance both ways, with no
// zero-area triangle; mixed with untrimmed faces they stay watertight; the angle limit holds; a flat patch with
// a hole meshes around the hole; faces whose boundary samples would cross have their edges sampled finer instead.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "ratbez/affine_map.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/tessellate.hpp"
#include "solid_test_support.hpp"
#include "trimmed_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

struct Case {
    std::string name;
    std::function<Solid()> make;
};

std::vector<Case> cases() {
    return {
        {"sphere", [] { return sphere(1.0); }},
        {"cylinder", [] { return cylinder(1.0, 2.0, {0, 0, 0}, {1, 0, 1}); }},
        {"cone_apex", [] { return cone(1.0, 0.0, 1.5); }},
        {"torus", [] { return torus(3.0, 1.0); }},
        {"revolution_270",
         [] {
             return revolve(Profile({line_segment({2, 0, 0}, {3, 0, 0}), arc(0.5, 270, 450, {3, 0, 0.5}, {0, -1, 0}),
                                     line_segment({3, 0, 1}, {2, 0, 1}), line_segment({2, 0, 1}, {2, 0, 0})}),
                            {0, 0, 0}, {0, 0, 1}, 270);
         }},
        {"plate_with_hole",
         [] {
             const Profile outer({line_segment({0, 0, 0}, {4, 0, 0}), line_segment({4, 0, 0}, {4, 3, 0}),
                                  line_segment({4, 3, 0}, {0, 3, 0}), line_segment({0, 3, 0}, {0, 0, 0})});
             return extrude(outer, {0, 0.2, 1}, 1.5, {Profile(std::vector<NurbsCurve>{circle(0.8, {2, 1.5, 0}, {0, 0, -1})})});
         }},
    };
}

double smallest_triangle_area(const Mesh& m) {
    double smallest = 1e300;
    for (const auto& t : m.triangles)
        smallest = std::min(smallest, 0.5 * norm(cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]])));
    return smallest;
}

void expect_good_mesh(const Solid& solid, const Mesh& mesh, double tolerance, const std::string& what) {
    SCOPED_TRACE(what + " at tolerance " + std::to_string(tolerance));
    const double size = solid.bounding_box().diagonal();
    EXPECT_TRUE(mesh.is_closed());
    EXPECT_GT(mesh.volume(), 0.0);
    EXPECT_GT(smallest_triangle_area(mesh), 1e-12 * size * size);
    EXPECT_LE(max_deviation(solid, mesh), tolerance);
    EXPECT_LE(max_surface_to_mesh_distance(solid, mesh), tolerance);
    EXPECT_LE(std::abs(mesh.volume() - solid.volume()), tolerance * solid.area());
}

TEST(TessellateTrimmed, KernelSolidsRebuiltTrimmedMeshWithinToleranceBothWays) {
    for (const Case& c : cases()) {
        const Solid trimmed = as_trimmed(c.make());
        const double size = trimmed.bounding_box().diagonal();
        for (double fraction : {1e-2, 1e-3}) {
            const double tolerance = fraction * size;
            expect_good_mesh(trimmed, tessellate(trimmed, tolerance), tolerance, c.name);
        }
    }
}

TEST(TessellateTrimmed, TrimmedAndUntrimmedFacesMeetWatertight) {
    for (const Case& c : cases()) {
        const Solid solid = c.make();
        // Every other face trimmed: edges shared by the two kinds, samples from the surface faces' grids.
        const Solid mixed = as_trimmed(solid, [](std::size_t i) { return i % 2 == 0; });
        const double tolerance = 2e-3 * solid.bounding_box().diagonal();
        expect_good_mesh(mixed, tessellate(mixed, tolerance), tolerance, c.name + " (mixed)");
    }
}

TEST(TessellateTrimmed, AngleLimitIsHonoured) {
    const Solid solid = as_trimmed(torus(3.0, 1.0));
    const double angle_deg = 6.0;
    const Mesh mesh = tessellate(solid, 0.1, angle_deg);
    EXPECT_TRUE(mesh.is_closed());
    EXPECT_GT(mesh.triangles.size(), tessellate(solid, 0.1).triangles.size());
    const auto normal = [](const Vec3& p) {
        const double r = std::hypot(p.x, p.y);
        const Vec3 centre{3 * p.x / r, 3 * p.y / r, 0};
        return (p - centre) / norm(p - centre);
    };
    double worst = 0;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Vec3 a = normal(mesh.vertices[t[k]]), b = normal(mesh.vertices[t[(k + 1) % 3]]);
            worst = std::max(worst, std::atan2(norm(cross(a, b)), dot(a, b)) * 180 / std::numbers::pi);
        }
    EXPECT_LE(worst, angle_deg * 1.0001);
}

TEST(TessellateTrimmed, AFaceOnItsOwnMeshesItsRegionOnly) {
    // The sphere's face rebuilt trimmed, meshed alone: the same area as the sphere to the tolerance's order.
    const Solid solid = as_trimmed(sphere(2.0));
    TessellationOptions options;
    options.tolerance = 1e-3;
    const Mesh mesh = tessellate(solid.faces().front(), options);
    EXPECT_NEAR(mesh.area(), 16 * std::numbers::pi, 1e-3 * solid.area());
}

// A ring 0.05 wide between circles of radius 1 and 0.95, 0.5 high.
Solid thin_ring() {
    const Profile outer(std::vector<NurbsCurve>{circle(1.0)});
    const Profile hole(std::vector<NurbsCurve>{circle(0.95, {0, 0, 0}, {0, 0, -1})});
    return extrude(outer, {0, 0, 1}, 0.5, {hole});
}

// The index of thin_ring's face that `is` picks.
std::size_t ring_face(const Solid& ring, const std::function<bool(const Face&)>& is) {
    for (std::size_t i = 0; i < ring.faces().size(); ++i)
        if (is(ring.faces()[i])) return i;
    ADD_FAILURE() << "no such face";
    return 0;
}
bool is_hole_wall(const Face& f) {
    if (f.kind() != Face::Kind::surface) return false;
    const Interval u = f.surface().domain_u(), v = f.surface().domain_v();
    const Vec3 p = f.point(0.5 * (u.min + u.max), 0.5 * (v.min + v.max));
    return std::hypot(p.x, p.y) < 0.975;
}
bool is_top(const Face& f) { return f.kind() == Face::Kind::planar && f.plane().normal.z > 0.5; }

// The ring with its hole's wall trimmed, as a file's would be: that circle's samples lie on it while the outer
// one's straddle it, their chords dipping up to the tolerance inside it, across the band.
Solid thin_ring_apart() {
    const Solid ring = thin_ring();
    const std::size_t hole = ring_face(ring, is_hole_wall);
    return as_trimmed(ring, [&](std::size_t i) { return i == hole; });
}

TEST(TessellateTrimmed, ThinBandsCloserThanTheToleranceAreMeshedFiner) {
    // Meshed at 0.2, the ring's two circles' chords would cross each other; the mesh still closes and keeps within
    // the tolerance (the edges of the loops that cross are sampled finer until they separate).
    for (const Solid& solid : {thin_ring(), as_trimmed(thin_ring()), thin_ring_apart()}) {
        const Mesh mesh = tessellate(solid, 0.2);
        EXPECT_TRUE(mesh.is_closed());
        EXPECT_LE(max_deviation(solid, mesh), 0.2);
        EXPECT_GT(mesh.volume(), 0.0);
    }
}

// The thin ring beside a face read loosely, as from a file: its top's surface lies 0.095 from its edges (the file's
// tolerance 0.1). The tessellation used to retry the crossing circles at half the tolerance for the whole solid,
// down below the loose face's own tolerance, where no mesh follows its boundary, and refused it (a Prusa extruder
// body: a band 0.0044 wide between two arcs, at its default tolerance and most others). Only the ring's edges are
// sampled finer now.
TEST(TessellateTrimmed, AThinBandBesideALooseFaceMeshesAtTheToleranceAsked) {
    const Solid ring = thin_ring_apart();
    std::vector<Face> faces = ring.faces();
    const std::size_t top = ring_face(ring, is_top);
    const Face trimmed = as_trimmed(faces[top]);
    faces[top] = Face::trimmed(transformed(trimmed.surface(), AffineMap::translation({0, 0, 0.095})), trimmed.loops(), 0.1);
    const Solid solid(std::move(faces));
    const double tolerance = 0.2;
    const Mesh mesh = tessellate(solid, tolerance);
    EXPECT_TRUE(mesh.is_closed());
    EXPECT_GT(mesh.volume(), 0.0);
    EXPECT_LE(max_deviation(solid, mesh), tolerance);
}

}  // namespace
}  // namespace ratbez

// Trimmed faces (Face::trimmed) and solids with voids: validation, measures, tables, transforms.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "ratbez/brep.hpp"
#include "ratbez/brep_tables.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/solid_transform.hpp"
#include "solid_test_support.hpp"
#include "trimmed_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// The flat patch S(u, v) = (2(u - o), 3(v - o), 0) over [o, o + 1]^2 (o = 0 unless given), and loops on it given in
// (u, v).
struct FlatPatch {
    explicit FlatPatch(double origin = 0)
        : o(origin), surface{1, 1, {o, o, o + 1, o + 1}, {o, o, o + 1, o + 1}, {{{0, 0, 0}, {0, 3, 0}}, {{2, 0, 0}, {2, 3, 0}}}} {}
    double o;
    NurbsSurface surface;
    Vec3 at(const Vec3& uv) const { return {2 * (uv.x - o), 3 * (uv.y - o), 0}; }
    // A closed polygon through the (u, v) points in the order given.
    std::vector<Coedge> polygon(const std::vector<Vec3>& uv) const {
        std::vector<VertexPtr> vertices;
        for (const Vec3& p : uv) vertices.push_back(std::make_shared<const Vertex>(Vertex{at(p)}));
        std::vector<Coedge> loop;
        for (std::size_t k = 0; k < uv.size(); ++k) {
            const Vec3 &a = uv[k], &b = uv[(k + 1) % uv.size()];
            const auto edge = std::make_shared<const Edge>(
                Edge{NurbsCurve(1, {0, 0, 1, 1}, {at(a), at(b)}), vertices[k], vertices[(k + 1) % uv.size()], false});
            loop.push_back(Coedge{edge, false, straight_pcurve(a, b, 0, 1)});
        }
        return loop;
    }
    // A circle of radius r about (cu, cv) in (u, v), clockwise (a hole), as one closed coedge: its p-curve is
    // the exact rational circle, its edge that curve mapped through the affine patch (an exact ellipse).
    std::vector<Coedge> circular_hole(double cu, double cv, double r) const {
        const NurbsCurve uv_circle = circle(r, {cu, cv, 0}, {0, 0, -1});
        std::vector<Vec4> mapped = uv_circle.homogeneous_points();
        for (Vec4& p : mapped) {
            const Vec3 q = at(project(p));
            p = Vec4{q.x * p.w, q.y * p.w, q.z * p.w, p.w};
        }
        const NurbsCurve edge_curve = NurbsCurve::from_homogeneous(uv_circle.degree(), uv_circle.knots(), mapped, true);
        const auto v = std::make_shared<const Vertex>(Vertex{edge_curve.start_point()});
        const auto edge = std::make_shared<const Edge>(Edge{edge_curve, v, v, false});
        return {Coedge{edge, false, std::make_shared<const NurbsCurve>(uv_circle)}};
    }
    std::vector<Coedge> square(double lo, double hi) const {
        return polygon({{lo, lo, 0}, {hi, lo, 0}, {hi, hi, 0}, {lo, hi, 0}});
    }
};

TEST(TrimmedFace, AreaOfAFlatPatchWithAHoleIsTheRegionsArea) {
    const FlatPatch patch;
    const Face face = Face::trimmed(patch.surface, {patch.square(0.1, 0.9), patch.circular_hole(0.5, 0.5, 0.25)});
    EXPECT_EQ(face.kind(), Face::Kind::trimmed);
    EXPECT_EQ(face.loops().size(), 2u);
    EXPECT_EQ(face.tolerance(), 0.0);
    // The patch stretches u by 2 and v by 3: the square 0.8 x 0.8 and the disc of radius 0.25 by 6 each.
    EXPECT_LT(relative(surface_area(face), 6 * (0.64 - std::numbers::pi * 0.0625)), 1e-13);
}

// Far out in its parameters (u, v near o) a hole's p-curve is rounded to ulps of o, and each cell of the area's
// boundary integral carries noise of that much however short it is. Halving such cells only added noise until the
// quadrature's budget ran out ("cannot reach a relative accuracy of 1e-14", as on a screw thread's face from a
// SolidWorks STEP file); a cell whose noise is as large as its error estimate counts as converged now, and the area
// comes out to the rounding of its parameters.
TEST(TrimmedFace, AreaOfAPatchFarOutInItsParametersIsMeasuredToItsRounding) {
    for (const double o : {1e4, 1e6}) {
        const FlatPatch patch(o);
        const Face face = Face::trimmed(patch.surface, {patch.square(o + 0.1, o + 0.9), patch.circular_hole(o + 0.5, o + 0.5, 0.25)});
        const double area = surface_area(face);
        EXPECT_LT(relative(area, 6 * (0.64 - std::numbers::pi * 0.0625)), 10 * std::numeric_limits<double>::epsilon() * o) << o;
    }
}

TEST(TrimmedFace, RejectsBoundariesThatDoNotBoundARegion) {
    const FlatPatch patch;
    // Clockwise outer loop; counterclockwise hole.
    std::vector<Coedge> backwards = patch.polygon({{0.1, 0.1, 0}, {0.1, 0.9, 0}, {0.9, 0.9, 0}, {0.9, 0.1, 0}});
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {backwards}), "loops");
    std::vector<Coedge> hole = patch.square(0.4, 0.6);
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {patch.square(0.1, 0.9), hole}), "loops");
    // No p-curve; a p-curve that is not 2D; a p-curve off its edge; a p-curve outside the domain.
    std::vector<Coedge> bare = patch.square(0.1, 0.9);
    bare[1].pcurve = nullptr;
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {bare}), "loops");
    std::vector<Coedge> lifted = patch.square(0.1, 0.9);
    lifted[1].pcurve = straight_pcurve({0.9, 0.1, 1e-3}, {0.9, 0.9, 0}, 0, 1);
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {lifted}), "loops");
    std::vector<Coedge> astray = patch.square(0.1, 0.9);
    astray[1].pcurve = straight_pcurve({0.9, 0.1, 0}, {0.95, 0.9, 0}, 0, 1);  // the edge runs at u = 0.9
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {astray}), "loops");
    // ... unless the face's tolerance covers the gap (0.05 in u is 0.1 in space).
    std::vector<Coedge> loose = astray;
    loose[2].pcurve = straight_pcurve({0.95, 0.9, 0}, {0.1, 0.9, 0}, 0, 1);
    EXPECT_NO_THROW(Face::trimmed(patch.surface, {loose}, 0.11));
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {loose}, 0.05), "loops");
    const std::vector<Coedge> outside = patch.square(-0.5, 0.9);
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {outside}), "loops");
    // Open in (u, v): the p-curves of consecutive coedges do not meet.
    std::vector<Coedge> open = patch.square(0.1, 0.9);
    open[1].pcurve = straight_pcurve({0.9, 0.1 + 1e-6, 0}, {0.9, 0.9, 0}, 0, 1);
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {open}, 1e-3), "loops");
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {}), "loops");
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {patch.square(0.1, 0.9)}, -1), "tolerance");
}

// pcurve_gap measures what Face::trimmed holds to the tolerance, where it does: the least tolerance that passes
// (the reader gives a face read from a file at least that: its fit measures at other parameters).
TEST(TrimmedFace, PcurveGapIsTheLeastToleranceThatPasses) {
    const FlatPatch patch;
    std::vector<Coedge> loose = patch.square(0.1, 0.9);
    loose[1].pcurve = straight_pcurve({0.9, 0.1, 0}, {0.95, 0.9, 0}, 0, 1);  // the edge runs at u = 0.9
    loose[2].pcurve = straight_pcurve({0.95, 0.9, 0}, {0.1, 0.9, 0}, 0, 1);
    double gap = 0;
    for (const Coedge& c : loose) gap = std::max(gap, pcurve_gap(patch.surface, c));
    EXPECT_NEAR(gap, 0.1, 1e-12);  // 0.05 in u is 0.1 in space, at the corner (0.9, 0.9)
    EXPECT_NO_THROW(Face::trimmed(patch.surface, {loose}, gap));
    EXPECT_ERROR_NAMING(Face::trimmed(patch.surface, {loose}, 0.999 * gap), "loops");
    EXPECT_LT(pcurve_gap(patch.surface, patch.square(0.1, 0.9)[1]), 1e-15);
    Coedge bare = loose[0];
    bare.pcurve = nullptr;
    EXPECT_ERROR_NAMING(pcurve_gap(patch.surface, bare), "coedge");
}

// Every kind of solid the kernel builds: poles, apexes, seams, planar caps with holes, rational weights.
std::vector<std::pair<std::string, Solid>> kernel_solids() {
    std::vector<std::pair<std::string, Solid>> out;
    out.emplace_back("sphere", sphere(1.3, {1, -2, 0.5}));
    out.emplace_back("cylinder", cylinder(0.7, 2.1, {0, 0, 0}, {1, 1, 0}));
    out.emplace_back("cone", cone(1.2, 0, 1.5));
    out.emplace_back("frustum", cone(1.2, 0.4, 1.5, {0, 1, 0}, {0, -1, 1}));
    out.emplace_back("torus", torus(3, 0.8));
    const Profile square({line_segment({2, 0, 0}, {3, 0, 0}), line_segment({3, 0, 0}, {3, 0, 1}),
                          line_segment({3, 0, 1}, {2, 0, 1}), line_segment({2, 0, 1}, {2, 0, 0})});
    out.emplace_back("revolution 270", revolve(square, {0, 0, 0}, {0, 0, 1}, 270));
    const Profile outer({line_segment({0, 0, 0}, {4, 0, 0}), line_segment({4, 0, 0}, {4, 3, 0}),
                         line_segment({4, 3, 0}, {0, 3, 0}), line_segment({0, 3, 0}, {0, 0, 0})});
    const Profile hole(std::vector<NurbsCurve>{circle(0.8, {2, 1.5, 0}, {0, 0, -1})});
    out.emplace_back("plate with a hole", extrude(outer, {0, 0.2, 1}, 1.5, {hole}));
    return out;
}

TEST(TrimmedFace, KernelSolidsRebuiltTrimmedHaveTheSameMeasures) {
    for (const auto& [name, solid] : kernel_solids()) {
        const Solid trimmed = as_trimmed(solid);
        for (const Face& face : trimmed.faces()) EXPECT_EQ(face.kind(), Face::Kind::trimmed) << name;
        EXPECT_LT(relative(trimmed.volume(), solid.volume()), 1e-12) << name;
        EXPECT_LT(relative(trimmed.area(), solid.area()), 1e-12) << name;
        EXPECT_EQ(trimmed.euler_characteristic(), solid.euler_characteristic()) << name;
        for (std::size_t f = 0; f < solid.faces().size(); ++f)
            EXPECT_LT(relative(surface_area(trimmed.faces()[f]), surface_area(solid.faces()[f])), 1e-12) << name << " face " << f;
    }
}

TEST(TrimmedFace, TablesAndTransformsKeepTrimmedFaces) {
    for (const auto& [name, solid] : kernel_solids()) {
        const Solid trimmed = as_trimmed(solid);
        const std::vector<Face> back = faces_of(tables_of(trimmed.faces()));
        const Solid rebuilt(back);
        ASSERT_EQ(back.size(), trimmed.faces().size());
        for (std::size_t f = 0; f < back.size(); ++f) {
            ASSERT_EQ(back[f].kind(), Face::Kind::trimmed);
            for (std::size_t l = 0; l < back[f].loops().size(); ++l)
                for (std::size_t c = 0; c < back[f].loops()[l].size(); ++c)
                    EXPECT_EQ(back[f].loops()[l][c].pcurve->homogeneous_points(),
                              trimmed.faces()[f].loops()[l][c].pcurve->homogeneous_points());
        }
        EXPECT_EQ(rebuilt.volume(), trimmed.volume()) << name;
        // A rigid motion, a scaling and a reflection (which swaps the parameters and runs the loops backwards).
        const AffineMap motion = AffineMap::rotation({1, 2, 3}, {0.3, -1, 0.2}, 37).after(AffineMap::translation({5, -1, 2}));
        EXPECT_LT(relative(transformed(trimmed, motion).volume(), solid.volume()), 1e-12) << name;
        EXPECT_LT(relative(transformed(trimmed, AffineMap::scaling(2.5, {1, 0, 0})).volume(), 15.625 * solid.volume()), 1e-12) << name;
        const Solid mirrored = transformed(trimmed, AffineMap::mirror({0, 0, 0}, {1, 0.5, 0}));
        EXPECT_LT(relative(mirrored.volume(), solid.volume()), 1e-12) << name;
        EXPECT_LT(relative(mirrored.area(), solid.area()), 1e-12) << name;
    }
}

TEST(TrimmedFace, ToleranceScalesWithTheMapAndSurvivesTables) {
    const FlatPatch patch;
    std::vector<Coedge> loose = patch.square(0.1, 0.9);
    loose[1].pcurve = straight_pcurve({0.9, 0.1, 0}, {0.9 + 1e-4, 0.9, 0}, 0, 1);
    loose[2].pcurve = straight_pcurve({0.9 + 1e-4, 0.9, 0}, {0.1, 0.9, 0}, 0, 1);
    const Face face = Face::trimmed(patch.surface, {loose}, 1e-3);
    EXPECT_EQ(face.tolerance(), 1e-3);
    EXPECT_EQ(faces_of(tables_of(std::vector<Face>{face})).front().tolerance(), 1e-3);
    EXPECT_NEAR(transformed(face, AffineMap::scaling(4, {0, 0, 0})).tolerance(), 4e-3 * std::sqrt(3.0), 1e-15);
}

// The six planar faces of the cube [lo, hi]^3, with their own vertices and shared edges, facing outward or
// (inward) into the cube: the shell of a void.
std::vector<Face> cube_faces(double lo, double hi, bool inward) {
    std::vector<VertexPtr> v;
    for (int k = 0; k < 8; ++k)
        v.push_back(std::make_shared<const Vertex>(Vertex{{k & 1 ? hi : lo, k & 2 ? hi : lo, k & 4 ? hi : lo}}));
    // Each face's corners counterclockwise seen from outside, and its outward normal.
    const std::array<std::pair<std::array<int, 4>, Vec3>, 6> sides{{{{0, 2, 3, 1}, {0, 0, -1}},
                                                                     {{4, 5, 7, 6}, {0, 0, 1}},
                                                                     {{0, 1, 5, 4}, {0, -1, 0}},
                                                                     {{2, 6, 7, 3}, {0, 1, 0}},
                                                                     {{0, 4, 6, 2}, {-1, 0, 0}},
                                                                     {{1, 3, 7, 5}, {1, 0, 0}}}};
    std::map<std::pair<int, int>, EdgePtr> edges;
    std::vector<Face> faces;
    for (auto [corners, normal] : sides) {
        if (inward) std::reverse(corners.begin(), corners.end()), normal = -1.0 * normal;
        std::vector<Coedge> loop;
        for (int k = 0; k < 4; ++k) {
            const int a = corners[static_cast<std::size_t>(k)], b = corners[static_cast<std::size_t>((k + 1) % 4)];
            const auto key = std::minmax(a, b);
            auto& edge = edges[key];
            if (!edge) edge = std::make_shared<const Edge>(Edge{line_segment(v[static_cast<std::size_t>(key.first)]->point, v[static_cast<std::size_t>(key.second)]->point),
                                                              v[static_cast<std::size_t>(key.first)], v[static_cast<std::size_t>(key.second)], false});
            loop.push_back(Coedge{edge, a != key.first});
        }
        // A right-handed frame with that normal: x along the first edge, y = normal x x.
        const Vec3 origin = v[static_cast<std::size_t>(corners[0])]->point;
        const Vec3 x = (v[static_cast<std::size_t>(corners[1])]->point - origin) / (hi - lo);
        faces.push_back(Face::planar(Plane{origin, x, cross(normal, x), normal}, {loop}));
    }
    return faces;
}

// A box [0, 4]^3 with the void [1, 2]^3.
Solid box_with_cubic_void() {
    std::vector<Face> faces = cube_faces(0, 4, false);
    for (Face& f : cube_faces(1, 2, true)) faces.push_back(std::move(f));
    return Solid(std::move(faces));
}

TEST(SolidShells, AVoidIsAnInnerShellWithInwardNormals) {
    const Solid solid = box_with_cubic_void();
    ASSERT_EQ(solid.shells().size(), 2u);
    EXPECT_EQ(solid.shells()[0].size(), 6u);
    EXPECT_EQ(solid.shells()[1].size(), 6u);
    EXPECT_EQ(solid.shells()[0].front(), 0u);  // the outer shell first
    EXPECT_LT(relative(solid.volume(), 64 - 1), 1e-13);
    EXPECT_LT(relative(solid.area(), 6 * 16 + 6 * 1), 1e-13);
    EXPECT_EQ(solid.euler_characteristic(), 4);  // two spheres' worth of shell
    // Pickled and transformed, the void stays a void.
    EXPECT_EQ(Solid(faces_of(tables_of(solid.faces()))).shells().size(), 2u);
    EXPECT_LT(relative(transformed(solid, AffineMap::mirror({0, 0, 0}, {1, 1, 1})).volume(), 63), 1e-13);
}

TEST(SolidShells, RejectsTwoOuterShellsAndVoidsOutsideOrOutward) {
    const Solid a = sphere(1), b = sphere(1, {5, 0, 0});
    std::vector<Face> two = a.faces();
    two.insert(two.end(), b.faces().begin(), b.faces().end());
    EXPECT_ERROR_NAMING(Solid(two), "faces");
    // A void whose normals point out of it is a second outer shell.
    const Solid big = sphere(3), small = sphere(1);
    std::vector<Face> nested = big.faces();
    nested.insert(nested.end(), small.faces().begin(), small.faces().end());
    EXPECT_ERROR_NAMING(Solid(nested), "faces");
    // An inward shell that is not inside the outer one.
    std::vector<Face> apart = cube_faces(0, 1, false);
    for (Face& f : cube_faces(3, 4, true)) apart.push_back(std::move(f));
    EXPECT_ERROR_NAMING(Solid(apart), "faces");
    // Only an inward shell.
    EXPECT_ERROR_NAMING(Solid(cube_faces(0, 1, true)), "faces");
}

}  // namespace
}  // namespace ratbez

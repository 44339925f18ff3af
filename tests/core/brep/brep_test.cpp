#include "ratbez/brep.hpp"

#include <gtest/gtest.h>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/revolve.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

// A unit square face in z = 0 with its own vertices and edges, counterclockwise about +z.
struct Square {
    std::vector<VertexPtr> v;
    std::vector<EdgePtr> e;
    Square() {
        const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        for (const Vec3& q : p) v.push_back(std::make_shared<const Vertex>(Vertex{q}));
        for (int i = 0; i < 4; ++i)
            e.push_back(std::make_shared<const Edge>(Edge{line_segment(p[i], p[(i + 1) % 4]), v[i], v[(i + 1) % 4], false}));
    }
    std::vector<Coedge> loop(bool reversed) const {
        std::vector<Coedge> l;
        if (!reversed)
            for (int i = 0; i < 4; ++i) l.push_back({e[i], false});
        else
            for (int i = 3; i >= 0; --i) l.push_back({e[i], true});
        return l;
    }
};

const Plane xy{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(Brep, PlanarFacePatchIsParameterisedByPlaneCoordinatesAlongTheNormal) {
    const Square s;
    const Face f = Face::planar(xy, {s.loop(false)});
    EXPECT_EQ(f.kind(), Face::Kind::planar);
    EXPECT_EQ(f.point(0.25, 0.75), (Vec3{0.25, 0.75, 0}));
    EXPECT_EQ(f.normal(0.5, 0.5), (Vec3{0, 0, 1}));
    EXPECT_EQ(f.surface().domain_u().min, 0.0);
    EXPECT_EQ(f.surface().domain_u().max, 1.0);
}

TEST(Brep, PlanarFaceRejectsWrongLoops) {
    const Square s;
    EXPECT_ERROR_NAMING(Face::planar(xy, {s.loop(true)}), "loops");  // clockwise outer loop
    EXPECT_ERROR_NAMING(Face::planar(xy, {}), "loops");
    EXPECT_ERROR_NAMING(Face::planar(Plane{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {s.loop(false)}), "loops");  // off plane
    std::vector<Coedge> broken = s.loop(false);
    std::swap(broken[1], broken[2]);
    EXPECT_ERROR_NAMING(Face::planar(xy, {broken}), "loops");
    EXPECT_ERROR_NAMING(Face::planar(Plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}}, {s.loop(false)}), "plane");
    EXPECT_ERROR_NAMING(Face::planar(Plane{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 2}}, {s.loop(false)}), "plane");
}

// A keyboard case read from a file (Bastardkb/charybdis) has a sliver triangle of area 0.03 whose curve ends 0.0097
// short of its vertex, within the file's tolerance, on a plane whose origin lies 30 mm away. Summed piece by piece
// from that origin, the open loop's area was off by the gap times the distance (-0.086), and the face was refused
// as clockwise. The loop is closed by straight bridges across the gaps, wherever the plane's origin lies.
TEST(Brep, APlanarLoopWithGapsWithinItsToleranceHasItsAreaWhereverThePlanesOriginLies) {
    // A thin triangle A B C (area 0.032) whose side C -> A ends 0.01 beside A, across the side.
    const Vec3 a{0, 0, 0}, b{1.6, 0, 0}, c{0.8, 0.04, 0};
    const VertexPtr va = std::make_shared<const Vertex>(Vertex{a}), vb = std::make_shared<const Vertex>(Vertex{b}),
                    vc = std::make_shared<const Vertex>(Vertex{c});
    for (const double gap : {0.01, -0.01}) {
        const std::vector<Coedge> loop{
            {std::make_shared<const Edge>(Edge{line_segment(a, b), va, vb, false}), false},
            {std::make_shared<const Edge>(Edge{line_segment(b, c), vb, vc, false}), false},
            {std::make_shared<const Edge>(Edge{line_segment(c, a + Vec3{0, gap, 0}), vc, va, false}), false}};
        for (const double far : {-30.0, 30.0}) {
            const Plane plane{{far, far, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            const Face face = Face::planar(plane, {loop}, 0.02);
            EXPECT_EQ(face.kind(), Face::Kind::planar) << gap << " " << far;
        }
    }
}

TEST(Brep, SurfaceFaceRejectsEdgesThatDoNotMatchItsSides) {
    const Solid cyl = cylinder(1, 2);
    const Face& lateral = cyl.faces()[0];
    auto sides = lateral.sides();
    EXPECT_NO_THROW(Face::from_surface(lateral.surface(), sides));
    // The top circle on the bottom side.
    auto wrong = sides;
    wrong[0] = Coedge{sides[2].edge, false};
    EXPECT_ERROR_NAMING(Face::from_surface(lateral.surface(), wrong), "sides");
    // A seam flagged degenerate.
    auto degenerate = sides;
    auto fake = std::make_shared<const Edge>(Edge{sides[1].edge->curve, sides[1].edge->start, sides[1].edge->end, true});
    degenerate[1] = Coedge{fake, false};
    degenerate[3] = Coedge{fake, true};
    EXPECT_ERROR_NAMING(Face::from_surface(lateral.surface(), degenerate), "sides");
    // Right geometry, but the seam's own vertices replaced: the sides no longer meet.
    auto loose = sides;
    auto copy = std::make_shared<const Edge>(Edge{sides[1].edge->curve, std::make_shared<const Vertex>(*sides[1].edge->start),
                                                  sides[1].edge->end, false});
    loose[1] = Coedge{copy, false};
    EXPECT_ERROR_NAMING(Face::from_surface(lateral.surface(), loose), "sides");
}

// The faces of a solid turned inside out: every loop reversed and every surface transposed (S_v x S_u
// is the inward normal), on the same edges, so the shell stays closed and coherent.
std::vector<Face> inside_out(const Solid& solid) {
    std::vector<Face> flipped;
    for (const Face& f : solid.faces()) {
        if (f.kind() == Face::Kind::planar) {
            const Plane& p = f.plane();
            std::vector<std::vector<Coedge>> loops;
            for (const auto& original : f.loops()) {
                std::vector<Coedge>& loop = loops.emplace_back();
                for (auto it = original.rbegin(); it != original.rend(); ++it) loop.push_back({it->edge, !it->reversed});
            }
            flipped.push_back(Face::planar(Plane{p.origin, p.y_axis, p.x_axis, -p.normal}, loops));
        } else {
            const NurbsSurface& s = f.surface();
            std::vector<Vec4> net;
            for (int j = 0; j < s.columns(); ++j)
                for (int i = 0; i < s.rows(); ++i) net.push_back(s.homogeneous_point(i, j));
            const NurbsSurface t = NurbsSurface::from_homogeneous(s.degree_v(), s.degree_u(), s.knots_v(), s.knots_u(), net);
            const auto& sd = f.sides();
            // Side mapping under the transpose: new v_min = old u_min, new u_max = old v_max, etc.
            flipped.push_back(Face::from_surface(t, {Coedge{sd[3].edge, !sd[3].reversed}, Coedge{sd[2].edge, !sd[2].reversed},
                                                     Coedge{sd[1].edge, !sd[1].reversed}, Coedge{sd[0].edge, !sd[0].reversed}}));
        }
    }
    return flipped;
}

TEST(Brep, SolidRejectsOpenAndInsideOutShells) {
    const Solid cyl = cylinder(1, 2);
    EXPECT_ERROR_NAMING(Solid({cyl.faces()[0], cyl.faces()[1]}), "faces");          // top cap missing
    EXPECT_ERROR_NAMING(Solid({cyl.faces()[0], cyl.faces()[1], cyl.faces()[1], cyl.faces()[2]}), "faces");  // used 3 times
    EXPECT_ERROR_NAMING(Solid(std::vector<Face>{}), "faces");
    // Closed, but inside out: a unit cube (polynomial faces), a torus (rational, weights within the
    // certificate, so the orientation check integrates it span by span) and a half-revolved polygon whose
    // edges carry weights 1e-3 and 1e3 (the check must cut its faces into certified cells first).
    const Profile square({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {1, 1, 0}),
                          line_segment({1, 1, 0}, {0, 1, 0}), line_segment({0, 1, 0}, {0, 0, 0})});
    const Solid cube = extrude(square, {0, 0, 1}, 1.0);
    EXPECT_NEAR(cube.volume(), 1.0, 1e-14);
    EXPECT_NEAR(cube.area(), 6.0, 1e-13);
    const std::vector<Vec3> polygon{{1, 0, 0}, {3, 0, 0.5}, {2.5, 0, 2}};
    std::vector<NurbsCurve> weighted;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        weighted.push_back(NurbsCurve::from_bezier(BezierCurve({polygon[i], polygon[(i + 1) % 3]}, {1e-3, 1e3})));
    for (const Solid& solid : {cube, torus(3, 1, {1, 2, 3}, {1, 1, 0}), revolve(Profile(weighted), {0, 0, 0}, {0, 0, 1}, 180)}) {
        EXPECT_GT(solid.volume(), 0);
        const std::string message = test::error_message([&] { Solid{inside_out(solid)}; });
        EXPECT_NE(message.find("inward"), std::string::npos) << message;
    }
}

TEST(Brep, EdgesVerticesAndBoundingBox) {
    const Solid cone_solid = cone(2, 0, 3, {1, 1, 1});
    EXPECT_EQ(cone_solid.edges().size(), 3u);  // seam, base circle, degenerate apex
    EXPECT_EQ(cone_solid.vertices().size(), 2u);
    EXPECT_EQ(cone_solid.euler_characteristic(), 2);
    const Box box = sphere(2, {1, 2, 3}).bounding_box();
    EXPECT_EQ(box.min, (Vec3{-1, 0, 1}));
    EXPECT_EQ(box.max, (Vec3{3, 4, 5}));
    const Box cyl = cylinder(1, 2).bounding_box();
    EXPECT_EQ(cyl.min, (Vec3{-1, -1, 0}));
    EXPECT_EQ(cyl.max, (Vec3{1, 1, 2}));
    EXPECT_NEAR(cyl.diagonal(), std::sqrt(12.0), 1e-15);
}

}  // namespace
}  // namespace ratbez

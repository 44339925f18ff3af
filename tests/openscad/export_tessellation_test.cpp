// export_tessellation: the mesh as written (rounded to the fewest decimals that pass) is within the
// tolerance and CGAL-clean, read back from the file; the .scad header states what was measured.
#include "ratbez/export/export.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "ratbez/convex_hull.hpp"
#include "ratbez/deviation.hpp"
#include "temp_directory_test_support.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::exporter {
namespace {

namespace fs = std::filesystem;

class ExportTessellation : public test::TempDirectoryTest {
protected:
    ExportTessellation() : TempDirectoryTest("export_tessellation") {}
    static std::string read(const std::string& path) { return test::read_file(path); }
};

// An OFF file as a reader gets it.
Mesh read_off(const std::string& text) {
    std::istringstream in(text);
    std::string magic;
    std::size_t vertices = 0, faces = 0, edges = 0;
    in >> magic >> vertices >> faces >> edges;
    Mesh mesh;
    for (std::size_t i = 0; i < vertices; ++i) {
        Vec3 p;
        in >> p.x >> p.y >> p.z;
        mesh.vertices.push_back(p);
    }
    for (std::size_t i = 0; i < faces; ++i) {
        int n = 0;
        std::array<std::uint32_t, 3> t{};
        in >> n >> t[0] >> t[1] >> t[2];
        mesh.triangles.push_back(t);
    }
    return mesh;
}

TEST_F(ExportTessellation, WrittenCoordinatesAreRoundedYetWithinToleranceAndClean) {
    const Solid ball = sphere(10, {1, 2, 3});
    const double tolerance = 0.01;
    const Mesh mesh = tessellate(ball, tolerance);
    ExportOptions options;
    options.checks = tessellation_checks(ball, mesh, tolerance);
    const WrittenMesh written = export_tessellation(ball, mesh, tolerance, path("ball.off"), options);
    ASSERT_TRUE(written.decimals.has_value());
    EXPECT_LE(*written.decimals, 6);  // far fewer than the 17 significant digits of an exact double
    const Mesh read_back = read_off(read(path("ball.off")));
    ASSERT_EQ(read_back.vertices.size(), written.mesh.vertices.size());
    for (std::size_t i = 0; i < read_back.vertices.size(); ++i) {
        EXPECT_EQ(read_back.vertices[i].x, written.mesh.vertices[i].x);
        EXPECT_EQ(read_back.vertices[i].y, written.mesh.vertices[i].y);
        EXPECT_EQ(read_back.vertices[i].z, written.mesh.vertices[i].z);
    }
    // The same triangles, except where rounding lifted a vertex above its neighbours: a ball stays convex
    // (issue 28), the few edges that turned reflex flipped back.
    EXPECT_EQ(read_back.triangles, written.mesh.triangles);
    EXPECT_EQ(read_back.triangles.size(), mesh.triangles.size());
    EXPECT_TRUE(is_convex_mesh(read_back));
    EXPECT_LE(max_deviation(ball, read_back), tolerance);
    EXPECT_TRUE(check_mesh(read_back, options.checks).ok());
    // One decimal fewer than written must fail a check, or the exporter would have taken it.
    if (*written.decimals > 0) {
        Mesh coarser = rounded_mesh(mesh, *written.decimals - 1);
        if (!is_convex_mesh(coarser)) coarser = convex_hull(coarser);
        EXPECT_FALSE(max_deviation(ball, coarser) <= tolerance && check_mesh(coarser, options.checks).ok());
    }
}

// A prism whose cap has a notch reaching within 2e-6 of its opposite side, turned by 45 degrees and moved off the
// origin: the cap's triangle under the notch is a sliver 2e-6 high. Coordinates rounded to a grid coarser than that
// can flatten it while every check passes: here 2 decimals, within the tolerance and CGAL-clean, were written (a
// KiCad capacitor's sliver 1.2e-6 high left 2.6e-16 high at 5 decimals; OpenSCAD then failed in
// CGAL_Nef_polyhedron3() on `use` of the library). The written mesh keeps every triangle.
TEST_F(ExportTessellation, RoundingKeepsEverySliverATriangle) {
    const double turn = std::numbers::pi / 4;
    const auto placed = [&](double x, double y) {
        return Vec3{0.1 + x * std::cos(turn) - y * std::sin(turn), 0.7 + x * std::sin(turn) + y * std::cos(turn), 0};
    };
    const std::vector<Vec3> corners{placed(0, 0), placed(4, 0), placed(4, 1), placed(2, 2e-6), placed(0, 1)};
    std::vector<NurbsCurve> sides;
    for (std::size_t k = 0; k < corners.size(); ++k) sides.push_back(line_segment(corners[k], corners[(k + 1) % corners.size()]));
    const Solid prism = extrude(Profile(sides), {0, 0, 1}, 1.0);
    const double tolerance = 0.01;
    const Mesh mesh = tessellate(prism, tolerance);
    ExportOptions options;
    options.checks = tessellation_checks(prism, mesh, tolerance);
    const WrittenMesh written = export_tessellation(prism, mesh, tolerance, path("notch.off"), options);
    const Mesh read_back = read_off(read(path("notch.off")));
    ASSERT_EQ(read_back.triangles, mesh.triangles);
    double thinnest = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
        const auto area_vector = [&](const Mesh& m) {
            return cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
        };
        const Vec3 exact = area_vector(mesh), kept = area_vector(read_back);
        thinnest = std::min(thinnest, norm(exact));
        EXPECT_GE(dot(exact, kept), 0.5 * dot(exact, exact)) << "a triangle flattened or turned by rounding to " << *written.decimals << " decimals";
    }
    EXPECT_LT(thinnest, 1e-5);  // the sliver is there
}

TEST_F(ExportTessellation, ScadHeaderStatesSourceToleranceDeviationCountsBoxAndVolumes) {
    const Solid ball = sphere(2);
    const Mesh mesh = tessellate(ball, 0.001);
    ExportOptions options;
    options.openscad.module_name = "ball";
    options.source = "test\nball(); // injected";
    options.checks = tessellation_checks(ball, mesh, 0.001);
    const WrittenMesh written = export_tessellation(ball, mesh, 0.001, path("ball.scad"), options);
    const std::string text = read(path("ball.scad"));
    const std::string head = text.substr(0, text.find("module ball() {"));
    std::istringstream lines(head);
    for (std::string line; std::getline(lines, line);) EXPECT_EQ(line.rfind("// ", 0), 0u) << line;
    EXPECT_EQ(head.rfind("// ratbez ", 0), 0u) << head;
    EXPECT_NE(head.find("// source: test\\nball(); // injected\n"), std::string::npos) << head;
    EXPECT_NE(head.find("// tolerance: 0.001; measured maximum deviation: "), std::string::npos) << head;
    EXPECT_NE(head.find("// " + std::to_string(mesh.triangles.size()) + " triangles, " +
                        std::to_string(mesh.vertices.size()) + " vertices; coordinates rounded to " +
                        std::to_string(*written.decimals) + " decimals\n"),
              std::string::npos)
        << head;
    // The mesh straddles the sphere: its vertices lie up to the tolerance outside it, the poles on the axis.
    const std::size_t box_at = head.find("// bounding box: [");
    ASSERT_NE(box_at, std::string::npos) << head;
    std::array<double, 6> box{};
    ASSERT_EQ(std::sscanf(head.c_str() + box_at, "// bounding box: [%lf, %lf, %lf] .. [%lf, %lf, %lf]", &box[0], &box[1],
                          &box[2], &box[3], &box[4], &box[5]),
              6)
        << head;
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(std::abs(-box[k] - 2), 0.001) << head;
        EXPECT_LE(std::abs(box[k + 3] - 2), 0.001) << head;
    }
    EXPECT_GE(box[5], 2.0) << head;  // a pole: moved outwards along the axis
    EXPECT_LE(box[2], -2.0) << head;
    EXPECT_NE(head.find("// volume: exact 33.51032164, mesh "), std::string::npos) << head;  // 4/3 pi 2^3
    EXPECT_EQ(text.substr(text.size() - 10), "}\nball();\n");
}

TEST_F(ExportTessellation, BadModuleNameIsRefusedBeforeAnyWork) {
    const Solid ball = sphere(1);
    const Mesh mesh = tessellate(ball, 0.01);
    ExportOptions options;
    options.openscad.module_name = "x\ncube(1);";
    try {
        export_tessellation(ball, mesh, 0.01, path("x.scad"), options);
        FAIL() << "expected ratbez::Error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "module_name: 'x\\ncube(1);' is not an OpenSCAD identifier (letters, digits, _; not starting with a digit)");
    }
    EXPECT_FALSE(fs::exists(path("x.scad")));
    // A built-in would shadow OpenSCAD's own module for every user of the library (issue 27).
    options.openscad.module_name = "cylinder";
    try {
        export_tessellation(ball, mesh, 0.01, path("x.scad"), options);
        FAIL() << "expected ratbez::Error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("module_name: 'cylinder' is an OpenSCAD built-in or keyword", 0), 0u) << e.what();
    }
    EXPECT_FALSE(fs::exists(path("x.scad")));
}

// A shell whose wall (0.02) is thinner than the tolerance (0.1): the half of a torus tube, 1 and 1.02 round,
// its two walls sampled each for its own curvature, their meshes straddling each one by up to the tolerance,
// cross each other. The export's tessellation meshes it again at half the tolerance, where they do not: within
// the tolerance still, and an export instead of a refusal (a Voron carriage's bore poked through a plane so).
TEST_F(ExportTessellation, AMeshThatIntersectsItselfIsMadeAgainFiner) {
    const Vec3 centre{3, 0, 0};
    const NurbsCurve outer = arc(1.02, -90, 90, centre), inner = arc(1.0, -90, 90, centre).reversed();
    const Solid tube = revolve(Profile({outer, line_segment(outer.end_point(), inner.start_point()), inner,
                                        line_segment(inner.end_point(), outer.start_point())}),
                               {0, 0, 0}, {0, 1, 0});
    const double tolerance = 0.1;
    ASSERT_EQ(check_mesh(tessellate(tube, tolerance)).self_intersection_free, false);
    TessellationOptions options;
    options.tolerance = tolerance;
    const Mesh mesh = tessellate_for_export(tube, options);
    EXPECT_EQ(check_mesh(mesh).self_intersection_free, true);
    EXPECT_LE(max_deviation(tube, mesh), tolerance);
    ExportOptions exported;
    exported.checks = tessellation_checks(tube, mesh, tolerance);
    EXPECT_LE(export_tessellation(tube, mesh, tolerance, path("tube.scad"), exported).max_deviation, tolerance);
    // Asked not to test for self-intersection (--skip-self-intersection-check), it is not made again.
    MeshCheckOptions skip;
    skip.check_self_intersections = false;
    EXPECT_EQ(tessellate_for_export(tube, options, skip).triangles.size(), tessellate(tube, tolerance).triangles.size());
}

// A flat ring `width` wide at the foot of a wall of radius 10, the floor curving up from it (the x-z profile,
// revolved about z): the ring's inner circle is sampled for the wall, its samples moved out across the ring by
// the wall's straddling offsets, the outer one for the floor.
Solid ring_at_a_wall(double width) {
    return revolve(Profile::from_beziers({BezierCurve({{10, 0, 0}, {10 + width, 0, 0}}),
                                          BezierCurve({{10 + width, 0, 0}, {16, 0, 0}, {16, 0, 6}}, {1, 0.7, 1}),
                                          BezierCurve({{16, 0, 6}, {16, 0, 8}}), BezierCurve({{16, 0, 8}, {10, 0, 8}}),
                                          BezierCurve({{10, 0, 8}, {10, 0, 0}})}));
}

// The ring narrower than those offsets and chords: its triangles folded back over the wall's and the floor's,
// and the tessellation handed out a mesh that intersects itself (14 of these 20 cases). Its edges are now
// sampled finer, on their curves, until no triangle folds.
TEST(Tessellation, AFlatRingNarrowerThanTheSamplesBesideItMeshesUnfolded) {
    for (double width : {0.001, 0.004, 0.02, 0.1, 0.5}) {
        const Solid solid = ring_at_a_wall(width);
        for (double tolerance : {0.03, 0.1, 0.3, 1.0}) {
            const Mesh mesh = tessellate(solid, tolerance);
            const MeshReport report = check_mesh(mesh);
            EXPECT_TRUE(report.ok()) << "width " << width << ", tolerance " << tolerance << ": " << testing::PrintToString(report.problems);
            EXPECT_LE(max_deviation(solid, mesh), tolerance) << "width " << width << ", tolerance " << tolerance;
        }
    }
}

// Of several solids in one file, a refusal says which (a Voron LED mount's second solid was refused unnamed).
TEST_F(ExportTessellation, ARefusalOfOneOfSeveralSolidsNamesIt) {
    const Solid ball = sphere(1), other = sphere(1, {3, 0, 0});
    const Mesh good = tessellate(ball, 0.01);
    Mesh open = tessellate(other, 0.01);
    open.triangles.pop_back();
    for (const char* file : {"parts.scad", "parts.stl", "parts.3mf"}) {
        std::vector<LibraryPart> parts(2);
        parts[0] = {"ball", &ball, &good, 0.01, tessellation_checks(ball, good, 0.01), std::nullopt};
        parts[1] = {"Nut, M3", &other, &open, 0.01, tessellation_checks(other, open, 0.01), std::nullopt};
        ExportOptions options;
        options.openscad.module_name = "parts";
        if (std::string(file) == "parts.scad") parts[1].module_name = "nut";
        try {
            export_library(parts, path(file), options);
            ADD_FAILURE() << file << ": expected ratbez::Error";
        } catch (const PartRefused& e) {  // which part, by its index, for a caller that leaves it out (the command)
            EXPECT_EQ(e.part(), 1u) << file;
            EXPECT_EQ(e.argument(), "mesh") << e.what();
            EXPECT_EQ(e.reason().rfind("'" + parts[1].module_name + "': ", 0), 0u) << e.what();
        }
        EXPECT_FALSE(std::filesystem::exists(path(file))) << file;
    }
}

// A binary STL as a reader gets it: three float32 vertices per triangle, widened to double.
std::vector<std::array<Vec3, 3>> read_binary_stl(const std::string& bytes) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    EXPECT_EQ(bytes.size(), 84 + 50 * std::size_t{count});
    std::vector<std::array<Vec3, 3>> triangles(count);
    for (std::size_t t = 0; t < count; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            float xyz[3];
            std::memcpy(xyz, bytes.data() + 84 + 50 * t + 12 + 12 * k, 12);
            triangles[t][k] = {xyz[0], xyz[1], xyz[2]};
        }
    return triangles;
}

TEST_F(ExportTessellation, ImportStlWritesTheMeshBesideAndAModuleThatImportsIt) {
    const Solid ball = sphere(10, {1, 2, 3});
    const double tolerance = 0.01;
    const Mesh mesh = tessellate(ball, tolerance);
    ExportOptions options;
    options.openscad.module_name = "ball";
    options.import_stl = true;
    options.checks = tessellation_checks(ball, mesh, tolerance);
    const WrittenMesh written = export_tessellation(ball, mesh, tolerance, path("ball.scad"), options);
    EXPECT_EQ(written.mesh.vertices, float32_mesh(mesh).vertices);
    EXPECT_LE(written.max_deviation, tolerance);
    const std::string text = read(path("ball.scad"));
    EXPECT_NE(text.find("; coordinates float32 (binary STL)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\nmodule ball() {\nimport(\"ball.stl\", convexity=10);\n}\nball();\n"), std::string::npos) << text;
    // The STL holds the mesh as checked: the float32 coordinates, triangle by triangle.
    const auto triangles = read_binary_stl(read(path("ball.stl")));
    ASSERT_EQ(triangles.size(), mesh.triangles.size());
    for (std::size_t t = 0; t < triangles.size(); t += 97)
        for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(triangles[t][k], written.mesh.vertices[mesh.triangles[t][k]]);
}

// STL has no vertex table: its readers join corners by their float32 coordinates. A vertex 1e-7 from another at
// 100 (a file's tiny edge) is the same vertex to them; the triangles between the two collapse and the mesh they
// read is closed. It is written so, not refused for "duplicate vertices".
TEST_F(ExportTessellation, BinaryStlWeldsTheVerticesFloat32BringsTogether) {
    Mesh mesh;
    const Vec3 at{100, 100, 100};
    mesh.vertices = {at, at + Vec3{1, 0, 0}, at + Vec3{0, 1, 0}, at + Vec3{0, 0, 1}, at + Vec3{1 - 1e-7, 0, 0}};
    mesh.triangles = {{0, 2, 4}, {4, 2, 1}, {0, 4, 3}, {4, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    ASSERT_EQ(static_cast<float>(mesh.vertices[4].x), static_cast<float>(mesh.vertices[1].x));
    export_mesh(mesh, path("tiny_edge.stl"));
    const auto triangles = read_binary_stl(read(path("tiny_edge.stl")));
    ASSERT_EQ(triangles.size(), 4u);  // the tetrahedron's: each corner one of its own four
    for (const auto& corners : triangles)
        for (const Vec3& p : corners)
            EXPECT_TRUE(p == mesh.vertices[0] || p == mesh.vertices[1] || p == mesh.vertices[2] || p == mesh.vertices[3]) << p.x;
}

TEST_F(ExportTessellation, BinaryStlRefusesAMeshItsFloat32CoordinatesMoveBeyondTheTolerance) {
    // Far from the origin float32 coordinates are 1/16 apart: the unit sphere's vertices move up to 0.03.
    const Solid far = sphere(1, {1e6, 0, 0});
    const double tolerance = 1e-3;
    const Mesh mesh = tessellate(far, tolerance);
    ExportOptions options;
    options.checks = tessellation_checks(far, mesh, tolerance);
    for (const char* name : {"far.stl", "far_import.scad"}) {
        options.import_stl = std::string(name).ends_with(".scad");
        try {
            export_tessellation(far, mesh, tolerance, path(name), options);
            FAIL() << name << ": expected ratbez::Error";
        } catch (const Error& e) {
            EXPECT_EQ(e.argument(), "mesh");
            EXPECT_NE(e.reason().find("float32"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(fs::is_empty(path("")));
    }
    // ASCII STL keeps the digits it needs.
    options.import_stl = false;
    options.binary_stl = false;
    EXPECT_LE(export_tessellation(far, mesh, tolerance, path("far.stl"), options).max_deviation, tolerance);
}

}  // namespace
}  // namespace ratbez::exporter

// 3MF through lib3mf: the package read back by lib3mf (what OpenSCAD's import() and slicers get) holds each
// object with its name, the version in its metadata, and coordinates as lib3mf writes them (float32 cut to
// 6 decimals); exports check THOSE coordinates and refuse a mesh they move beyond the tolerance.
#include "ratbez/export/three_mf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/export/export.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/tessellate.hpp"
#include "temp_directory_test_support.hpp"

namespace ratbez::exporter {
namespace {

namespace fs = std::filesystem;

class ThreeMf : public test::TempDirectoryTest {
protected:
    ThreeMf() : TempDirectoryTest("three_mf") {}
};

Mesh tetrahedron(const Vec3& corner = {0, 0, 0}) {
    Mesh mesh;
    mesh.vertices = {corner, corner + Vec3{1, 0, 0}, corner + Vec3{0, 1, 0}, corner + Vec3{0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    return mesh;
}

std::string metadata_value(const std::string& package, const std::string& name) {
    for (const auto& [key, value] : read_three_mf_metadata(package))
        if (key == name) return value;
    return "(none)";
}

TEST(WriteThreeMf, ObjectsReadBackInOrderWithNamesAndTheCoordinatesLib3mfWrites) {
    Mesh a = tetrahedron();
    a.vertices[1] = {0.1234567, -1.0 / 3, 9.999999e-7};
    const Mesh b = tetrahedron({5, 0, 0});
    const std::string package =
        write_three_mf({{&a, "peg <&\"'> \xc3\xbc", Color{1, 0, 0, 0.5}}, {&b, "knob", std::nullopt}}, {{"Application", "test 1"}});
    ASSERT_GT(package.size(), 4u);
    EXPECT_EQ(package.substr(0, 2), "PK");  // a ZIP package
    const std::vector<ThreeMfMesh> read = read_three_mf(package);
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(read[0].name, "peg <&\"'> \xc3\xbc");
    EXPECT_EQ(read[1].name, "knob");
    EXPECT_EQ(read[0].mesh.triangles, a.triangles);
    EXPECT_EQ(read[1].mesh.vertices, b.vertices);  // small whole numbers survive exactly
    // lib3mf 1.8.1 prints a float32 with 6 decimals, cut rather than rounded: 0.1234567 -> "0.123456",
    // -1/3 -> "-0.333333", 9.999999e-7 -> "0". A reader gets the float32 nearest those decimals.
    EXPECT_EQ(read[0].mesh.vertices[1].x, static_cast<double>(0.123456f));
    EXPECT_EQ(read[0].mesh.vertices[1].y, static_cast<double>(-0.333333f));
    EXPECT_EQ(read[0].mesh.vertices[1].z, 0.0);
    EXPECT_EQ(metadata_value(package, "Application"), "test 1");
    ASSERT_TRUE(read[0].color.has_value());
    EXPECT_EQ(read[0].color->red, 1.0);
    EXPECT_EQ(read[0].color->green, 0.0);
    EXPECT_EQ(read[0].color->alpha, 128 / 255.0);  // 0.5 as a byte
    EXPECT_FALSE(read[1].color.has_value());
}

TEST(WriteThreeMf, RefusesCoordinatesBeyondLib3mfsRangeAndNamesTheMesh) {
    const Mesh far = tetrahedron({2e9, 0, 0});
    try {
        write_three_mf({{&far, "far", std::nullopt}}, {});
        FAIL() << "expected ratbez::Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "mesh");
        EXPECT_NE(e.reason().find("3MF's coordinate range"), std::string::npos) << e.what();
    }
    try {
        read_three_mf("not a zip");
        FAIL() << "expected ratbez::Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "3mf");
    }
}

TEST_F(ThreeMf, ExportTessellationChecksTheCoordinatesAsReadBackAndStatesTheVersion) {
    const Solid ball = sphere(10, {1, 2, 3});
    const double tolerance = 0.01;
    const Mesh mesh = tessellate(ball, tolerance);
    ExportOptions options;
    options.openscad.module_name = "ball";
    options.openscad.color = Color{0, 0.5, 1, 1};
    options.source = "test";
    options.checks = tessellation_checks(ball, mesh, tolerance);
    const WrittenMesh written = export_tessellation(ball, mesh, tolerance, path("ball.3mf"), options);
    const std::string package = test::read_file(path("ball.3mf"));
    const std::vector<ThreeMfMesh> read = read_three_mf(package);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(read[0].name, "ball");
    EXPECT_EQ(read[0].mesh.triangles, mesh.triangles);  // the same triangle count and order
    EXPECT_EQ(read[0].mesh.vertices, written.mesh.vertices);  // what was checked is what is in the file
    EXPECT_NE(written.mesh.vertices, float32_mesh(mesh).vertices);  // not float32 alone: cut to 6 decimals
    EXPECT_FALSE(written.decimals.has_value());
    EXPECT_LE(written.max_deviation, tolerance);
    EXPECT_EQ(written.max_deviation, max_deviation(ball, read[0].mesh));
    EXPECT_TRUE(check_mesh(read[0].mesh, options.checks).ok());
    EXPECT_EQ(metadata_value(package, "Application").rfind("ratbez 0.", 0), 0u);
    EXPECT_EQ(metadata_value(package, "Title"), "ball");
    const std::string description = metadata_value(package, "Description");
    EXPECT_NE(description.find("a 3MF file of 1 solid\nsource: test\nobject ball:\n  tolerance: 0.01; measured maximum deviation: "),
              std::string::npos)
        << description;
    EXPECT_NE(description.find(std::to_string(mesh.triangles.size()) + " triangles"), std::string::npos) << description;
    EXPECT_NE(description.find("coordinates float32 cut to 6 decimals (3MF as lib3mf writes it)"), std::string::npos) << description;
    EXPECT_EQ(std::distance(fs::directory_iterator(directory_), fs::directory_iterator()), 1);  // no temporary left
}

TEST_F(ThreeMf, RefusesAMeshLib3mfsCoordinatesMoveBeyondTheToleranceNamingThe3mfFormat) {
    // Two cases: 6 decimals cut too coarse for a 0.006 mm ball at 1e-6, and float32 too coarse far away.
    struct Case {
        Solid solid;
        double tolerance;
    };
    for (const Case& c : {Case{sphere(0.003), 1e-6}, Case{sphere(1, {1e6, 0, 0}), 1e-3}}) {
        const Mesh mesh = tessellate(c.solid, c.tolerance);
        ExportOptions options;
        options.openscad.module_name = "small";
        options.checks = tessellation_checks(c.solid, mesh, c.tolerance);
        try {
            export_tessellation(c.solid, mesh, c.tolerance, path("small.3mf"), options);
            FAIL() << "expected ratbez::Error";
        } catch (const Error& e) {
            EXPECT_EQ(e.argument(), "mesh");
            EXPECT_EQ(e.reason().rfind("3MF, as lib3mf 1.8 writes it, stores float32 coordinates cut to 6 decimals, which leave this mesh ", 0), 0u)
                << e.what();
            EXPECT_NE(e.reason().find("write .scad, .off or ASCII STL text, or use a coarser tolerance"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(fs::is_empty(directory_));
        // The text formats keep the digits they need.
        EXPECT_LE(export_tessellation(c.solid, mesh, c.tolerance, path("small.off"), options).max_deviation, c.tolerance);
        fs::remove(path("small.off"));
    }
}

TEST_F(ThreeMf, BinaryStlRefusalNamesTheFileThatStoresFloat32) {
    const Solid far = sphere(1, {1e6, 0, 0});
    const Mesh mesh = tessellate(far, 1e-3);
    ExportOptions options;
    options.openscad.module_name = "far";
    options.checks = tessellation_checks(far, mesh, 1e-3);
    for (const bool import_stl : {false, true}) {
        options.import_stl = import_stl;
        try {
            export_tessellation(far, mesh, 1e-3, path(import_stl ? "far.scad" : "far.stl"), options);
            FAIL() << "expected ratbez::Error";
        } catch (const Error& e) {
            EXPECT_EQ(e.reason().rfind(import_stl ? "the binary STL beside the .scad (import_stl) stores float32 coordinates, "
                                                  : "binary STL stores float32 coordinates, ",
                                       0),
                      0u)
                << e.what();
        }
    }
}

TEST_F(ThreeMf, SeveralSolidsGiveOneObjectEachWithTheirOwnChecks) {
    const Solid peg = cylinder(2, 10), knob = sphere(3, {0, 0, 10});
    const Mesh peg_mesh = tessellate(peg, 0.01), knob_mesh = tessellate(knob, 0.02);
    std::vector<LibraryPart> parts = {
        {"peg", &peg, &peg_mesh, 0.01, tessellation_checks(peg, peg_mesh, 0.01), std::nullopt},
        {"the knob", &knob, &knob_mesh, 0.02, tessellation_checks(knob, knob_mesh, 0.02), Color{1, 0, 0, 1}}};
    ExportOptions options;
    const std::vector<WrittenMesh> written = export_library(parts, path("parts.3mf"), options);
    ASSERT_EQ(written.size(), 2u);
    const std::string package = test::read_file(path("parts.3mf"));
    const std::vector<ThreeMfMesh> read = read_three_mf(package);
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(read[0].name, "peg");
    EXPECT_EQ(read[1].name, "the knob");  // 3MF names are text, not identifiers
    EXPECT_EQ(read[0].mesh.vertices, written[0].mesh.vertices);
    EXPECT_EQ(read[1].mesh.triangles, knob_mesh.triangles);
    EXPECT_LE(written[0].max_deviation, 0.01);
    EXPECT_LE(written[1].max_deviation, 0.02);
    EXPECT_EQ(metadata_value(package, "Title"), "parts");
    const std::string description = metadata_value(package, "Description");
    EXPECT_NE(description.find("a 3MF file of 2 solids"), std::string::npos) << description;
    EXPECT_NE(description.find("\nobject peg:\n  tolerance: 0.01;"), std::string::npos) << description;
    EXPECT_NE(description.find("\nobject the knob:\n  tolerance: 0.02;"), std::string::npos) << description;
    // Two objects of one name are refused before anything is written.
    parts[1].module_name = "peg";
    EXPECT_THROW(export_library(parts, path("twice.3mf"), options), Error);
    EXPECT_FALSE(fs::exists(path("twice.3mf")));
}

TEST_F(ThreeMf, ACancelledExportLeavesNoFile) {
    const Solid ball = sphere(5);
    const Mesh mesh = tessellate(ball, 0.01);
    ExportOptions options;
    options.openscad.module_name = "ball";
    options.checks = tessellation_checks(ball, mesh, 0.01);
    for (const double at : {0.05, 0.5, 0.92}) {
        options.progress = [at](double fraction) {
            if (fraction >= at) throw Cancelled();
        };
        EXPECT_THROW(export_tessellation(ball, mesh, 0.01, path("ball.3mf"), options), Cancelled) << at;
        EXPECT_TRUE(fs::is_empty(directory_)) << at;
    }
}

}  // namespace
}  // namespace ratbez::exporter

#include "ratbez/export/writers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "test_support.hpp"
#include "ratbez/error.hpp"

namespace ratbez::exporter {
namespace {

using test::tetrahedron;

// Options naming the module, the rest as by default.
OpenScadOptions named(std::string module_name, int convexity = 10) {
    OpenScadOptions options;
    options.module_name = std::move(module_name);
    options.convexity = convexity;
    return options;
}

TEST(WriteOpenScad, TetrahedronExactTextWithClockwiseFaces) {
    std::ostringstream out;
    write_openscad(tetrahedron(), out);
    EXPECT_EQ(out.str(),
              "// use <this file> imports module shape(); opening the file renders it. Faces are clockwise seen "
              "from outside (OpenSCAD's order).\n"
              "module shape() {\n"
              "polyhedron(points=[\n"
              "[0,0,0],\n"
              "[1,0,0],\n"
              "[0,1,0],\n"
              "[0,0,1]],\n"
              "faces=[\n"
              "[0,1,2],\n"
              "[0,3,1],\n"
              "[0,2,3],\n"
              "[1,3,2]],\n"
              "convexity=10);\n"
              "}\n"
              "shape();\n");
}

TEST(WriteOpenScad, NamedModuleAndConvexity) {
    std::ostringstream out;
    write_openscad(tetrahedron(), out, named("tetra_1", 4));
    const std::string text = out.str();
    EXPECT_NE(text.find("module tetra_1() {\npolyhedron(points=[\n"), std::string::npos);
    EXPECT_NE(text.find("convexity=4);\n}\ntetra_1();\n"), std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 11), "tetra_1();\n");
}

TEST(WriteOpenScad, HeaderLinesAreEscapedSoNoNameRunsAsCode) {
    std::ostringstream out;
    OpenScadOptions options = named("part");
    options.header = {"source: evil\ncube(5); // \\ \r\t\x01 end", "second"};
    write_openscad(tetrahedron(), out, options);
    const std::string text = out.str();
    EXPECT_EQ(text.rfind("// source: evil\\ncube(5); // \\\\ \\r\\t\\x01 end\n// second\n// use <this file>", 0), 0u)
        << text;
    // Every line before the module is a comment.
    const std::string head = text.substr(0, text.find("module part() {"));
    std::istringstream lines(head);
    for (std::string line; std::getline(lines, line);) EXPECT_EQ(line.rfind("// ", 0), 0u) << line;
}

TEST(OpenScadIdentifier, MakesAnyTextAnIdentifier) {
    EXPECT_EQ(openscad_identifier("vase"), "vase");
    EXPECT_EQ(openscad_identifier("my vase-2.final"), "my_vase_2_final");
    EXPECT_EQ(openscad_identifier("9lives"), "_9lives");
    EXPECT_EQ(openscad_identifier(""), "shape");
    EXPECT_EQ(openscad_identifier("for"), "for_solid");
    EXPECT_EQ(openscad_identifier("sphere"), "sphere_solid");
    EXPECT_EQ(openscad_identifier("polyhedron"), "polyhedron_solid");
    EXPECT_FALSE(is_openscad_identifier("cylinder"));
    EXPECT_TRUE(is_openscad_builtin("len"));
    EXPECT_EQ(openscad_identifier("module"), "module_solid");
    EXPECT_EQ(openscad_identifier("use"), "use_solid");
    EXPECT_EQ(openscad_identifier("caf\xc3\xa9"), "caf__");
    EXPECT_TRUE(is_openscad_identifier("_9lives"));
    EXPECT_FALSE(is_openscad_identifier("9lives"));
    EXPECT_FALSE(is_openscad_identifier("true"));
    EXPECT_FALSE(is_openscad_identifier(""));
    EXPECT_FALSE(is_openscad_identifier("a\nb"));
}

TEST(WriteOpenScad, NumbersRoundTripShortest) {
    Mesh m = tetrahedron();
    m.vertices[1] = {0.1, -2.5e-17, 1.0 / 3.0};
    m.vertices[2] = {-0.0, 123456789.125, 1e300};
    std::ostringstream out;
    write_openscad(m, out);
    const std::string text = out.str();
    EXPECT_NE(text.find("[0.1,-2.5e-17,0.3333333333333333],\n"), std::string::npos) << text;
    EXPECT_NE(text.find("[0,123456789.125,1e+300],\n"), std::string::npos) << text;  // -0 written as 0
}

TEST(WriteOpenScad, RejectsBadModuleNameConvexityAndMesh) {
    std::ostringstream out;
    EXPECT_THROW(write_openscad(tetrahedron(), out, named("2bad")), Error);
    EXPECT_THROW(write_openscad(tetrahedron(), out, named("has space")), Error);
    EXPECT_THROW(write_openscad(tetrahedron(), out, named("if")), Error);
    EXPECT_THROW(write_openscad(tetrahedron(), out, named("", 0)), Error);
    Mesh bad_index = tetrahedron();
    bad_index.triangles[2][1] = 4;
    try {
        write_openscad(bad_index, out);
        FAIL() << "expected ratbez::Error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "mesh: triangle 2 refers to vertex 4 but there are only 4 vertices");
    }
    Mesh not_finite = tetrahedron();
    not_finite.vertices[3].z = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(write_openscad(not_finite, out), Error);
    EXPECT_THROW(write_off(not_finite, out), Error);
    EXPECT_THROW(write_stl_binary(not_finite, out), Error);
}

float read_float(const std::string& bytes, std::size_t offset) {
    float value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

TEST(WriteStlBinary, SizeHeaderCountNormalsAndVertices) {
    std::ostringstream out;
    write_stl_binary(tetrahedron(), out);
    const std::string bytes = out.str();
    ASSERT_EQ(bytes.size(), 84u + 50u * 4u);
    EXPECT_EQ(bytes.substr(0, 17), "ratbez binary STL");
    EXPECT_NE(bytes.substr(0, 5), "solid");
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, sizeof count);
    EXPECT_EQ(count, 4u);
    // First facet: triangle (0, 2, 1), the bottom face, normal -z.
    EXPECT_EQ(read_float(bytes, 84), 0.0f);
    EXPECT_EQ(read_float(bytes, 88), 0.0f);
    EXPECT_EQ(read_float(bytes, 92), -1.0f);
    EXPECT_EQ(read_float(bytes, 84 + 12 + 12 + 0), 0.0f);  // second vertex = vertex 2 = (0, 1, 0)
    EXPECT_EQ(read_float(bytes, 84 + 12 + 12 + 4), 1.0f);
    // Last facet: triangle (1, 2, 3), normal (1, 1, 1) / sqrt(3).
    const std::size_t last = 84 + 50 * 3;
    EXPECT_NEAR(read_float(bytes, last), 0.57735026f, 1e-7);
    EXPECT_NEAR(read_float(bytes, last + 8), 0.57735026f, 1e-7);
    EXPECT_EQ(bytes[last + 48], 0);  // attribute byte count
    EXPECT_EQ(bytes[last + 49], 0);
}

TEST(WriteStlAscii, FacetStructure) {
    Mesh m;
    m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 0.5, 0}};
    m.triangles = {{0, 1, 2}};
    std::ostringstream out;
    write_stl_ascii(m, out, "part");
    EXPECT_EQ(out.str(),
              "solid part\n"
              "facet normal 0 0 1\n"
              "outer loop\n"
              "vertex 0 0 0\n"
              "vertex 2 0 0\n"
              "vertex 0 0.5 0\n"
              "endloop\n"
              "endfacet\n"
              "endsolid part\n");
    EXPECT_THROW(write_stl_ascii(m, out, "two\nlines"), Error);
}

TEST(WriteOff, TetrahedronExactText) {
    std::ostringstream out;
    write_off(tetrahedron(), out);
    EXPECT_EQ(out.str(),
              "OFF\n4 4 0\n"
              "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
}

TEST(WriteOpenScad, LargeMeshCrossesTheBufferBoundaryIntact) {
    // A strip of 200k triangles: more than one 1 MiB buffer of text; every face line must survive.
    Mesh m;
    const std::uint32_t n = 100'000;
    for (std::uint32_t i = 0; i <= n; ++i) {
        m.vertices.push_back({i * 0.001, 0.123456789, 0});
        m.vertices.push_back({i * 0.001, 1.987654321, 0});
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
        m.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
    }
    std::ostringstream out;
    write_openscad(m, out);
    const std::string text = out.str();
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n';
    // comment, module, polyhedron, points, faces=[, faces, convexity, }, call
    EXPECT_EQ(lines, 1 + 1 + 1 + m.vertices.size() + 1 + m.triangles.size() + 1 + 1 + 1);
    EXPECT_NE(text.find("[199999,200001,200000]],\nconvexity=10);\n}\nshape();\n"), std::string::npos);
}

}  // namespace
}  // namespace ratbez::exporter

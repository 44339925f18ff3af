// The real OpenSCAD 2021.01 binary renders our library files, opened alone and through `use`. A bare
// top-level polyhedron is exported unchecked, so each file's module is called inside a boolean operation, which makes OpenSCAD convert it to a
// CGAL Nef polyhedron and complain about any open, inverted or non-manifold mesh. OpenSCAD exits 0 even
// then ("ERROR: The given mesh is not closed!"), so the test reads its output, and then reads the STL it
// wrote back to compare the volume.
//
// Then the same for the users' models of the corpus (tests/corpus), read from STEP.
//
// Registered only with RATBEZ_TEST_OPENSCAD=ON (slow: CGAL Nef inside OpenSCAD).

#include <gtest/gtest.h>

#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "build_paths.hpp"
#include "ratbez/export/export.hpp"
#include "ratbez/occt/files.hpp"
#include "ratbez/tessellate.hpp"
#include "spec.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> example_names() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(ratbez::build_paths::examples_dir))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Volume of an ASCII STL as OpenSCAD writes it ("vertex x y z" lines, three per facet).
double ascii_stl_volume(const std::string& text, std::size_t& facets) {
    std::istringstream in(text);
    std::string word;
    double v[9];
    int k = 0;
    double six_volume = 0;
    facets = 0;
    while (in >> word) {
        if (word != "vertex") continue;
        in >> v[3 * k] >> v[3 * k + 1] >> v[3 * k + 2];
        if (++k == 3) {
            six_volume += v[0] * (v[4] * v[8] - v[5] * v[7]) - v[1] * (v[3] * v[8] - v[5] * v[6]) +
                          v[2] * (v[3] * v[7] - v[4] * v[6]);
            k = 0;
            ++facets;
        }
    }
    return six_volume / 6;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Runs OpenSCAD in `dir` on `input`, writing `output`; returns what it printed (stdout and stderr).
std::string openscad(const fs::path& dir, const std::string& input, const std::string& output) {
    const std::string command = "cd '" + dir.string() + "' && '" + ratbez::build_paths::openscad + "' -o " + output + " " + input +
                                " > openscad.log 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(dir / "openscad.log");
    return read_file(dir / "openscad.log");
}

struct Case {
    std::string example;
    double relative_tolerance;
};

// Readable test parameters in gtest's output instead of a byte dump.
void PrintTo(const Case& c, std::ostream* out) { *out << c.example << " at " << c.relative_tolerance << " of its size"; }

class OpenScadRender : public ::testing::TestWithParam<Case> {};

TEST_P(OpenScadRender, RendersWithoutWarningsAndKeepsTheVolume) {
    const Case c = GetParam();
    const auto spec = ratbez::spec::load_spec(std::string(ratbez::build_paths::examples_dir) + "/" + c.example + ".json");
    const auto box = spec.solid.bounding_box();
    const double size = box.diagonal();
    const double tolerance = c.relative_tolerance * size;
    const ratbez::Mesh mesh = ratbez::tessellate(spec.solid, tolerance);
    // OpenSCAD's CGAL Nef conversion is slow (a 100k-triangle difference() takes half a minute), so the
    // finest tolerance runs only where the mesh stays small.
    if (c.relative_tolerance < 1e-3 && mesh.triangles.size() > 30000)
        GTEST_SKIP() << mesh.triangles.size() << " triangles: too slow for OpenSCAD's CGAL Nef";

    const std::string digits = std::to_string(std::lround(-std::log10(c.relative_tolerance)));
    const fs::path dir =
        fs::temp_directory_path() / ("ratbez_openscad_" + c.example + "_" + digits + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    ratbez::exporter::ExportOptions options;
    options.openscad.module_name = spec.name;
    options.checks = ratbez::exporter::tessellation_checks(spec.solid, mesh, tolerance);
    const auto written = ratbez::exporter::export_tessellation(spec.solid, mesh, tolerance, (dir / "shape.scad").string(), options);
    EXPECT_LE(written.max_deviation, tolerance);

    // The file is a library: `use` imports its module (and ignores its top-level call). The far cube is
    // subtracted from nothing: it only forces the boolean operation, which makes CGAL check the mesh.
    std::ofstream(dir / "wrapper.scad") << "use <shape.scad>\ndifference() {\n  " << spec.name << "();\n  translate(["
                                        << box.max.x + size << ", " << box.max.y + size << ", " << box.max.z + size
                                        << "]) cube(" << size * 1e-3 << ");\n}\n";
    const auto run_openscad = [&](const std::string& input, const std::string& output) { return openscad(dir, input, output); };
    if (c.relative_tolerance == 1e-2) {
        // Opened on its own, the file's call renders the solid.
        const std::string alone = run_openscad("shape.scad", "alone.stl");
        EXPECT_EQ(alone.find("WARNING"), std::string::npos) << alone;
        EXPECT_EQ(alone.find("ERROR"), std::string::npos) << alone;
        std::size_t facets = 0;
        EXPECT_NEAR(ascii_stl_volume(read_file(dir / "alone.stl"), facets), written.mesh.volume(),
                    2e-5 * std::abs(written.mesh.volume()));
        EXPECT_EQ(facets, mesh.triangles.size());
    }
    const std::string log = run_openscad("wrapper.scad", "out.stl");
    EXPECT_EQ(log.find("WARNING"), std::string::npos) << log;
    EXPECT_EQ(log.find("ERROR"), std::string::npos) << log;
    EXPECT_NE(log.find("Simple:        yes"), std::string::npos) << log;

    std::size_t facets = 0;
    const double stl_volume = ascii_stl_volume(read_file(dir / "out.stl"), facets);
    ASSERT_GT(facets, 0u) << "OpenSCAD dropped the polyhedron:\n" << log;
    // OpenSCAD prints STL coordinates in float precision (about 7 significant digits, 6 in practice);
    // the volume then agrees to a few parts per million of the shape's size cubed.
    const double mesh_volume = written.mesh.volume();
    EXPECT_NEAR(stl_volume, mesh_volume, 2e-5 * std::abs(mesh_volume))
        << c.example << ": " << facets << " facets read back, " << mesh.triangles.size() << " written";
    fs::remove_all(dir);
}

// import_stl: the library's module import()s a binary STL beside it; used from another folder, OpenSCAD
// finds the STL next to the library (it resolves the name against the file that holds the import).
TEST(OpenScadImportStl, AUsedLibraryFindsItsStlBesideItAndRendersCleanly) {
    const auto spec = ratbez::spec::load_spec(std::string(ratbez::build_paths::examples_dir) + "/vase.json");
    const auto box = spec.solid.bounding_box();
    const double size = box.diagonal(), tolerance = 1e-2 * size;
    const ratbez::Mesh mesh = ratbez::tessellate(spec.solid, tolerance);
    const fs::path dir = fs::temp_directory_path() / ("ratbez_openscad_import_stl_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "lib");
    fs::create_directories(dir / "work");
    ratbez::exporter::ExportOptions options;
    options.openscad.module_name = "vase";
    options.import_stl = true;
    options.checks = ratbez::exporter::tessellation_checks(spec.solid, mesh, tolerance);
    const auto written =
        ratbez::exporter::export_tessellation(spec.solid, mesh, tolerance, (dir / "lib" / "vase.scad").string(), options);
    ASSERT_TRUE(fs::exists(dir / "lib" / "vase.stl"));
    std::ofstream(dir / "work" / "cut.scad") << "use <../lib/vase.scad>\ndifference() {\n  vase();\n  translate(["
                                             << box.max.x + size << ", 0, 0]) cube(" << size * 1e-3 << ");\n}\n";
    const std::string command = "cd '" + (dir / "work").string() + "' && '" + ratbez::build_paths::openscad +
                                "' -o out.stl cut.scad > openscad.log 2>&1";
    const int status = std::system(command.c_str());
    const std::string log = read_file(dir / "work" / "openscad.log");
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
    EXPECT_EQ(log.find("WARNING"), std::string::npos) << log;
    EXPECT_EQ(log.find("ERROR"), std::string::npos) << log;
    std::size_t facets = 0;
    const double volume = ascii_stl_volume(read_file(dir / "work" / "out.stl"), facets);
    ASSERT_GT(facets, 0u) << "OpenSCAD imported nothing:\n" << log;
    EXPECT_NEAR(volume, written.mesh.volume(), 2e-5 * std::abs(written.mesh.volume()));
    fs::remove_all(dir);
}

// Users' models (issue 24): every STEP model of the corpus (FreeCAD's booleans, fillets, PartDesign features,
// compounds; tests/corpus) read, each solid a module of one library at its default tolerance, the module placing
// them all used from another file inside a boolean.
class CorpusRender : public ::testing::TestWithParam<fs::path> {};

TEST_P(CorpusRender, RendersThroughUseInABooleanWithoutWarnings) {
    const std::vector<ratbez::Solid> solids = ratbez::occt::read_step_all(GetParam().string());
    ASSERT_FALSE(solids.empty());
    std::vector<ratbez::Mesh> meshes;
    meshes.reserve(solids.size());  // the parts point into it
    std::vector<ratbez::exporter::LibraryPart> parts;
    ratbez::Box box;
    for (std::size_t i = 0; i < solids.size(); ++i) {
        const double tolerance = ratbez::default_tolerance(solids[i]);
        meshes.push_back(ratbez::tessellate(solids[i], tolerance));
        parts.push_back({"part_" + std::to_string(i), &solids[i], &meshes.back(), tolerance,
                         ratbez::exporter::tessellation_checks(solids[i], meshes.back(), tolerance), std::nullopt});
        box.add(solids[i].bounding_box());
    }
    const fs::path dir = fs::temp_directory_path() / ("ratbez_openscad_corpus_" + GetParam().stem().string() + "_" +
                                                    std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    ratbez::exporter::ExportOptions options;
    options.openscad.module_name = "model";
    const auto written = ratbez::exporter::export_library(parts, (dir / "model.scad").string(), options);
    const double size = box.diagonal();
    std::ofstream(dir / "wrapper.scad") << "use <model.scad>\ndifference() {\n  model();\n  translate(["
                                        << box.max.x + size << ", " << box.max.y + size << ", " << box.max.z + size
                                        << "]) cube(" << size * 1e-3 << ");\n}\n";
    const std::string log = openscad(dir, "wrapper.scad", "out.stl");
    EXPECT_EQ(log.find("WARNING"), std::string::npos) << log;
    EXPECT_EQ(log.find("ERROR"), std::string::npos) << log;
    std::size_t facets = 0;
    const double stl_volume = ascii_stl_volume(read_file(dir / "out.stl"), facets);
    ASSERT_GT(facets, 0u) << "OpenSCAD dropped the model:\n" << log;
    // Several solids may touch or overlap, and OpenSCAD's union merges them. One keeps its volume to OpenSCAD's
    // STL precision (6 significant digits, relative 1e-5 on each coordinate and so a few 1e-5 on the volume).
    if (solids.size() == 1) {
        EXPECT_NEAR(stl_volume, written.front().mesh.volume(), 1e-4 * std::abs(written.front().mesh.volume()));
    }
    fs::remove_all(dir);
}

std::vector<fs::path> corpus_step_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(ratbez::build_paths::corpus_dir))
        if (entry.path().extension() == ".step") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRender, ::testing::ValuesIn(corpus_step_files()),
                         [](const ::testing::TestParamInfo<fs::path>& info) { return info.param.stem().string(); });

std::vector<Case> all_cases() {
    std::vector<Case> cases;
    for (const auto& name : example_names())
        for (double t : {1e-2, 1e-3, 1e-4}) cases.push_back({name, t});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Examples, OpenScadRender, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             const long exponent = std::lround(-std::log10(info.param.relative_tolerance));
                             return info.param.example + "_tol_1em" + std::to_string(exponent);
                         });

}  // namespace

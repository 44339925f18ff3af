// Replays of the fuzz targets' inputs under the ordinary test builds (Release, and Debug with ASan +
// UBSan in scripts/test.sh): every seed of fuzz/corpus/<target>/ (past crashes are kept there as
// regression_* files) through the very harness that found them, plus one test per crash with the
// crashing input as a literal and the behaviour that is now expected.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "build_paths.hpp"
#include "harness.hpp"
#include "model_file_mutation.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/tessellate.hpp"
#include "ratbez/error.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/mesh.hpp"
#ifdef RATBEZ_HAVE_SPEC_FUZZER
#include "spec.hpp"
#endif

namespace ratbez::reliability {
namespace {

using Harness = void (*)(const std::uint8_t*, std::size_t);

// Runs one input; only ratbez::Error may come out (as in LLVMFuzzerTestOneInput).
void replay(Harness harness, const std::vector<std::uint8_t>& input, const std::string& name) {
    try {
        harness(input.data(), input.size());
    } catch (const Error&) {
        // rejected: fine
    } catch (const std::exception& e) {
        ADD_FAILURE() << name << ": an exception other than ratbez::Error escaped: " << e.what();
    }
}

std::vector<std::uint8_t> read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t replay_corpus(const std::string& target, Harness harness) {
    const std::filesystem::path dir = std::filesystem::path(build_paths::fuzz_corpus_dir) / target;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) replay(harness, read_file(file), file.filename().string());
    return files.size();
}

std::vector<std::uint8_t> bytes(std::string_view text) { return {text.begin(), text.end()}; }

TEST(FuzzCorpus, GeometrySeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_geometry", fuzz::run_geometry), 0u); }
TEST(FuzzCorpus, MeshSeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_mesh", fuzz::run_mesh), 0u); }
TEST(FuzzCorpus, OutputSeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_output", fuzz::run_output), 0u); }
// The readers' seeds are real files and the files of the issue 29 findings (regression_*; their expected errors
// are hostile_files_test.cpp's); each also replays mutated as the fuzzer and the soak mutate it, a few seeds
// each (the campaign itself is scripts/soak.sh).
TEST(FuzzCorpus, ReadBrepSeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_read_brep", fuzz::run_read_brep), 0u); }
TEST(FuzzCorpus, ReadStepSeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_read_step", fuzz::run_read_step), 0u); }

std::size_t replay_mutated(const std::string& target, Harness harness, std::uint64_t mutations_per_seed) {
    const std::filesystem::path dir = std::filesystem::path(build_paths::fuzz_corpus_dir) / target;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().filename().string().rfind("regression_", 0) != 0) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::size_t count = 0;
    for (const auto& file : files) {
        const std::vector<std::uint8_t> seed = read_file(file);
        for (std::uint64_t k = 0; k < mutations_per_seed; ++k, ++count) {
            const std::string mutated = fuzz::mutate_model_file(std::string(seed.begin(), seed.end()), k);
            replay(harness, bytes(mutated), file.filename().string() + " mutation " + std::to_string(k));
        }
    }
    return count;
}

TEST(FuzzCorpus, MutatedReadBrepSeedsReplayCleanly) { EXPECT_GT(replay_mutated("fuzz_read_brep", fuzz::run_read_brep, 4), 0u); }
TEST(FuzzCorpus, MutatedReadStepSeedsReplayCleanly) { EXPECT_GT(replay_mutated("fuzz_read_step", fuzz::run_read_step, 4), 0u); }
#ifdef RATBEZ_HAVE_SPEC_FUZZER
TEST(FuzzCorpus, SpecSeedsReplayCleanly) { EXPECT_GT(replay_corpus("fuzz_spec", fuzz::run_spec), 0u); }

// fuzz_spec found: a JSON number that overflows a double ("1e3081") made nlohmann::json throw
// out_of_range (406), which parse_spec did not catch: std::terminate instead of a SpecError.
TEST(FuzzRegression, SpecNumberOverflowIsASpecError) {
    const std::string text =
        R"({"shape": {"type": "extrude", "profile": [{"type": "circle", "radius": 2}], "direction":1e3081, 1], "distance": 3}})";
    replay(fuzz::run_spec, bytes(text), "number overflow");
    try {
        (void)spec::parse_spec(R"({"shape": {"type": "sphere", "radius": 1e400}})");
        FAIL() << "1e400 was accepted";
    } catch (const spec::SpecError& e) {
        EXPECT_EQ(e.path(), "document");
        EXPECT_NE(std::string(e.reason()).find("not valid JSON"), std::string::npos) << e.what();
    }
}

// fuzz_spec found: an unknown field with the empty key ("": 1, legal JSON) at the top level was reported
// under an empty path, which the harness counts as a broken invariant (every error names its field).
TEST(FuzzRegression, SpecEmptyKeyIsNamed) {
    for (const auto& [text, path] : {std::pair{R"({"": "cone", "shape": {"type": "sphere", "radius": 1}})", R"(document[""])"},
                                     std::pair{R"({"shape": {"type": "sphere", "radius": 1, "": 2}})", R"(shape[""])"}}) {
        replay(fuzz::run_spec, bytes(text), "empty key");
        try {
            (void)spec::parse_spec(text);
            FAIL() << "the empty key was accepted: " << text;
        } catch (const spec::SpecError& e) {
            EXPECT_EQ(e.path(), path) << e.what();
            EXPECT_NE(std::string(e.reason()).find("unknown field"), std::string::npos) << e.what();
        }
    }
}
#endif

// fuzz_mesh found: check_mesh computed the mesh volume before validating the triangle indices, and
// Mesh::volume / Mesh::area read vertices[index] unchecked: a heap read out of bounds.
// The input: 4 vertices on the integer grid, 4 triangles, one naming vertex 5.
TEST(FuzzRegression, MeshIndexPastTheVerticesIsRejected) {
    const std::vector<std::uint8_t> input = {0x04, 0x04, 0x01, 0x02, 0x02, 0x02, 0x03, 0x02, 0x02, 0x02, 0x03, 0x02,
                                             0x02, 0x02, 0x03, 0x00, 0x02, 0x01, 0x00, 0x01, 0x03, 0x00, 0x03, 0x02,
                                             0x01, 0x02, 0x05, 0x01};
    replay(fuzz::run_mesh, input, "index past the vertices");

    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 7}};
    EXPECT_THROW((void)mesh.volume(), Error);
    EXPECT_THROW((void)mesh.area(), Error);
    const exporter::MeshReport report = exporter::check_mesh(mesh);
    ASSERT_FALSE(report.ok());
    EXPECT_NE(report.problems.front().find("refers to vertex 7"), std::string::npos) << report.problems.front();
}

// fuzz_geometry found: a profile whose second piece runs straight back down the line the first piece
// ends on (a 180° cusp; corpus regression_profile_folds_back). Its extrusion folds two faces onto each
// other and the tessellation came out open. An open mesh is now refused with an Error naming the solid.
TEST(FuzzRegression, ProfileThatFoldsBackIsNotMeshedOpen) {
    const double h = 1.75;
    const std::vector<NurbsCurve> pieces{
        NurbsCurve::from_bezier(BezierCurve({{0, 0, h}, {h, 0.158984375, h}, {h, h, h}, {h, 3.75, h}}, {2, 1, 1, 1})),
        NurbsCurve::from_bezier(BezierCurve({{h, 3.75, h}, {h, h, h}, {h, h, h}, {h, h, h}})),
        NurbsCurve::from_bezier(BezierCurve({{h, h, h}, {0, 0, h}})),
    };
    try {
        const Solid solid = extrude(Profile(pieces), {h, h, h}, h);
        const Mesh mesh = tessellate(solid, solid.bounding_box().diagonal() / 20);
        EXPECT_TRUE(mesh.is_closed()) << "an open mesh was handed out";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_TRUE(message.rfind("solid:", 0) == 0 || message.rfind("profile:", 0) == 0) << message;
    }
}

}  // namespace
}  // namespace ratbez::reliability

// Runs the real `ratbez` binary: exit codes, the single stderr line for bad input, every export
// format, `info` and `check` on the examples.

#include <gtest/gtest.h>

#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <utility>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "build_paths.hpp"
#include "ratbez/export/three_mf.hpp"

namespace {

namespace fs = std::filesystem;

struct CommandResult {
    int exit_code = -1;
    std::string out, err;
};

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        // No progress line unless a test asks for one (a slow machine must not change stderr).
        setenv("RATBEZ_PROGRESS_AFTER", "1e9", 1);
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string(info->test_suite_name()) + "_" + info->name();
        for (char& c : name)
            if (c == '/') c = '_';
        dir_ = fs::temp_directory_path() / ("ratbez_cli_test_" + name + "_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    CommandResult ratbez(const std::vector<std::string>& args) const {
        std::string command = quoted(ratbez::build_paths::cli);
        for (const auto& a : args) command.append(" ").append(quoted(a));
        const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
        command.append(" >").append(quoted(out.string())).append(" 2>").append(quoted(err.string())).append(" </dev/null");
        const int status = std::system(command.c_str());
        CommandResult run;
        run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        run.out = read_file(out);
        run.err = read_file(err);
        return run;
    }
    std::string spec_file(const std::string& json, const std::string& name = "spec.json") const {
        const fs::path p = dir_ / name;
        std::ofstream(p) << json;
        return p.string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static std::string example(const std::string& name) { return std::string(ratbez::build_paths::examples_dir) + "/" + name; }

    fs::path dir_;
};

// Bad input: exit code 2, nothing on stdout, exactly one line on stderr.
void expect_bad_input(const CommandResult& run, const std::string& expected_line) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, expected_line + "\n");
}

void expect_bad_input_prefix(const CommandResult& run, const std::string& prefix) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err.rfind(prefix, 0), 0u) << run.err;
    ASSERT_FALSE(run.err.empty());
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "not a single line: " << run.err;
}

TEST_F(Cli, MissingField) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sphere"}})")}),
                     "spec error: shape.radius: is required");
    expect_bad_input(ratbez({"info", spec_file(R"({"name": "x"})")}), "spec error: shape: is required");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"radius": 1}})")}), "spec error: shape.type: is required");
}

TEST_F(Cli, WrongType) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sphere", "radius": "ten"}})")}),
                     "spec error: shape.radius: must be a positive number");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sphere", "radius": 1, "center": [0, "a", 0]}})")}),
                     "spec error: shape.center: must be a list of 2 or 3 numbers");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "cylinder", "radius": 1, "height": true}})")}),
                     "spec error: shape.height: must be a positive number");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": "sphere"})")}), "spec error: shape: must be a JSON object");
    expect_bad_input(ratbez({"info", spec_file(R"({"name": 7, "shape": {"type": "sphere", "radius": 1}})")}),
                     "spec error: name: must be a string");
}

TEST_F(Cli, NegativeOrZeroNumbers) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sphere", "radius": -1}})")}),
                     "spec error: shape.radius: must be a positive number");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "cylinder", "radius": 1, "height": 0}})")}),
                     "spec error: shape.height: must be a positive number");
    expect_bad_input(ratbez({"info", spec_file(R"({"tolerance": -0.1, "shape": {"type": "sphere", "radius": 1}})")}),
                     "spec error: tolerance: must be a positive number");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "cone", "radius1": -2, "radius2": 1, "height": 1}})")}),
                     "spec error: shape.radius1: must be a number >= 0");
}

TEST_F(Cli, UnknownTypeAndUnknownFields) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "cube", "size": 1}})")}),
                     "spec error: shape.type: unknown shape type 'cube' (expected cylinder, cone, sphere, torus, revolve, extrude, "
                     "ruled, loft or sweep)");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sphere", "radius": 1, "centre": [0, 0, 0]}})")}),
                     "spec error: shape.centre: unknown field (expected one of: type, radius, center)");
    expect_bad_input(ratbez({"info", spec_file(R"({"tolerence": 0.1, "shape": {"type": "sphere", "radius": 1}})")}),
                     "spec error: tolerence: unknown field (expected one of: name, description, tolerance, tessellation_angle, color, shape)");
    expect_bad_input(
        ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": [{"type": "spline", "points": []}]}})")}),
        "spec error: shape.profile[0].type: unknown curve type 'spline' (expected bezier, nurbs, line, arc, circle or interpolate)");
}

TEST_F(Cli, NestedProfilePaths) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": [
        {"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]},
        {"type": "bezier", "points": [[1, 0, 0], [2, 0, 1], [0, 0]], "weights": [1, 1]}]}})")}),
                     "spec error: shape.profile[1].weights: must have one weight per point (3), not 2");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "extrude", "direction": [0, 0, 1], "distance": 1,
        "profile": [{"type": "bezier", "points": [[1, 0, 0], [2, 0], "x"]}]}})")}),
                     "spec error: shape.profile[0].points[2]: must be a list of 2 or 3 numbers");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": [
        {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1], "points": [[1, 0, 0], [2, 0, 1], [1, 0, 2]]}]}})")}),
                     "spec error: shape.profile[0].knots: must have len(points) + degree + 1 = 6 values, not 5");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": []}})")}),
                     "spec error: shape.profile: must have at least one curve");
}

TEST_F(Cli, KernelErrorsNameTheField) {
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "torus", "major_radius": 2, "minor_radius": 3}})")}),
                     "spec error: shape.minor_radius: must be less than major_radius (else the tube meets the axis)");
    // A profile that does not reach the axis and is not closed.
    expect_bad_input_prefix(
        ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": [{"type": "line", "from": [1, 0, 0], "to": [2, 0, 1]}]}})")}),
        "spec error: shape.profile: ");
    expect_bad_input_prefix(
        ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "angle": 400, "profile": [{"type": "circle", "radius": 1, "center": [3, 0, 0], "normal": [0, 1, 0]}]}})")}),
        "spec error: shape.angle: must be in (0, 360] degrees");
    // A bow tie in the xz plane: its sides cross.
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "revolve", "profile": [
        {"type": "line", "from": [1, 0, 0], "to": [2, 0, 1]}, {"type": "line", "from": [2, 0, 1], "to": [2, 0, 0]},
        {"type": "line", "from": [2, 0, 0], "to": [1, 0, 1]}, {"type": "line", "from": [1, 0, 1], "to": [1, 0, 0]}]}})")}),
                     "spec error: shape.profile: pieces 0 and 2 cross or touch near (1.5, 0, 0.5) (a profile must not cross itself)");
}

// Issue 26: curves interpolated through points (closed profiles, sweep paths), lofts aligned by default.
TEST_F(Cli, InterpolatedSectionsAndAlignment) {
    const CommandResult loft = ratbez({"info", example("interpolated_loft.json")});
    ASSERT_EQ(loft.exit_code, 0) << loft.err;
    EXPECT_NE(loft.out.find("faces:                3"), std::string::npos) << loft.out;
    // A circle of radius 2 swept along an interpolated S path (tangent-continuous, as a sweep needs).
    const CommandResult swept = ratbez({"info", spec_file(R"({"shape": {"type": "sweep",
        "profile": [{"type": "circle", "radius": 0.5, "normal": [0, 0, 1]}],
        "path": [{"type": "interpolate", "points": [[0, 0, 0], [1, 0, 4], [-1, 0, 8], [0, 0, 12]], "tangents": [[0, 0, 1], [0, 0, 1]]}]}})")});
    ASSERT_EQ(swept.exit_code, 0) << swept.err;
    // The issue's circle -> square (the square from its SW corner): aligned it is about OpenCASCADE's 43.16
    // (43.093: each quarter of the circle between the square's corners is one arc matched by its own parameter,
    // the seam at a corner; 43.109 with the seam halfway along a side, where the side folded), twisted (align
    // false) it is refused naming the place.
    const std::string square = R"([{"type": "line", "from": [-1.5, -1.5, 4], "to": [1.5, -1.5, 4]},
        {"type": "line", "from": [1.5, -1.5, 4], "to": [1.5, 1.5, 4]}, {"type": "line", "from": [1.5, 1.5, 4], "to": [-1.5, 1.5, 4]},
        {"type": "line", "from": [-1.5, 1.5, 4], "to": [-1.5, -1.5, 4]}])";
    const CommandResult aligned = ratbez({"info", spec_file(R"({"shape": {"type": "ruled", "profile_a": [{"type": "circle", "radius": 2}],
        "profile_b": )" + square + "}}")});
    ASSERT_EQ(aligned.exit_code, 0) << aligned.err;
    EXPECT_NE(aligned.out.find("volume:               43.093"), std::string::npos) << aligned.out;
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "ruled", "align": false,
        "profile_a": [{"type": "circle", "radius": 2}], "profile_b": )" + square + "}}")}),
                            "spec error: shape.profile_b: the lofted surface folds back on itself (no tangent plane) near (");
    // The interpolate kind's own fields.
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "extrude", "direction": [0, 0, 1], "distance": 1,
        "profile": [{"type": "interpolate", "closed": true, "degree": 3, "points": [[0, 0], [1, 0], [0, 1]]}]}})")}),
                     "spec error: shape.profile[0].points: a degree-3 curve through them needs at least 4 distinct points, got 3 "
                     "(lower the degree for fewer points)");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "extrude", "direction": [0, 0, 1], "distance": 1,
        "profile": [{"type": "interpolate", "closed": true, "parameterization": "arc", "points": [[0, 0], [1, 0], [0, 1], [-1, 0]]}]}})")}),
                     "spec error: shape.profile[0].parameterization: must be \"chord\", \"centripetal\" or \"uniform\", got \"arc\"");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "ruled", "align": 1,
        "profile_a": [{"type": "circle", "radius": 2}], "profile_b": [{"type": "circle", "radius": 1, "center": [0, 0, 1]}]}})")}),
                     "spec error: shape.align: must be true or false");
}

TEST_F(Cli, ModellingKindsNameTheirFields) {
    // ruled / loft / sweep: the spec's own checks, and the kernel's errors under the field they belong to.
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "loft", "profiles": [[{"type": "circle", "radius": 1}]]}})")}),
                     "spec error: shape.profiles: must be a list of at least 2 profiles");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "loft", "degree": 0, "profiles": [
        [{"type": "circle", "radius": 1}], [{"type": "circle", "radius": 1, "center": [0, 0, 1]}]]}})")}),
                     "spec error: shape.degree: must be an integer from 1 to 10");
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "loft", "profiles": [
        [{"type": "circle", "radius": 1}], [{"type": "circle", "radius": 1, "center": [0, 0, 0.5], "normal": [1, 0, 1]}]]}})")}),
                            "spec error: shape.profiles[1]: must lie entirely in front of the plane of profiles[0]");
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "ruled",
        "profile_a": [{"type": "circle", "radius": 1}],
        "profile_b": [{"type": "arc", "radius": 1, "start_deg": 0, "end_deg": 90, "center": [0, 0, 1]}]}})")}),
                            "spec error: shape.profile_b: must be closed");
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "sweep",
        "profile": [{"type": "circle", "radius": 0.1, "normal": [1, 0, 0]}],
        "path": [{"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}, {"type": "line", "from": [1, 0, 0], "to": [1, 1, 0]}]}})")}),
                            "spec error: shape.path: has a corner at parameter 1");
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "sweep",
        "profile": [{"type": "circle", "radius": 0.1, "normal": [1, 0, 0]}],
        "path": [{"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}, {"type": "line", "from": [2, 0, 0], "to": [3, 0, 0]}]}})")}),
                            "spec error: shape.path: curve 1 starts at (2, 0, 0)");
    expect_bad_input(ratbez({"info", spec_file(R"({"shape": {"type": "sweep", "tolerance": -1,
        "profile": [{"type": "circle", "radius": 1}], "path": [{"type": "line", "from": [0, 0, 0], "to": [0, 0, 1]}]}})")}),
                     "spec error: shape.tolerance: must be a positive number");
    // A profile too large for the bend it is swept round.
    expect_bad_input_prefix(ratbez({"info", spec_file(R"({"shape": {"type": "sweep",
        "profile": [{"type": "circle", "radius": 1, "center": [0.5, 0, 0], "normal": [0, 1, 0]}],
        "path": [{"type": "arc", "radius": 0.5, "start_deg": 0, "end_deg": 90}]}})")}),
                            "spec error: shape.profile: reaches ");
}

TEST_F(Cli, NotJsonAndMissingFile) {
    // Column 31 is where the unquoted key `radius` starts (1-based).
    const std::string file = spec_file("{ \"shape\": {\"type\": \"sphere\", radius: 1} }");
    expect_bad_input_prefix(ratbez({"info", file}), "spec error: " + file + ": not valid JSON: parse error at line 1, column 31");
    const std::string array = spec_file("[1, 2]", "array.json");
    expect_bad_input(ratbez({"info", array}), "spec error: " + array + ": must be a JSON object with a \"shape\"");
    expect_bad_input(ratbez({"info", path("missing.json")}), "spec error: " + path("missing.json") + ": cannot open the file");
    expect_bad_input_prefix(ratbez({"info", spec_file("", "empty.json")}), "spec error: " + path("empty.json") + ": not valid JSON");
}

TEST_F(Cli, UsageErrors) {
    expect_bad_input(ratbez({}), "usage error: command: missing (export, check, info or demo; see ratbez --help)");
    expect_bad_input(ratbez({"explode", "x.json"}),
                     "usage error: command: unknown command 'explode' (expected export, check, info or demo)");
    const std::string sphere = example("sphere.json");
    expect_bad_input(ratbez({"export", sphere}),
                     "usage error: -o: the output file is required (-o OUT.scad|stl|off|3mf|step|brep)");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--tolerance", "abc"}),
                     "usage error: --tolerance: must be a positive number, not 'abc'");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--tolerance=-1"}),
                     "usage error: --tolerance: must be a positive number, not '-1'");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--tolerence", "0.1"}),
                     "usage error: --tolerence: unknown option for 'export'");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.stl"), "--module", "m"}),
                     "usage error: --module: applies only to .scad output");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--module", "9lives"}),
                     "usage error: --module: '9lives' is not an OpenSCAD identifier (letters, digits, _; not starting with a digit)");
    // A built-in would shadow OpenSCAD's own cylinder() in every file that uses the library (issue 27).
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--module", "cylinder"}),
                     "usage error: --module: 'cylinder' is an OpenSCAD built-in or keyword: a module of that name would "
                     "shadow OpenSCAD's own in every file that uses the library (try 'cylinder_solid')");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--module", "polyhedron"}),
                     "usage error: --module: 'polyhedron' is an OpenSCAD built-in or keyword: a module of that name would "
                     "shadow OpenSCAD's own in every file that uses the library (try 'polyhedron_solid')");
    // "-o" is named as typed, not as the "--output" it stands for.
    expect_bad_input(ratbez({"export", sphere, "-o"}), "usage error: -o: needs a value");
    expect_bad_input(ratbez({"info", sphere, "-o", path("a.scad")}), "usage error: -o: unknown option for 'info'");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "-o", path("b.scad")}),
                     "usage error: -o: given more than once");
    expect_bad_input(ratbez({"info"}), "usage error: SPEC.json: missing (usage: ratbez info SPEC.json|MODEL.step|MODEL.brep ...)");
    expect_bad_input(ratbez({"info", sphere, "other.json"}), "usage error: other.json: unexpected argument for 'info'");
    EXPECT_FALSE(fs::exists(path("a.scad")));
    EXPECT_FALSE(fs::exists(path("a.stl")));
}

TEST_F(Cli, UnknownExtensionAndUnwritablePath) {
    const std::string sphere = example("sphere.json");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.obj")}),
                     "usage error: -o: unknown extension '.obj' in '" + path("a.obj") +
                         "' (expected .scad, .stl, .off, .3mf, .step or .brep)");
    expect_bad_input(ratbez({"export", sphere, "-o", path("no/such/dir/a.scad")}),
                     "error: path: the folder '" + path("no/such/dir") + "' of '" + path("no/such/dir/a.scad") +
                         "' does not exist");
    expect_bad_input_prefix(ratbez({"export", sphere, "-o", path("no/such/dir/a.step")}), "error: path: ");
    expect_bad_input_prefix(ratbez({"export", sphere, "-o", path("no/such/dir/a.brep")}), "error: path: ");
}

// Signed volume of a binary STL (float32 coordinates).
double binary_stl_volume(const std::string& bytes, std::uint32_t& count) {
    std::memcpy(&count, bytes.data() + 80, 4);
    double six_volume = 0;
    for (std::uint32_t t = 0; t < count; ++t) {
        float v[9];
        std::memcpy(v, bytes.data() + 84 + 50 * std::size_t{t} + 12, sizeof v);
        const double ax = v[0], ay = v[1], az = v[2], bx = v[3], by = v[4], bz = v[5], cx = v[6], cy = v[7], cz = v[8];
        six_volume += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return six_volume / 6;
}

TEST_F(Cli, ExportsEveryFormat) {
    const std::string sphere = example("sphere.json");
    const double exact = 4.0 / 3.0 * std::numbers::pi * 1000.0;

    CommandResult run = ratbez({"export", sphere, "-o", path("s.scad"), "--module", "ball"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(run.out.rfind("wrote " + path("s.scad") + " (", 0), 0u) << run.out;
    const std::string scad = read_file(path("s.scad"));
    EXPECT_NE(scad.find("module ball() {\npolyhedron(points=[\n"), std::string::npos);
    EXPECT_EQ(scad.substr(scad.size() - 10), "}\nball();\n");
    EXPECT_NE(scad.find("\n// source: spec " + sphere + "\n// tolerance: "), std::string::npos) << scad.substr(0, 400);

    run = ratbez({"export", sphere, "-o", path("i.scad"), "--import-stl", "--tolerance", "0.05"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out.rfind("wrote " + path("i.scad") + " and " + path("i.stl") + " (", 0), 0u) << run.out;
    EXPECT_NE(read_file(path("i.scad")).find("module ball() {\nimport(\"i.stl\", convexity=10);\n}\nball();\n"),
              std::string::npos)
        << read_file(path("i.scad"));
    EXPECT_GE(read_file(path("i.stl")).size(), 84u);
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.stl"), "--import-stl"}),
                     "usage error: --import-stl: applies only to .scad output");

    run = ratbez({"export", sphere, "-o", path("s.stl"), "--tolerance", "0.05"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string stl = read_file(path("s.stl"));
    ASSERT_GE(stl.size(), 84u);
    std::uint32_t count = 0;
    const double volume = binary_stl_volume(stl, count);
    EXPECT_EQ(stl.size(), 84u + 50u * count);
    EXPECT_GT(count, 100u);
    // Within the chordal tolerance times the area (plus float32 rounding).
    EXPECT_NEAR(volume, exact, 0.05 * 4 * std::numbers::pi * 100 + 1e-3);
    EXPECT_NE(run.out.find(std::to_string(count) + " triangles"), std::string::npos) << run.out;

    run = ratbez({"export", sphere, "-o", path("s_ascii.stl"), "--ascii", "--tolerance=0.5"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_file(path("s_ascii.stl")).rfind("solid ball\nfacet normal ", 0), 0u);

    run = ratbez({"export", sphere, "-o", path("s.off"), "--angle", "20"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_file(path("s.off")).rfind("OFF\n", 0), 0u);

    run = ratbez({"export", sphere, "-o", path("s.step")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_file(path("s.step")).rfind("ISO-10303-21;", 0), 0u);
    EXPECT_EQ(run.err, "");

    run = ratbez({"export", sphere, "-o", path("s.brep")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(read_file(path("s.brep")).find("CASCADE Topology"), std::string::npos);
}

TEST_F(Cli, ExportsEveryExampleAsScad) {
    for (const auto& entry : fs::directory_iterator(ratbez::build_paths::examples_dir)) {
        if (entry.path().extension() != ".json") continue;
        const std::string out = path(entry.path().stem().string() + ".scad");
        const CommandResult run = ratbez({"export", entry.path().string(), "-o", out});
        EXPECT_EQ(run.exit_code, 0) << entry.path() << ": " << run.err;
        const std::string scad = read_file(out);
        EXPECT_EQ(scad.rfind("// ratbez ", 0), 0u) << entry.path();
        // A library file: the module is named after the spec's `name`, and the last line calls it.
        const std::string json = read_file(entry.path().string());
        const std::size_t at = json.find("\"name\": \"") + 9;
        const std::string name = json.substr(at, json.find('"', at) - at);
        EXPECT_NE(scad.find("\nmodule " + name + "() {\npolyhedron("), std::string::npos) << entry.path();
        EXPECT_EQ(scad.substr(scad.size() - name.size() - 6), "}\n" + name + "();\n") << entry.path();
    }
}

TEST_F(Cli, TooFineNamesTheOptionPassedAndEstimatesTheCount) {
    const std::string sphere = example("sphere.json");  // tolerance 0.01 in the spec: 7,990 triangles
    CommandResult run = ratbez({"export", sphere, "-o", path("a.scad"), "--max-triangles", "1000"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("spec error: tolerance: too fine: the mesh would need about ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(" triangles, more than --max-triangles 1000 allows; --tolerance "), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find(" or coarser fits\n"), std::string::npos) << run.err;
    const std::size_t at = run.err.find("about ") + 6;
    const double estimate = std::stod(run.err.substr(at, run.err.find(' ', at) - at));
    EXPECT_GT(estimate, 4000);
    EXPECT_LT(estimate, 16000);
    run = ratbez({"export", sphere, "-o", path("a.scad"), "--tolerance", "0.001", "--max-triangles", "5000"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("usage error: --tolerance: too fine: the mesh would need about ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("more than --max-triangles 5000 allows; --tolerance "), std::string::npos) << run.err;
    // Absurdly fine: the estimate in powers of ten, and still a tolerance that fits (none was named below 3e-16).
    run = ratbez({"export", sphere, "-o", path("a.scad"), "--tolerance", "1e-30"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err.rfind("usage error: --tolerance: too fine: the mesh would need about ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("e+"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(" or coarser fits\n"), std::string::npos) << run.err;
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.scad"), "--max-triangles", "0"}),
                     "usage error: --max-triangles: must be a positive whole number, not '0'");
    expect_bad_input(ratbez({"export", sphere, "-o", path("a.step"), "--max-triangles", "10"}),
                     "usage error: --max-triangles: does not apply to exact .step output");
    EXPECT_FALSE(fs::exists(path("a.scad")));
}

// Issue 29 item 3: an export whose mesh the CGAL checks would refuse (4,000,000 triangles) was tessellated in
// full first (sphere r = 10 at 1e-5: 4.47M triangles, 352 s) and refused after. It is refused from the plan,
// one line, with the estimate, the checks' limit and a --tolerance that fits. (At 1e-5 the staggered rows of
// issue 28 now mesh it in 2.7M triangles, within the limit: 5e-6 is over it.)
TEST_F(Cli, ExportOverTheChecksLimitIsRefusedFromThePlan) {
    const std::string spec = spec_file(R"({"shape": {"type": "sphere", "radius": 10}})");
    const CommandResult run = ratbez({"export", spec, "-o", path("a.scad"), "--tolerance", "5e-6"});
    expect_bad_input_prefix(run, "usage error: --tolerance: too fine: the mesh would need about ");
    EXPECT_NE(run.err.find(" triangles, more than the export's mesh checks' limit of 4000000 triangles (about 1.8 GB at "
                           "450 bytes each) allows; --tolerance 1.2e-05 or coarser fits\n"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(path("a.scad")));
}

TEST_F(Cli, ProgressLineOnStderrForALongExport) {
    // RATBEZ_PROGRESS_AFTER=0 stands for "over a second" without a slow test.
    setenv("RATBEZ_PROGRESS_AFTER", "0", 1);
    const CommandResult run = ratbez({"export", example("sphere.json"), "-o", path("s.off"), "--tolerance", "0.1"});
    setenv("RATBEZ_PROGRESS_AFTER", "1e9", 1);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err.rfind("\rexporting " + path("s.off") + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("100% (about 0 s left)"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.back(), '\n');
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;  // one line, rewritten in place
    // Rewritten only when its percent grows: each percent once, in order.
    int last = -1;
    for (std::size_t at = run.err.find(": "); at != std::string::npos; at = run.err.find(": ", at + 1)) {
        const int percent = std::stoi(run.err.substr(at + 2, 3));
        EXPECT_GT(percent, last) << run.err;
        last = percent;
    }
    EXPECT_EQ(last, 100);
}

TEST_F(Cli, ModuleNameFromSpecNameElseOutputStem) {
    const std::string named = spec_file(R"({"name": "ball", "shape": {"type": "sphere", "radius": 1}})", "named.json");
    const std::string unnamed = spec_file(R"({"shape": {"type": "sphere", "radius": 1}})", "unnamed.json");
    ASSERT_EQ(ratbez({"export", named, "-o", path("out.scad")}).exit_code, 0);
    EXPECT_NE(read_file(path("out.scad")).find("\nmodule ball() {\n"), std::string::npos);
    ASSERT_EQ(ratbez({"export", unnamed, "-o", path("2 my-part.scad")}).exit_code, 0);
    EXPECT_NE(read_file(path("2 my-part.scad")).find("\nmodule _2_my_part() {\n"), std::string::npos);
    ASSERT_EQ(ratbez({"export", named, "-o", path("out.scad"), "--module", "other"}).exit_code, 0);
    EXPECT_NE(read_file(path("out.scad")).find("\nmodule other() {\n"), std::string::npos);
}

TEST_F(Cli, InfoOfSphereAndTorus) {
    CommandResult run = ratbez({"info", example("sphere.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("name:                 ball\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("faces:                1\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("euler characteristic: 2\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("bounding box:         ("), std::string::npos) << run.out;

    run = ratbez({"info", example("sphere.json"), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto sphere = nlohmann::json::parse(run.out);
    EXPECT_EQ(sphere["faces"], 1);
    EXPECT_EQ(sphere["euler_characteristic"], 2);
    EXPECT_EQ(sphere["degenerate_edges"], 2);
    EXPECT_NEAR(sphere["volume"].get<double>(), 4.0 / 3.0 * std::numbers::pi * 1000.0, 1e-8);
    EXPECT_NEAR(sphere["area"].get<double>(), 4.0 * std::numbers::pi * 100.0, 1e-8);
    // The control-point box contains the ball of radius 10.
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(sphere["bounding_box"]["min"][k].get<double>(), -10.0 + 1e-12);
        EXPECT_GE(sphere["bounding_box"]["max"][k].get<double>(), 10.0 - 1e-12);
    }

    run = ratbez({"info", example("torus.json"), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto torus = nlohmann::json::parse(run.out);
    EXPECT_EQ(torus["euler_characteristic"], 0);
    EXPECT_NEAR(torus["volume"].get<double>(), 2 * std::numbers::pi * std::numbers::pi * 10 * 9, 1e-8);

    run = ratbez({"info", example("cylinder.json"), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto cylinder = nlohmann::json::parse(run.out);
    EXPECT_EQ(cylinder["faces"], 3);
    EXPECT_EQ(cylinder["euler_characteristic"], 2);
    EXPECT_NEAR(cylinder["volume"].get<double>(), std::numbers::pi * 25 * 20, 1e-8);
}

// Whether every failure of a check report is one the BOP analysis still finds on faces read from files whose
// surfaces keep C0 knots (a trimmed face keeps its surface's parameter): GeomAbs_C0 and the face
// self-intersection test.
bool only_known_bop_findings(const nlohmann::json& report) {
    for (const auto& failure : report["failures"]) {
        const std::string text = failure.get<std::string>();
        if (text.rfind("BOP check: BOPAlgo GeomAbs_C0", 0) != 0 && text.rfind("BOP check: BOPAlgo SelfIntersect: face", 0) != 0)
            return false;
    }
    return true;
}

TEST_F(Cli, CheckPassesOnEveryExample) {
    for (const auto& entry : fs::directory_iterator(ratbez::build_paths::examples_dir)) {
        if (entry.path().extension() != ".json") continue;
        const CommandResult run = ratbez({"check", entry.path().string(), "--json"});
        const auto report = nlohmann::json::parse(run.out, nullptr, false);
        ASSERT_FALSE(report.is_discarded()) << run.out;
        EXPECT_EQ(run.exit_code, 0) << entry.path() << ": " << run.out << run.err;
        EXPECT_EQ(report["passed"], true) << entry.path();
        EXPECT_EQ(report["bop_clean"], true) << entry.path();
        EXPECT_EQ(report["valid"], true) << entry.path();
        EXPECT_NEAR(report["volume"].get<double>(), report["occt_volume"].get<double>(),
                    1e-6 * std::abs(report["volume"].get<double>()))
            << entry.path();
    }
    const CommandResult table = ratbez({"check", example("cone.json")});
    EXPECT_EQ(table.exit_code, 0) << table.err;
    EXPECT_EQ(table.out.rfind("cone (cone)\n", 0), 0u) << table.out;
}

// Issue 14, items 9 and 11: a spec's size and nesting are bounded before the work grows, repeated keys are
// refused, and two demo specs with one name fail the demo instead of overwriting each other's files.
TEST_F(Cli, SpecSizeDepthAndRepeatedKeysAreRefused) {
    const CommandResult zero = ratbez({"info", "/dev/zero"});  // read until memory ran out
    expect_bad_input(zero, "spec error: /dev/zero: has more than 16777216 bytes, the limit for a spec");
    const std::string deep = spec_file(std::string(100000, '['));
    expect_bad_input(ratbez({"info", deep}), "spec error: " + deep + ": nests objects and arrays deeper than the limit 64");
    const std::string twice = spec_file(R"({"shape": {"type": "sphere", "radius": 1, "radius": 2}})");
    expect_bad_input(ratbez({"info", twice}), "spec error: " + twice + ": the key \"radius\" appears twice in one object");
}

// Issue 29 item 8: a spec with a NUL and garbage after the closing brace was accepted (the JSON parser took the
// NUL for the end of the text and never read the rest). Refused, one line, exit code 2; garbage alone already was.
TEST_F(Cli, SpecWithANulByteIsRefused) {
    const std::string spec = R"({"shape": {"type": "sphere", "radius": 1}})";
    const std::string nul = spec_file(spec + std::string(1, '\0') + "garbage");
    expect_bad_input(ratbez({"info", nul}), "spec error: " + nul + ": not valid JSON: a NUL byte at offset 42 (JSON text has none)");
    const std::string inside = spec_file(R"({"name": "a)" + std::string(1, '\0') + R"(b", "shape": {"type": "sphere", "radius": 1}})");
    expect_bad_input(ratbez({"info", inside}), "spec error: " + inside + ": not valid JSON: a NUL byte at offset 11 (JSON text has none)");
    expect_bad_input_prefix(ratbez({"export", nul, "-o", path("a.scad")}), "spec error: " + nul + ": not valid JSON: a NUL byte");
    EXPECT_FALSE(fs::exists(path("a.scad")));
}

TEST_F(Cli, DemoFailsWhenTwoSpecsShareAName) {
    fs::create_directories(dir_ / "specs");
    std::ofstream(dir_ / "specs" / "a.json") << R"({"name": "same", "shape": {"type": "sphere", "radius": 1}})";
    std::ofstream(dir_ / "specs" / "b.json") << R"({"name": "same", "shape": {"type": "sphere", "radius": 2}})";
    const CommandResult demo = ratbez({"demo", path("out"), "--examples", (dir_ / "specs").string(), "--no-render"});
    EXPECT_EQ(demo.exit_code, 1) << demo.out << demo.err;
    EXPECT_NE(demo.out.find("FAIL same: the name 'same' is also the name of a.json"), std::string::npos) << demo.out;
}

}  // namespace

namespace {

class CliEconomy : public Cli {};

// Issue 17: meshes that straddle the surface need fewer triangles; no example may need more than the
// inscribed meshes did (main at 93a7f42, each example at its own tolerance). Binary STL without the
// self-intersection check keeps it cheap (no deviation measurement: TessellateEconomy and TessellateShape
// measure both directions); release only (scripts/test.sh).
TEST_F(CliEconomy, ExamplesNeedNoMoreTrianglesThanInscribedMeshes) {
    const std::vector<std::pair<std::string, int>> before{
        {"cone", 344},  {"cone_apex", 70}, {"cylinder", 128}, {"extrude", 108}, {"loft", 1596},  {"partial_revolve", 1154},
        {"ring", 1808}, {"ruled", 932},    {"sphere", 7990},  {"sweep", 1940},  {"torus", 2208}, {"vase", 6064}};
    for (const auto& [name, most] : before) {
        SCOPED_TRACE(name);
        const CommandResult run =
            ratbez({"export", example(name + ".json"), "-o", path(name + ".stl"), "--skip-self-intersection-check"});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const auto open = run.out.find(" ("), end = run.out.find(" triangles");
        ASSERT_NE(end, std::string::npos) << run.out;
        const int triangles = std::stoi(run.out.substr(open + 2, end - open - 2));
        EXPECT_LE(triangles, most);
        EXPECT_GT(triangles, most / 3);  // a mesh, not a token
    }
}

}  // namespace

TEST_F(Cli, DerivedModuleNamesThatAreBuiltinsGetASuffixAndSaySo) {
    // A spec without a name exported to cylinder.scad: the module is named after the file, which would be
    // OpenSCAD's own cylinder (issue 27).
    const std::string spec = spec_file(R"({"shape": {"type": "cylinder", "radius": 1, "height": 2}})", "unnamed.json");
    const CommandResult run = ratbez({"export", spec, "-o", path("cylinder.scad"), "--tolerance", "0.05"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "note: module cylinder_solid() (the file name 'cylinder' is an OpenSCAD built-in, which the "
                       "library must not shadow)\n");
    const std::string scad = read_file(path("cylinder.scad"));
    EXPECT_NE(scad.find("module cylinder_solid() {\n"), std::string::npos);
    EXPECT_EQ(scad.find("module cylinder()"), std::string::npos);
}

// A name from a model file goes to the terminal escaped: an ESC in a STEP product's name recoloured it; a C1
// control (U+009B, CSI) or a bidirectional override (U+202E) would too, or reorder the line.
TEST_F(Cli, NamesFromFilesArePrintedWithControlCharactersEscaped) {
    ASSERT_EQ(ratbez({"export", example("sphere.json"), "-o", path("ball.step")}).exit_code, 0);
    std::string step = read_file(path("ball.step"));
    const std::string translator = "'Open CASCADE STEP translator 7.6 1'";  // the product's id and name
    for (int field = 0; field < 2; ++field) {
        const std::size_t at = step.find(translator);
        ASSERT_NE(at, std::string::npos) << step.substr(0, 2000);
        step.replace(at, translator.size(), "'\x1b[31mred\xc2\x9b" "2J\xe2\x80\xae" "desrever'");
    }
    std::ofstream(path("ball_red.step"), std::ios::binary) << step;
    for (const char* command : {"info", "check"}) {
        const CommandResult run = ratbez({command, path("ball_red.step")});
        for (const char* raw : {"\x1b", "\xc2\x9b", "\xe2\x80\xae"})
            EXPECT_EQ(run.out.find(raw), std::string::npos) << command << ": " << run.out;
        EXPECT_NE(run.out.find("\\x1b[31mred"), std::string::npos) << command << ": " << run.out;
        EXPECT_NE(run.out.find("desrever"), std::string::npos) << command << ": " << run.out;
    }
}

TEST_F(Cli, HelpAfterACommandPrintsTheUsage) {
    for (const char* command : {"export", "check", "info", "demo"})
        for (const char* help : {"--help", "-h"}) {
            const CommandResult run = ratbez({command, help});
            EXPECT_EQ(run.exit_code, 0) << command << " " << help;
            EXPECT_NE(run.out.find(std::string("  ratbez ") + command), std::string::npos) << run.out;
            EXPECT_EQ(run.err, "");
        }
    const CommandResult after = ratbez({"export", example("sphere.json"), "-o", path("a.scad"), "--help"});
    EXPECT_EQ(after.exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(path("a.scad")));
}

TEST_F(Cli, Version) {
    const CommandResult run = ratbez({"--version"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.out, "ratbez " RATBEZ_VERSION "\n");
    EXPECT_EQ(run.err, "");
    expect_bad_input(ratbez({"--version", "x"}), "usage error: x: unexpected argument for '--version'");
}

// .3mf (issue 27): one object named after the spec (or the file: any text) with the spec's colour, read back by lib3mf
// with the triangles the command reports; a built-in name is no matter there (no note), and --module is
// refused as for every format but .scad.
TEST_F(Cli, ExportsThreeMfNamedAndColouredFromTheSpec) {
    const std::string spec =
        spec_file(R"({"name": "red_ball", "color": "#ff0000", "shape": {"type": "sphere", "radius": 1}})");
    CommandResult run = ratbez({"export", spec, "-o", path("r.3mf"), "--tolerance", "0.01"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const std::string package = read_file(path("r.3mf"));
    const auto objects = ratbez::exporter::read_three_mf(package);
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].name, "red_ball");
    ASSERT_TRUE(objects[0].color.has_value());
    EXPECT_EQ(objects[0].color->red, 1.0);
    EXPECT_EQ(objects[0].color->blue, 0.0);
    EXPECT_EQ(run.out.rfind("wrote " + path("r.3mf") + " (" + std::to_string(objects[0].mesh.triangles.size()) + " triangles, ", 0), 0u)
        << run.out;
    EXPECT_NEAR(objects[0].mesh.volume(), 4.0 / 3.0 * std::numbers::pi, 0.01 * 4 * std::numbers::pi);
    EXPECT_NE(package.find("PK"), std::string::npos);
    const auto metadata = ratbez::exporter::read_three_mf_metadata(package);
    ASSERT_FALSE(metadata.empty());
    EXPECT_EQ(metadata.front(), std::make_pair(std::string("Application"), std::string("ratbez " RATBEZ_VERSION)));

    const std::string unnamed = spec_file(R"({"shape": {"type": "sphere", "radius": 1}})", "unnamed.json");
    run = ratbez({"export", unnamed, "-o", path("sphere.3mf"), "--tolerance", "0.05"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");  // no note: a 3MF object may be called sphere
    EXPECT_EQ(ratbez::exporter::read_three_mf(read_file(path("sphere.3mf"))).at(0).name, "sphere");
    expect_bad_input(ratbez({"export", spec, "-o", path("m.3mf"), "--module", "m"}),
                     "usage error: --module: applies only to .scad output");
    // Coordinates lib3mf cannot hold within the tolerance: refused as our failure (exit 1), no file.
    const std::string tiny = spec_file(R"({"shape": {"type": "sphere", "radius": 0.01}})", "tiny.json");
    run = ratbez({"export", tiny, "-o", path("tiny.3mf"), "--tolerance", "1e-6"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err.rfind("error: mesh: 3MF, as lib3mf 1.8 writes it, stores float32 coordinates cut to 6 decimals", 0), 0u) << run.err;
    EXPECT_FALSE(fs::exists(path("tiny.3mf")));
}

TEST_F(Cli, SpecColourWrapsTheModuleBody) {
    const std::string spec = spec_file(R"({"name": "red_ball", "color": "#FF000080", "shape": {"type": "sphere", "radius": 1}})");
    const CommandResult run = ratbez({"export", spec, "-o", path("r.scad"), "--tolerance", "0.05"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(read_file(path("r.scad")).find("module red_ball() {\ncolor([1,0,0,0.5019607843137255])\npolyhedron("),
              std::string::npos);
    expect_bad_input(ratbez({"export", spec_file(R"({"color": "red", "shape": {"type": "sphere", "radius": 1}})"), "-o",
                             path("b.scad")}),
                     "spec error: color: 'red' is not a colour (expected \"#rrggbb\" or \"#rrggbbaa\", hexadecimal)");
    expect_bad_input(ratbez({"info", spec_file(R"({"color": 3, "shape": {"type": "sphere", "radius": 1}})")}),
                     "spec error: color: must be a string");
}

// ---- model files (issue 24): a .step/.stp/.brep works wherever a spec does, every solid in it ----------

std::string corpus(const std::string& name) { return std::string(ratbez::build_paths::corpus_dir) + "/" + name; }

TEST_F(Cli, InfoListsEverySolidOfAModelFile) {
    const CommandResult run = ratbez({"info", "--json", corpus("two_solids.step")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto solids = nlohmann::json::parse(run.out);
    ASSERT_TRUE(solids.is_array());
    ASSERT_EQ(solids.size(), 2u);
    // FreeCAD's Part.export names no product: the solids are named after the file, numbered.
    EXPECT_EQ(solids[0]["name"], "two_solids_1");
    EXPECT_EQ(solids[1]["name"], "two_solids_2");
    EXPECT_EQ(solids[0]["type"], "STEP solid");
    EXPECT_NEAR(solids[0]["volume"].get<double>(), 125, 1e-9);                                   // a 5 mm cube
    EXPECT_NEAR(solids[1]["volume"].get<double>(), std::numbers::pi * 4 * 6 / 3 * 3, 1e-9);       // a cylinder r 2 h 6
    // A box with a spherical void: one solid of two shells, its volume the box's less the ball's.
    const CommandResult void_run = ratbez({"info", corpus("box_with_void.brep")});
    ASSERT_EQ(void_run.exit_code, 0) << void_run.err;
    EXPECT_NE(void_run.out.find("shells:               2 (the outer one and voids)"), std::string::npos) << void_run.out;
    EXPECT_NE(void_run.out.find("euler characteristic: 4"), std::string::npos) << void_run.out;
}

TEST_F(Cli, ExportsEverySolidOfAModelFileIntoOneLibrary) {
    const CommandResult run = ratbez({"export", corpus("two_solids.step"), "-o", path("parts.scad")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("2 solids in modules two_solids_1, two_solids_2 placed by parts()"), std::string::npos) << run.out;
    const std::string scad = read_file(path("parts.scad"));
    for (const char* module : {"module two_solids_1() {", "module two_solids_2() {", "module parts() {"})
        EXPECT_NE(scad.find(module), std::string::npos) << module;
    // Exact formats keep every solid: the STEP written reads back as two.
    for (const char* exact : {"parts.step", "parts.brep"}) {
        const CommandResult written = ratbez({"export", corpus("two_solids.step"), "-o", path(exact)});
        ASSERT_EQ(written.exit_code, 0) << written.err;
        EXPECT_NE(written.out.find("(exact B-rep, 2 solids, 9 faces)"), std::string::npos) << written.out;
        const CommandResult back = ratbez({"info", "--json", path(exact)});
        ASSERT_EQ(back.exit_code, 0) << back.err;
        EXPECT_EQ(nlohmann::json::parse(back.out).size(), 2u) << exact;
    }
    // One mesh of both for .stl and .off, one object each for .3mf.
    for (const char* mesh : {"parts.stl", "parts.off", "parts.3mf"}) {
        const CommandResult written = ratbez({"export", corpus("two_solids.step"), "-o", path(mesh)});
        EXPECT_EQ(written.exit_code, 0) << mesh << ": " << written.err;
        EXPECT_TRUE(fs::exists(path(mesh))) << mesh;
    }
}

TEST_F(Cli, FacesOutsideEverySolidAreLeftOutWithANote) {
    // FreeCAD's SOT404.stp: four solids and an open shell of 17 faces; the export goes on and says what it left out.
    const std::string part = "/usr/share/freecad/Mod/Idf/Idflibs/SOT404.stp";
    if (!fs::exists(part)) GTEST_SKIP() << "FreeCAD's Idf parts are not installed";
    const CommandResult run = ratbez({"export", part, "-o", path("sot.scad")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("note: '" + part + "': left out 17 face(s) outside every solid"), std::string::npos) << run.err;
    const CommandResult clean = ratbez({"info", corpus("two_solids.step")});
    EXPECT_EQ(clean.err.find("left out"), std::string::npos) << clean.err;
    // --strict: a script that must not go on with part of a model gets the note as its refusal, and no file.
    for (const char* command : {"export", "check", "info"}) {
        std::vector<std::string> arguments{command, part, "--strict"};
        if (std::string(command) == "export") arguments.insert(arguments.end(), {"-o", path("strict.scad")});
        const CommandResult refused = ratbez(arguments);
        EXPECT_EQ(refused.exit_code, 2) << command << ": " << refused.err;
        EXPECT_EQ(refused.err, "error: path: '" + part + "': left out 17 face(s) outside every solid: they bound no volume (open "
                               "shells or loose faces) (--strict: refused)\n") << command;
    }
    EXPECT_FALSE(fs::exists(path("strict.scad")));
    EXPECT_EQ(ratbez({"info", corpus("two_solids.step"), "--strict"}).exit_code, 0);
}

TEST_F(Cli, ASolidOfSeveralThatCannotBeHandedOutIsLeftOutWithANote) {
    // tests/cli/data (make_parts.py): a cylinder beside a prism that touches itself along an edge, which does not mesh
    // (a keyboard's audio jack in a STEP assembly of five), or beside a bipyramid that intersects itself, whose mesh
    // the export's checks refuse (an ODrive board's leader). The export had refused the whole file; the cylinder is
    // written, and the note names the other solid and why, as for a solid the reader leaves out. --strict refuses
    // the file with that solid's refusal (exit 2 for the mesh not made, 1 for the mesh refused) and writes nothing.
    struct Case {
        const char* file;
        std::string why;
        int strict_exit;
    };
    const std::vector<Case> cases = {
        {"touching_parts", "solid: 'touching_parts_2': face 8: loops: two points of the boundary fall on one place (0, 0): the loops "
                           "touch themselves or each other",
         2},
        {"crossing_parts", "mesh: 'crossing_parts_2': refusing to export an invalid mesh: the surface intersects itself near (", 1},
    };
    for (const Case& c : cases) {
        const std::string file = std::string(ratbez::build_paths::cli_data_dir) + "/" + c.file + ".brep";
        const CommandResult run = ratbez({"export", file, "-o", path("parts.scad")});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const std::string kept = std::string(c.file) + "_1";
        EXPECT_NE(run.out.find("(1 solid in module " + kept + " placed by parts()"), std::string::npos) << run.out;
        EXPECT_EQ(run.err.rfind("note: '" + file + "': left out 1 of 2 solids that do not mesh or whose meshes fail the export's "
                                "checks: " + c.why, 0), 0u) << run.err;
        const std::string scad = read_file(path("parts.scad"));
        EXPECT_NE(scad.find("module " + kept + "() {"), std::string::npos) << c.file;
        EXPECT_EQ(scad.find(std::string(c.file) + "_2"), std::string::npos) << c.file;
        const CommandResult strict = ratbez({"export", file, "-o", path("strict.scad"), "--strict"});
        EXPECT_EQ(strict.exit_code, c.strict_exit) << c.file;
        EXPECT_EQ(strict.err.rfind("error: " + c.why, 0), 0u) << strict.err;
        EXPECT_FALSE(fs::exists(path("strict.scad"))) << c.file;
    }
}

TEST_F(Cli, OneSolidOfAModelFileIsNamedAfterTheOutput) {
    // A solid with a void and a trimmed sphere: exported as any single solid, module after the file written.
    for (const char* input : {"box_with_void.brep", "sphere_minus_box.step"}) {
        const CommandResult run = ratbez({"export", corpus(input), "-o", path("part.scad")});
        ASSERT_EQ(run.exit_code, 0) << input << ": " << run.err;
        EXPECT_NE(read_file(path("part.scad")).find("module part() {"), std::string::npos) << input;
    }
}

TEST_F(Cli, CheckReportsEverySolidOfAModelFile) {
    const CommandResult run = ratbez({"check", "--json", corpus("two_solids.brep")});
    ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
    const auto reports = nlohmann::json::parse(run.out);
    ASSERT_EQ(reports.size(), 2u);
    for (const auto& report : reports) {
        EXPECT_EQ(report["valid"], true);
        EXPECT_EQ(report["passed"], true);
    }
    // The trimmed sphere keeps its surface's C0 knots (only_known_bop_findings): the BOP analysis says so, and
    // the check fails on that alone.
    const CommandResult text = ratbez({"check", corpus("sphere_minus_box.step")});
    EXPECT_EQ(text.out.rfind("sphere_minus_box (STEP solid)\nOpenCASCADE check: ", 0), 0u) << text.out;
    const CommandResult json = ratbez({"check", "--json", corpus("sphere_minus_box.step")});
    const auto reports_of_file = nlohmann::json::parse(json.out);  // a model file: an array of reports
    ASSERT_EQ(reports_of_file.size(), 1u) << json.out;
    const auto& report = reports_of_file[0];
    EXPECT_EQ(report["valid"], true);
    EXPECT_TRUE(only_known_bop_findings(report)) << json.out;
    EXPECT_EQ(text.exit_code, report["passed"] == true ? 0 : 1) << text.out;
}

TEST_F(Cli, ModelFileErrorsAreOneLine) {
    expect_bad_input(ratbez({"info", path("missing.step")}), "error: path: '" + path("missing.step") + "' does not exist");
    std::ofstream(path("garbage.step")) << "not STEP at all\n";
    expect_bad_input(ratbez({"info", path("garbage.step")}), "error: path: '" + path("garbage.step") + "' is not a readable STEP file");
    expect_bad_input(ratbez({"export", corpus("two_solids.step"), "-o", path("x.scad"), "--import-stl"}),
                     "usage error: --import-stl: applies to one solid, and '" + corpus("two_solids.step") + "' holds 2");
}

// The profile check that revolve and extrude run before building faces (the profile must not cross or
// touch itself: kernel/core/src/modelling/profile_crossings.hpp), against OpenCASCADE's nearest counterpart in the
// same run, single-threaded:
//   ours       detail::require_no_crossings(profile, plane)
//   BRepCheck  BRepCheck_Analyzer on the planar cap face bounded by the same profile (the extrusion's top
//              face, converted by ratbez::occt::convert). It checks more than crossings (edges against
//              their pcurves, vertices, orientation), among them BRepCheck_Wire's self-intersection test.
// Both accept every profile here. Names: profile/<profile>/<ours|BRepCheck>; counter `spans` (Bézier spans).

#include <benchmark/benchmark.h>

#include <BRepCheck_Analyzer.hxx>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "modelling/profile_crossings.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/occt/topology.hpp"

namespace ratbez::bench {
namespace {

struct NamedProfile {
    std::string name;
    Profile profile;
};

// Closed profiles in the xy plane: four rational quarter circles; a star of 64 straight sides; one
// closed cubic B-spline of 1000 control points around a wavy circle.
std::vector<NamedProfile> profiles() {
    std::vector<NamedProfile> out;
    out.push_back({"circle_4_arcs", Profile({arc(1.0, 0, 90), arc(1.0, 90, 180), arc(1.0, 180, 270), arc(1.0, 270, 360)})});

    std::vector<Vec3> star;
    for (int k = 0; k < 64; ++k) {
        const double radius = k % 2 == 0 ? 1.0 : 0.6, angle = 2 * std::numbers::pi * k / 64;
        star.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    std::vector<NurbsCurve> sides;
    for (std::size_t k = 0; k < star.size(); ++k) sides.push_back(line_segment(star[k], star[(k + 1) % star.size()]));
    out.push_back({"star_64_lines", Profile(sides)});

    const int count = 1000, p = 3;
    std::vector<double> knots(p + 1, 0.0);
    for (int k = 1; k < count - p; ++k) knots.push_back(static_cast<double>(k) / (count - p));
    knots.insert(knots.end(), p + 1, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double angle = 2 * std::numbers::pi * i / (count - 1), radius = 1 + 0.05 * std::sin(40 * angle);
        points.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    points.back() = points.front();
    out.push_back({"spline_1000_points", Profile({NurbsCurve(p, knots, points)})});
    return out;
}

double span_count(const Profile& profile) {
    std::size_t spans = 0;
    for (const NurbsCurve& piece : profile.pieces()) spans += piece.bezier_segments().size();
    return static_cast<double>(spans);
}

void ours(benchmark::State& state, const Profile& profile) {
    for (auto _ : state) detail::require_no_crossings(profile, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    state.counters["spans"] = span_count(profile);
}

void brepcheck(benchmark::State& state, const Profile& profile) {
    const occt::ConvertedSolid converted = occt::convert(extrude(profile, {0, 0, 1}, 1.0));
    const TopoDS_Face cap = converted.faces.back();  // extrude's faces end with the bottom and top caps
    for (auto _ : state) {
        BRepCheck_Analyzer analyzer(cap);
        if (!analyzer.IsValid()) state.SkipWithError("BRepCheck calls the cap invalid");
    }
    state.counters["spans"] = span_count(profile);
}

}  // namespace

void register_benchmarks() {
    static const std::vector<NamedProfile> all = profiles();
    for (const NamedProfile& named : all) {
        const Profile* profile = &named.profile;
        benchmark::RegisterBenchmark(benchmark_name({"profile", named.name, "ours"}).c_str(),
                                     [profile](benchmark::State& s) { ours(s, *profile); })
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(benchmark_name({"profile", named.name, "BRepCheck"}).c_str(),
                                     [profile](benchmark::State& s) { brepcheck(s, *profile); })
            ->Unit(benchmark::kMicrosecond);
    }
}

}  // namespace ratbez::bench

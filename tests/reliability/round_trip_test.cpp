// Randomized round trips through every stage of the kernel, seeded and reproducible:
//   random profile (Bézier and NURBS pieces, weights in [1e-3, 1e3], scale 1e-4 .. 1e4, close to but
//   not touching the axis) -> revolve (full or partial) -> OpenCASCADE check (BRepCheck validity, our
//   evaluation against OCCT's, volumes) -> tessellate -> closed mesh with valid indices and the right
//   volume -> CGAL: closed, manifold, outward, no self-intersection -> max_deviation within the
//   tolerance -> OpenSCAD text parses back to the same mesh (vertices bit for bit, same triangles).
//
// Budget (2 cores, beside every other suite): the cheap stages run on EVERY case; the expensive ones on
// a deterministic subset: the OCCT check, CGAL's self-intersection test and max_deviation on every 10th
// case (index % 10 == 0). The other CGAL checks (closed, manifold, outward) run on all.
// The Release suite runs 10 shards of 100 cases (1,000, sized to the test command's 20 minutes); the sanitizer
// build (Debug + ASan + UBSan, about 15x slower) runs 10 shards of 15 (150), with the same stage schedule,
// and FoundSeed replays every seed that ever failed, one test each.
// RATBEZ_ROUND_TRIP_CASES sets the cases per shard (scripts/soak.sh runs 1,000 per shard and more).
//
// Case i of the run uses the seed base + i (base 20261122 unless RATBEZ_ROUND_TRIP_SEED says otherwise);
// a failure prints it. To reproduce one case alone:
//   RATBEZ_ROUND_TRIP_SEED=<seed> RATBEZ_ROUND_TRIP_CASES=1 reliability_round_trip_tests --gtest_filter='*Shard/0'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "polyhedron_parser.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/export/writers.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::reliability {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int default_cases_per_shard = 15;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int default_cases_per_shard = 15;
#else
constexpr int default_cases_per_shard = 100;
#endif
#else
constexpr int default_cases_per_shard = 100;
#endif
constexpr int shards = 10;
constexpr std::uint64_t default_seed = 20261122;

std::uint64_t environment_number(const char* name, std::uint64_t fallback) {
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    return std::strtoull(text, nullptr, 10);
}

// One random case: everything needed to rebuild it from its seed.
struct Case {
    std::uint64_t seed = 0;
    std::vector<NurbsCurve> pieces;
    Vec3 axis_point, axis_dir;
    double angle = 360;
    double scale = 1;
    bool closed = true;
    std::string summary;  // what was drawn, for failure messages
};

class CaseGenerator {
public:
    // Weights are drawn log-uniformly from [10^-weight_exponent, 10^weight_exponent].
    CaseGenerator(std::uint64_t seed, double weight_exponent)
        : random_(seed), seed_(seed), weight_exponent_(weight_exponent) {}

    Case make() {
        Case c;
        c.seed = seed_;
        c.scale = std::pow(10.0, uniform(-4, 4));
        c.closed = uniform(0, 1) < 0.6;
        c.angle = uniform(0, 1) < 0.5 ? 360.0 : uniform(5, 355);
        // A random rigid placement of the (radial, axial) half-plane: axis through axis_point along
        // axis_dir, radial direction e perpendicular to it.
        c.axis_point = Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)} * (c.scale * uniform(0, 3));
        c.axis_dir = Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        if (norm(c.axis_dir) < 0.1) c.axis_dir = {0, 0, 1};
        const Frame frame = frame_from_axis(c.axis_point, c.axis_dir);
        const double turn = uniform(0, 2 * std::numbers::pi);
        const Vec3 e = frame.x_axis * std::cos(turn) + frame.y_axis * std::sin(turn);
        const Vec3 d = frame.z_axis;
        const auto place = [&](double r, double h) { return c.axis_point + e * (r * c.scale) + d * (h * c.scale); };

        // The profile is star-shaped about a center in the (r, h) half-plane: piece k lies in the wedge
        // between the rays at angles a_k and a_{k+1} (each under 150 degrees), its interior control points
        // strictly inside the wedge at increasing angles. Then every line through the center crosses the
        // control polygon once, so by variation diminishing the piece crosses it once: no piece loops, and
        // pieces in different wedges meet only at their shared ends. A ring keeps its distance from the
        // axis (r >= gap > 0; gap as small as 1e-3 of its size); a dome has its center on the axis and runs
        // from angle -90 to 90 degrees, touching the axis only at its two ends.
        const double gap = std::pow(10.0, uniform(-3, 0));
        const double radius = 1.0;
        const double center_r = c.closed ? gap + radius * 1.6 : 0.0;
        const double center_h = uniform(-2, 2);
        const int count = c.closed ? static_cast<int>(uniform(3, 6.999)) : static_cast<int>(uniform(2, 4.999));
        const double total = c.closed ? 2 * std::numbers::pi : std::numbers::pi;
        const double start = c.closed ? uniform(0, 2 * std::numbers::pi) : -std::numbers::pi / 2;
        // Even out wedges so that none reaches 150 degrees. Halfway to equal wedges bounds a dome's wedges
        // (180 degrees in all) by 135 degrees, but not a ring's: its largest wedge can reach
        // 360 (1 + 1/count) / 2 > 180 degrees, and a piece in a wedge over 180 degrees can cross the other
        // pieces (seed 20263063: a straight piece in a 222-degree wedge cut through a cubic; revolve does
        // not check self-intersection). So redraw until every wedge is under 150 degrees; a draw that
        // already is keeps its random sequence, and with it its case.
        std::vector<double> cuts;
        const double max_wedge = 150.0 / 180.0 * std::numbers::pi;
        do {
            cuts.assign(1, 0.0);
            for (int k = 1; k < count; ++k) cuts.push_back(uniform(0, 1));
            std::sort(cuts.begin(), cuts.end());
            cuts.push_back(1);
            for (int k = 0; k <= count; ++k) cuts[k] = 0.5 * cuts[k] + 0.5 * static_cast<double>(k) / count;
        } while ([&] {
            for (int k = 0; k < count; ++k)
                if (total * (cuts[k + 1] - cuts[k]) >= max_wedge) return true;
            return false;
        }());
        const auto ray_radius = [&] { return radius * uniform(0.4, 1.5); };
        std::vector<double> boundary_radius;
        for (int k = 0; k <= count; ++k) boundary_radius.push_back(ray_radius());
        if (c.closed) boundary_radius.back() = boundary_radius.front();
        const auto polar = [&](double angle, double rho) {
            return place(center_r + rho * std::cos(angle), center_h + rho * std::sin(angle));
        };

        std::ostringstream summary;
        summary << (c.closed ? "ring" : "dome") << " of " << count << " pieces, scale " << c.scale << ", gap " << gap
                << ", angle " << c.angle << ":";
        for (int k = 0; k < count; ++k) {
            const double a0 = start + total * cuts[k], a1 = start + total * cuts[k + 1];
            const bool nurbs = uniform(0, 1) < 0.5;
            const int degree = static_cast<int>(uniform(1, 3.999));
            const int interior_knots = nurbs ? static_cast<int>(uniform(0, 2.999)) : 0;
            const int n = degree + 1 + interior_knots;  // control points
            std::vector<Vec3> points;
            std::vector<double> angles;
            for (int i = 1; i + 1 < n; ++i) angles.push_back(uniform(0.05, 0.95));
            std::sort(angles.begin(), angles.end());
            points.push_back(polar(a0, boundary_radius[k]));
            for (double t : angles) points.push_back(polar(a0 + (a1 - a0) * t, ray_radius()));
            points.push_back(polar(a1, boundary_radius[k + 1]));
            std::vector<double> weights;
            const bool rational = uniform(0, 1) < 0.7;
            for (int i = 0; i < n; ++i) weights.push_back(rational ? std::pow(10.0, uniform(-weight_exponent_, weight_exponent_)) : 1.0);
            if (!c.closed) {
                // The dome's ends sit exactly on the axis.
                if (k == 0) points.front() = place(0, center_h - boundary_radius[0]);
                if (k + 1 == count) points.back() = place(0, center_h + boundary_radius[count]);
            }
            if (!nurbs) {
                c.pieces.push_back(NurbsCurve::from_bezier(BezierCurve(points, weights)));
                summary << " bezier(" << degree << (rational ? ", rational" : "") << ")";
            } else {
                std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
                std::vector<double> inner;
                for (int i = 0; i < interior_knots; ++i) inner.push_back(uniform(0.1, 0.9));
                std::sort(inner.begin(), inner.end());
                for (double u : inner) knots.push_back(u);
                knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), 1.0);
                const double a = uniform(-5, 5), b = a + std::pow(10.0, uniform(-2, 2));
                for (double& u : knots) u = a + (b - a) * u;
                c.pieces.emplace_back(degree, knots, points, weights);
                summary << " nurbs(" << degree << ", " << interior_knots << " knots" << (rational ? ", rational" : "") << ")";
            }
        }
        if (uniform(0, 1) < 0.5) {
            // The same profile backwards: revolve must orient the solid outward either way.
            std::vector<NurbsCurve> reversed;
            for (auto it = c.pieces.rbegin(); it != c.pieces.rend(); ++it) reversed.push_back(it->reversed());
            c.pieces = std::move(reversed);
            summary << " (reversed)";
        }
        c.summary = summary.str();
        return c;
    }

private:
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(random_); }
    std::mt19937_64 random_;
    std::uint64_t seed_;
    double weight_exponent_;
};

// Runs every stage of one case; returns "" when all pass, else what failed.
std::string run_case(const Case& c, int index) {
    const bool expensive = index % 10 == 0;
    const bool deviation = expensive;
    std::ostringstream failures;
    try {
        const Profile profile(c.pieces);
        if (profile.is_closed() != c.closed) failures << "profile closure is " << profile.is_closed() << "; ";
        const Solid solid = revolve(profile, c.axis_point, c.axis_dir, c.angle);
        const double volume = solid.volume();
        const double area = solid.area();
        if (!(volume > 0) || !std::isfinite(volume)) failures << "volume " << volume << "; ";

        if (expensive) {
            occt::CheckOptions options;
            options.grid = 12;
            options.bop_analysis = false;  // not asserted here, and minutes on some extreme weights
            const occt::CheckReport report = occt::check(solid, options);
            if (!report.valid) failures << "OCCT: not valid; ";
            if (!report.closed) failures << "OCCT: not closed; ";
            // OCCT's own volume and area (BRepGProp) are too inaccurate on B-spline faces for the check's
            // 1e-6 limit (SETUP-NOTES): only validity and the evaluation comparison are asserted here.
            if (!(report.max_deviation <= 1e-9 * report.size))
                failures << "OCCT evaluates the converted geometry " << report.max_deviation << " away from ours; ";
        }

        const double size = solid.bounding_box().diagonal();
        const double tolerance = size * 4e-3;
        const Mesh mesh = tessellate(solid, tolerance);
        for (const auto& t : mesh.triangles)
            for (auto i : t)
                if (i >= mesh.vertices.size()) {
                    failures << "triangle index out of range; ";
                    return failures.str();
                }
        if (!mesh.is_closed()) failures << "mesh not closed; ";
        // The mesh lies within the tolerance of the surface, so its volume is within about
        // tolerance x area of the exact one.
        if (!(std::abs(mesh.volume() - volume) <= tolerance * area * 1.01 + 1e-9 * std::abs(volume)))
            failures << "mesh volume " << mesh.volume() << " vs exact " << volume << "; ";

        exporter::MeshCheckOptions checks;
        checks.check_self_intersections = expensive;
        const exporter::MeshReport report = exporter::check_mesh(mesh, checks);
        if (!report.ok()) {
            failures << "CGAL:";
            for (const auto& p : report.problems) failures << " [" << p << "]";
            failures << "; ";
        }

        if (deviation) {
            DeviationOptions options;
            options.samples_per_edge = 3;
            const double measured = max_deviation(solid, mesh, options);
            const double allowed = tolerance * (1 + 1e-6);
            if (!(measured <= allowed))
                failures << "max_deviation " << measured << " > " << allowed << " (tolerance " << tolerance << "); ";
        }

        std::ostringstream text;
        exporter::write_openscad(mesh, text);
        const ParsedPolyhedron parsed = parse_polyhedron(text.str());
        std::string why;
        if (!same_mesh_bits(mesh, parsed.mesh, why)) failures << "OpenSCAD text does not read back: " << why << "; ";
    } catch (const std::exception& e) {
        failures << "threw: " << e.what();
    }
    return failures.str();
}

void run_shard(int shard, double weight_exponent) {
    const std::uint64_t base = environment_number("RATBEZ_ROUND_TRIP_SEED", default_seed);
    const int per_shard = static_cast<int>(environment_number("RATBEZ_ROUND_TRIP_CASES", default_cases_per_shard));
    int failed = 0;
    for (int k = 0; k < per_shard; ++k) {
        const int index = shard * per_shard + k;
        const std::uint64_t seed = base + static_cast<std::uint64_t>(index);
        const Case c = CaseGenerator(seed, weight_exponent).make();
        const std::string failure = run_case(c, index);
        if (!failure.empty()) {
            ++failed;
            ADD_FAILURE() << "round trip failed: seed " << seed << " (case " << index << ", weights within 10^+-"
                          << weight_exponent << "): " << c.summary << "\n  " << failure;
            if (failed >= 10) break;  // enough to go on; the rest of the shard would repeat it
        }
    }
}

class RoundTrip : public ::testing::TestWithParam<int> {};

// The full weight range, [1e-3, 1e3], every stage, max_deviation within the tolerance itself.
// What it found, all fixed in the kernel (each seed is replayed with every stage by FoundSeed below):
//  - revolve's and Face::planar's area checks used a fixed-depth rule that missed edges whose weights
//    crowd them into a sliver of their parameter range (seed 20261421: "outer loop must run
//    counterclockwise"); they now use the adaptive cubature of properties.cpp;
//  - max_deviation overestimated up to 10x (seeds 20261122, 20261232, 20261262, 20261332, 20261372,
//    20261482): its seeds and Newton starts sat at uniform parameters, away from the crowded geometry;
//    they now go per weight-certified cell;
//  - and again in cases 3000-9999 (seeds 20266302, 20266752, 20268472, 20268482, 20268692, 20269892):
//    Newton stopped on a cell's edge, a shared damping term swamped a partial 1e8 times smaller than the
//    other, curve Newton gave up halving too soon in spans that turn half a circle within 1e-6, and the
//    planar caps' side test took the wrong curve at a corner; all meter errors, the meshes were good;
//  - CGAL found self-intersections (seeds 20261322, 20261342 and 9 more in the first 1000 cases): a thin
//    row along a profile corner, closed by a zipper, sagged through the neighbouring face; such rows
//    now take the neighbour's parameter lines;
//  - OCCT rejected seed 20261992 (BRepCheck_InvalidCurveOnSurface): the converted tolerance of 1e-12 of
//    the size was below OCCT's own evaluation differences;
//  - OCCT rejected seed 20264282 (BRepCheck_SelfIntersectingWire on both caps): a span with end weights
//    2.4e-3 and 23 crawled at 2e-10 for most of its parameter, and OCCT's 2D intersector took two
//    parameters 1e-8 apart for a self-intersection; Profile now puts such pieces in normal form.
// (At weights [0.5, 2], seeds 20261122, 20261302, 20262082 once measured up to 27x: max_deviation's
// point inversion settled in the wrong knot span or misjudged a polyline corner of a planar cap; seeds
// 20261182, 20261752 were real, up to 15%: the tessellator's cell check sampled too few points.)
TEST_P(RoundTrip, Shard) { run_shard(GetParam(), 3.0); }

// Every seed that ever failed above, with every stage (as case index 0), so that each stays covered in
// the sanitizer build too, whose shards run fewer cases. One test per seed: under the sanitizers a seed
// takes about 4 s, and ctest runs them side by side.
class FoundSeed : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(FoundSeed, PassesEveryStage) {
    const Case c = CaseGenerator(GetParam(), 3.0).make();
    const std::string failure = run_case(c, 0);
    EXPECT_TRUE(failure.empty()) << "seed " << GetParam() << ": " << c.summary << "\n  " << failure;
}

INSTANTIATE_TEST_SUITE_P(RoundTrip, FoundSeed,
                         ::testing::Values(20261122, 20261232, 20261262, 20261322, 20261332, 20261342, 20261372,
                                           20261421, 20261482, 20261992, 20264282, 20266302, 20266752, 20268472,
                                           20268482, 20268692, 20269892),
                         [](const ::testing::TestParamInfo<std::uint64_t>& info) { return std::to_string(info.param); });

INSTANTIATE_TEST_SUITE_P(Reliability, RoundTrip, ::testing::Range(0, shards));

}  // namespace
}  // namespace ratbez::reliability

// Lofts and sweeps, ours against OpenCASCADE's on the same input in the same run, single-threaded:
//   loft/<shape>/ours           ratbez::loft (skinning, The NURBS Book 10.3; ruled: straight rulings)
//   loft/<shape>/ThruSections   BRepOffsetAPI_ThruSections(isSolid, ruled) through the same profiles' wires
//   sweep/<shape>/ours          ratbez::sweep (rotation-minimising frame; exact along arcs, else a NURBS
//                               measured within the tolerance)
//   sweep/<shape>/MakePipeShell BRepOffsetAPI_MakePipeShell, corrected Frenet, made solid, the same tolerance
// Counters (computed once, outside the timing): `valid` (BRepCheck on the OCCT shape: ours converted),
// `volume_error` (relative, against the closed form: the loft's cross-sections, Pappus's area x length for
// a tube), `control_points` (of the B-spline faces), and for the tubes `deviation` (the largest distance of
// the faces from the true sweep: | distance to the path - r | on a 61 x 61 grid of every face).
// Shapes: loft/circles (radii 1, 2, 1 at z = 0, 1, 2; V = 86 pi / 15), loft/circles_ruled (two frustums,
// 14 pi / 3), sweep/torus (a circle r = 0.5 along a circle R = 2), sweep/helix_1e-4 and sweep/helix_1e-6
// (r = 0.3 along three turns of a helix of radius 2, pitch 0.8 pi, at that tolerance).

#include <benchmark/benchmark.h>

#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "modelling_test_support.hpp"
#include "ratbez/closest_point.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/loft.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/occt/reference_modelling.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/sweep.hpp"

namespace ratbez::bench {
namespace {

constexpr double pi = std::numbers::pi;

// The largest | distance to the path - r | over 61 x 61 grids of the surfaces, offset from the knots
// (interval ends are exact, so a grid on them would see nothing): how far a tube of radius r (its
// section centred on the path, normal to it) strays from the true sweep.
double tube_deviation(const std::vector<NurbsSurface>& surfaces, const NurbsCurve& path, double r) {
    const CurveProjector onto(path);
    double worst = 0;
    for (const NurbsSurface& s : surfaces) {
        const Interval du = s.domain_u(), dv = s.domain_v();
        for (int i = 0; i < 61; ++i)
            for (int j = 0; j < 61; ++j) {
                const Vec3 p = s.point(du.min + du.width() * (i + 0.382) / 61, dv.min + dv.width() * (j + 0.382) / 61);
                worst = std::max(worst, std::abs(onto.closest_point(p).distance - r));
            }
    }
    return worst;
}

std::vector<NurbsSurface> our_surfaces(const Solid& solid) {
    std::vector<NurbsSurface> out;
    for (const Face& f : solid.faces())
        if (f.kind() == Face::Kind::surface) out.push_back(f.surface());
    return out;
}

std::vector<NurbsSurface> occt_surfaces(const TopoDS_Shape& shape) {
    std::vector<NurbsSurface> out;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        const Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(it.Current())));
        if (!s.IsNull()) out.push_back(occt::from_occt(s));
    }
    return out;
}

struct Facts {
    double valid, volume_error, control_points, deviation;
};

void run(benchmark::State& state, const std::function<void()>& build, const Facts& facts, bool tube) {
    for (auto _ : state) build();
    state.counters["valid"] = facts.valid;
    state.counters["volume_error"] = facts.volume_error;
    state.counters["control_points"] = facts.control_points;
    if (tube) state.counters["deviation"] = facts.deviation;
}

struct Case {
    std::string kind, shape;
    std::function<Solid()> ours;
    std::function<TopoDS_Shape()> theirs;
    double exact_volume;
    std::string occt_name;
    // For tubes: the path and radius the deviation is measured against.
    std::optional<NurbsCurve> path;
    double radius = 0;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    const std::vector<Profile> circles{Profile({circle(1.0)}), Profile({circle(2.0, {0, 0, 1})}), Profile({circle(1.0, {0, 0, 2})})};
    out.push_back({"loft", "circles", [circles] { return loft(circles); },
                   [circles] { return occt::thru_sections(circles, false); }, 86 * pi / 15, "ThruSections", {}, 0});
    out.push_back({"loft", "circles_ruled", [circles] { return loft(circles, 3, true); },
                   [circles] { return occt::thru_sections(circles, true); }, 14 * pi / 3, "ThruSections", {}, 0});
    const Profile tube({circle(0.5, {2, 0, 0}, {0, 1, 0})});
    out.push_back({"sweep", "torus", [tube] { return sweep(tube, circle(2.0)); },
                   [tube] { return occt::pipe_shell(tube, circle(2.0)); }, 2 * pi * pi * 2 * 0.25, "MakePipeShell",
                   circle(2.0), 0.5});
    const NurbsCurve path = test::helix_path(2.0, 0.4, 12);
    const double r = 0.3;
    const Profile section({circle(r, path.start_point(), path.derivative(path.domain().min))});
    const double pappus = pi * r * r * test::curve_length(path);
    for (const double tolerance : {1e-4, 1e-6}) {
        const std::string name = tolerance == 1e-4 ? "helix_1e-4" : "helix_1e-6";
        out.push_back({"sweep", name, [section, path, tolerance] { return sweep(section, path, tolerance); },
                       [section, path, tolerance] { return occt::pipe_shell(section, path, tolerance); }, pappus,
                       "MakePipeShell", path, r});
    }
    return out;
}

}  // namespace

void register_benchmarks() {
    static const std::vector<Case> all = cases();
    for (const Case& c : all) {
        const Solid ours = c.ours();
        const TopoDS_Shape theirs = c.theirs();
        const occt::ShapeFacts occt_facts = occt::shape_facts(theirs);
        const occt::ShapeFacts our_facts = occt::shape_facts(occt::to_occt(ours));
        const bool tube = c.path.has_value();
        const Facts mine{our_facts.valid ? 1.0 : 0.0, std::abs(enclosed_volume(ours) - c.exact_volume) / c.exact_volume,
                         static_cast<double>(occt::control_points(ours)),
                         tube ? tube_deviation(our_surfaces(ours), *c.path, c.radius) : 0.0};
        const Facts others{occt_facts.valid ? 1.0 : 0.0, std::abs(occt_facts.volume - c.exact_volume) / c.exact_volume,
                           static_cast<double>(occt_facts.control_points),
                           tube ? tube_deviation(occt_surfaces(theirs), *c.path, c.radius) : 0.0};
        const Case* k = &c;
        benchmark::RegisterBenchmark(benchmark_name({c.kind, c.shape, "ours"}).c_str(),
                                     [k, mine, tube](benchmark::State& s) { run(s, [k] { benchmark::DoNotOptimize(k->ours()); }, mine, tube); })
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(benchmark_name({c.kind, c.shape, c.occt_name}).c_str(),
                                     [k, others, tube](benchmark::State& s) {
                                         run(s, [k] { benchmark::DoNotOptimize(k->theirs()); }, others, tube);
                                     })
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace ratbez::bench

// Surface evaluation on an n x n parameter grid, ours against OpenCASCADE in the same run, single-threaded:
//   ours           ratbez::evaluate_grid (the AVX2 + FMA kernels where the CPU has them)
//   ours_portable  the same with the baseline x86-64 (SSE2) kernels every machine runs
//   GeomAdaptor_Surface   OCCT's cached evaluator (BSplSLib_Cache: span polynomials rebuilt on a span change)
//   Geom_BSplineSurface   OCCT's direct D0 / D1
// on the converted surface (ratbez::occt::to_occt: same knots, poles and weights, so the same parameters
// give the same points). D0 = points, D1 = points and first partials. Every OCCT result is stored into a
// preallocated array, as ours is, so both pay the same memory traffic. Counter `points_per_second`; the
// OCCT rows also report `max_difference`, the largest distance between their points and ours (a check
// that both computed the same thing).
//
// Names: eval/<surface>/<D0|D1>/<implementation>/<n>; the surfaces come from bench_shapes.hpp.

#include <benchmark/benchmark.h>

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "bench_shapes.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez::bench {
namespace {

constexpr int grid_sizes[] = {250, 500, 1000};

struct Case {
    NurbsSurface surface;
    Handle(Geom_BSplineSurface) occt;
    std::vector<double> us, vs;
};

void set_rate(benchmark::State& state, std::size_t points) {
    state.counters["points_per_second"] =
        benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["points"] = static_cast<double>(points);
}

void ours(benchmark::State& state, const Case& c, GridOutput output, GridKernels kernels) {
    select_grid_kernels(kernels);
    SurfaceGrid grid;
    evaluate_grid(c.surface, c.us, c.vs, output, grid);  // sizes the output once, as a caller reusing it would
    for (auto _ : state) {
        evaluate_grid(c.surface, c.us, c.vs, output, grid);
        benchmark::DoNotOptimize(grid.points.x.data());
        benchmark::ClobberMemory();
    }
    select_grid_kernels(GridKernels::best);
    set_rate(state, c.us.size() * c.vs.size());
}

// The largest distance between OCCT's points and ours on the same grid.
double difference_from_ours(const Case& c, const std::vector<gp_Pnt>& points) {
    const SurfaceGrid grid = evaluate_grid(c.surface, c.us, c.vs);
    double worst = 0;
    for (std::size_t k = 0; k < points.size(); ++k)
        worst = std::max(worst, distance(grid.points[k], occt::from_occt(points[k])));
    return worst;
}

template <class Evaluator>
void occt_d0(benchmark::State& state, const Case& c, const Evaluator& evaluator) {
    std::vector<gp_Pnt> points(c.us.size() * c.vs.size());
    for (auto _ : state) {
        gp_Pnt* out = points.data();
        for (double u : c.us)
            for (double v : c.vs) evaluator.D0(u, v, *out++);
        benchmark::DoNotOptimize(points.data());
        benchmark::ClobberMemory();
    }
    set_rate(state, points.size());
    state.counters["max_difference"] = difference_from_ours(c, points);
}

template <class Evaluator>
void occt_d1(benchmark::State& state, const Case& c, const Evaluator& evaluator) {
    const std::size_t size = c.us.size() * c.vs.size();
    std::vector<gp_Pnt> points(size);
    std::vector<gp_Vec> du(size), dv(size);
    for (auto _ : state) {
        std::size_t k = 0;
        for (double u : c.us)
            for (double v : c.vs) {
                evaluator.D1(u, v, points[k], du[k], dv[k]);
                ++k;
            }
        benchmark::DoNotOptimize(points.data());
        benchmark::ClobberMemory();
    }
    set_rate(state, size);
    state.counters["max_difference"] = difference_from_ours(c, points);
}

}  // namespace

void register_benchmarks() {
    benchmark::AddCustomContext("ratbez_grid_kernels", grid_kernels_name());

    // Cases live for the whole run (the benchmarks keep references).
    static std::vector<Case> cases;
    static std::vector<std::string> names;
    const auto surfaces = evaluation_surfaces();
    cases.reserve(std::size(grid_sizes) * surfaces.size());
    for (const NamedSurface& named : surfaces)
        for (int n : grid_sizes) {
            const std::size_t count = static_cast<std::size_t>(n);
            cases.push_back({named.surface, occt::to_occt(named.surface),
                             uniform_parameters(named.surface.domain_u(), count),
                             uniform_parameters(named.surface.domain_v(), count)});
            const Case* c = &cases.back();
            const std::string size = std::to_string(n);
            for (const char* order : {"D0", "D1"}) {
                const bool d1 = std::string_view(order) == "D1";
                const GridOutput output = d1 ? GridOutput::partials : GridOutput::points;
                auto name = [&](const char* implementation) {
                    return benchmark_name({"eval", named.name, order, implementation, size});
                };
                benchmark::RegisterBenchmark(name("ours").c_str(), [c, output](benchmark::State& s) {
                    ours(s, *c, output, GridKernels::best);
                })->Unit(benchmark::kMillisecond);
                benchmark::RegisterBenchmark(name("ours_portable").c_str(),
                                             [c, output](benchmark::State& s) {
                                                 ours(s, *c, output, GridKernels::portable);
                                             })->Unit(benchmark::kMillisecond);
                benchmark::RegisterBenchmark(name("GeomAdaptor_Surface").c_str(),
                                             [c, d1](benchmark::State& s) {
                                                 const GeomAdaptor_Surface adaptor(c->occt);
                                                 if (d1) occt_d1(s, *c, adaptor);
                                                 else occt_d0(s, *c, adaptor);
                                             })->Unit(benchmark::kMillisecond);
                benchmark::RegisterBenchmark(name("Geom_BSplineSurface").c_str(),
                                             [c, d1](benchmark::State& s) {
                                                 if (d1) occt_d1(s, *c, *c->occt);
                                                 else occt_d0(s, *c, *c->occt);
                                             })->Unit(benchmark::kMillisecond);
            }
        }
}

}  // namespace ratbez::bench

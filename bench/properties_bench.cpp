// Volume and area of a solid, ours against OpenCASCADE's global properties on the same converted solid,
// in the same run, single-threaded, on shapes whose exact values are known in closed form:
//   ours           enclosed_volume / surface_area (properties.hpp: weight certificate, then adaptive
//                  Gauss–Legendre to a relative 1e-14)
//   BRepGProp      BRepGProp::VolumeProperties / SurfaceProperties, OCCT's fixed Gauss rule per face
//   BRepGProp_eps  the same with Eps = 1e-12, OCCT's adaptive integration to that relative precision
// Names: <volume|area>/<shape>/<implementation>; counter `relative_error` against the closed form, so the
// table shows what each answer is worth next to what it costs.

#include <benchmark/benchmark.h>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/properties.hpp"

namespace ratbez::bench {
namespace {

constexpr double pi = std::numbers::pi;

struct Measured {
    std::string name;
    Solid solid;
    double volume, area;
};

// A quadrilateral in the xz half-plane revolved about z, its edges rational lines with weights 1e-3 and
// 1e3 (still the straight edges, at very uneven speed): Pappus gives V = 2π ∫∫ ρ dA, and every edge
// sweeps a frustum of area π (ρ_a + ρ_b) |b - a|.
Measured weighted_polygon_ring() {
    const std::vector<Vec3> polygon{{1, 0, 0}, {3, 0, 0.5}, {2.5, 0, 2}, {1.5, 0, 1.5}};
    std::vector<NurbsCurve> pieces;
    double moment = 0, area = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % polygon.size()];
        const std::vector<double> weights = i % 2 == 0 ? std::vector<double>{1e-3, 1e3} : std::vector<double>{1e3, 1e-3};
        pieces.push_back(NurbsCurve::from_bezier(BezierCurve({a, b}, weights)));
        moment += (a.x + b.x) * (a.x * b.z - b.x * a.z) / 6;
        area += pi * (a.x + b.x) * distance(a, b);
    }
    return {"weighted_polygon_ring", revolve(Profile(pieces)), 2 * pi * std::abs(moment), area};
}

// A star of 1000 straight sides extruded by 1: polynomial faces only. V = its area, A = 2 V + perimeter.
// The references add up in long double: summed naively in double, 1000 terms drift by 1e-14 of the total,
// more than the answers being compared.
Measured extruded_star() {
    const int sides = 1000;
    std::vector<Vec3> star;
    for (int k = 0; k < sides; ++k) {
        const double radius = k % 2 == 0 ? 1.0 : 0.8, angle = 2 * pi * k / sides;
        star.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    std::vector<NurbsCurve> pieces;
    long double area = 0, perimeter = 0;
    for (int k = 0; k < sides; ++k) {
        const Vec3& a = star[static_cast<std::size_t>(k)];
        const Vec3& b = star[static_cast<std::size_t>((k + 1) % sides)];
        pieces.push_back(line_segment(a, b));
        area += (static_cast<long double>(a.x) * b.y - static_cast<long double>(b.x) * a.y) / 2;
        perimeter += std::hypot(static_cast<long double>(b.x) - a.x, static_cast<long double>(b.y) - a.y);
    }
    return {"extruded_star_1000", extrude(Profile(pieces), {0, 0, 1}, 1.0), static_cast<double>(area),
            static_cast<double>(2 * area + perimeter)};
}

std::vector<Measured> shapes() {
    const double R = 3, r = 1, r2 = 0.5, h = 2;
    std::vector<Measured> out;
    out.push_back({"sphere", sphere(1.0), 4 * pi / 3, 4 * pi});
    out.push_back({"torus", torus(R, r), 2 * pi * pi * R * r * r, 4 * pi * pi * R * r});
    out.push_back({"frustum", cone(r, r2, h), pi * h / 3 * (r * r + r * r2 + r2 * r2),
                   pi * (r + r2) * std::hypot(r - r2, h) + pi * (r * r + r2 * r2)});
    out.push_back(weighted_polygon_ring());
    out.push_back(extruded_star());
    return out;
}

void measure(benchmark::State& state, const std::function<double()>& compute, double exact) {
    double value = 0;
    for (auto _ : state) benchmark::DoNotOptimize(value = compute());
    state.counters["relative_error"] = std::abs(value - exact) / exact;
}

double occt_volume(const TopoDS_Shape& shape, double eps) {
    GProp_GProps props;
    if (eps > 0)
        BRepGProp::VolumeProperties(shape, props, eps, Standard_True);
    else
        BRepGProp::VolumeProperties(shape, props, Standard_True);
    return props.Mass();
}

double occt_area(const TopoDS_Shape& shape, double eps) {
    GProp_GProps props;
    if (eps > 0)
        BRepGProp::SurfaceProperties(shape, props, eps);
    else
        BRepGProp::SurfaceProperties(shape, props);
    return props.Mass();
}

}  // namespace

void register_benchmarks() {
    static const std::vector<Measured> all = shapes();
    static std::vector<TopoDS_Solid> converted;
    for (const Measured& m : all) converted.push_back(occt::to_occt(m.solid));
    for (std::size_t k = 0; k < all.size(); ++k) {
        const Measured* m = &all[k];
        const TopoDS_Shape* shape = &converted[k];
        for (const bool volume : {true, false}) {
            const std::string kind = volume ? "volume" : "area";
            const double exact = volume ? m->volume : m->area;
            const std::function<double()> ours = volume ? std::function<double()>([m] { return enclosed_volume(m->solid); })
                                                        : std::function<double()>([m] { return surface_area(m->solid); });
            benchmark::RegisterBenchmark(benchmark_name({kind, m->name, "ours"}).c_str(),
                                         [ours, exact](benchmark::State& s) { measure(s, ours, exact); })
                ->Unit(benchmark::kMicrosecond);
            for (const double eps : {0.0, 1e-12}) {
                const std::function<double()> theirs = [volume, shape, eps] {
                    return volume ? occt_volume(*shape, eps) : occt_area(*shape, eps);
                };
                benchmark::RegisterBenchmark(benchmark_name({kind, m->name, eps > 0 ? "BRepGProp_eps" : "BRepGProp"}).c_str(),
                                             [theirs, exact](benchmark::State& s) { measure(s, theirs, exact); })
                    ->Unit(benchmark::kMicrosecond);
            }
        }
    }
}

}  // namespace ratbez::bench

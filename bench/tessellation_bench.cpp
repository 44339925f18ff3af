// Tessellation of whole solids, ours against OpenCASCADE's BRepMesh in the same run, single-threaded:
//   ours      ratbez::tessellate(solid, tolerance)
//   BRepMesh  BRepMesh_IncrementalMesh on the converted solid (ratbez::occt::convert) with
//             IMeshTools_Parameters{Deflection = tolerance, Angle = 0.5 rad, Relative = false,
//             InParallel = false}; the triangulation is removed (BRepTools::Clean, not timed) before
//             every run, so each iteration meshes from scratch.
// Tolerance = 1e-2, 1e-3 and 1e-4 of the solid's size (its bounding-box diagonal, brep.hpp).
// Counters: `triangles`; `deviation`, the largest distance of the mesh from the exact surface measured by
// ratbez::max_deviation for BOTH meshes (BRepMesh's converted to a ratbez::Mesh, face by face with its
// location; its vertices are not welded across faces, which does not matter for a distance);
// `deviation_over_tolerance` (<= 1 means the tolerance was met); `triangles_per_second`.
//
// Names: tess/<solid>/<ours|BRepMesh>/<tolerance exponent>, e.g. tess/sphere/ours/3 for 1e-3.
//
// Issue 17's sphere: bound/sphere_r10_tol0.01/ours meshes a sphere of radius 10 at tolerance 0.01 and adds
// the counter `bound`, the fewest triangles any mesh with its vertices on the sphere needs,
// 4 pi r^2 / ((3 sqrt 3 / 4) 2 r tol) = 4,837 (equilateral triangles whose circumcircle's sagitta is the
// tolerance); ours straddle the sphere and may go below it.

#include <benchmark/benchmark.h>

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <TopAbs_Orientation.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::bench {
namespace {

constexpr int tolerance_exponents[] = {2, 3, 4};

// BRepMesh's triangulation of every face as one ratbez::Mesh: nodes moved by the face's location, and
// triangles flipped on REVERSED faces so they stay outward (ours are all FORWARD, topology.hpp).
Mesh mesh_from_occt(const occt::ConvertedSolid& converted) {
    Mesh mesh;
    for (const TopoDS_Face& face : converted.faces) {
        TopLoc_Location location;
        const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
        if (triangulation.IsNull()) continue;
        const gp_Trsf transformation = location.Transformation();
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int k = 1; k <= triangulation->NbNodes(); ++k)
            mesh.vertices.push_back(occt::from_occt(triangulation->Node(k).Transformed(transformation)));
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (int k = 1; k <= triangulation->NbTriangles(); ++k) {
            int a = 0, b = 0, c = 0;
            triangulation->Triangle(k).Get(a, b, c);
            if (reversed) std::swap(b, c);
            mesh.triangles.push_back({base + static_cast<std::uint32_t>(a - 1), base + static_cast<std::uint32_t>(b - 1),
                                      base + static_cast<std::uint32_t>(c - 1)});
        }
    }
    return mesh;
}

void report(benchmark::State& state, const Solid& solid, const Mesh& mesh, double tolerance) {
    const double deviation = max_deviation(solid, mesh);
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    state.counters["triangles_per_second"] = benchmark::Counter(static_cast<double>(mesh.triangles.size()),
                                                                benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tolerance"] = tolerance;
    state.counters["deviation"] = deviation;
    state.counters["deviation_over_tolerance"] = deviation / tolerance;
}

void ours(benchmark::State& state, const Solid& solid, double tolerance) {
    Mesh mesh;
    for (auto _ : state) {
        mesh = tessellate(solid, tolerance);
        benchmark::DoNotOptimize(mesh.triangles.data());
    }
    report(state, solid, mesh, tolerance);
}

void brepmesh(benchmark::State& state, const Solid& solid, double tolerance) {
    const occt::ConvertedSolid converted = occt::convert(solid);
    IMeshTools_Parameters parameters;
    parameters.Deflection = tolerance;
    parameters.Angle = 0.5;
    parameters.Relative = Standard_False;
    parameters.InParallel = Standard_False;
    for (auto _ : state) {
        state.PauseTiming();
        BRepTools::Clean(converted.solid);
        state.ResumeTiming();
        BRepMesh_IncrementalMesh mesher(converted.solid, parameters);
        benchmark::DoNotOptimize(mesher.IsDone());
    }
    report(state, solid, mesh_from_occt(converted), tolerance);
}

}  // namespace

void register_benchmarks() {
    benchmark::RegisterBenchmark("bound/sphere_r10_tol0.01/ours", [](benchmark::State& s) {
        static const Solid ball = sphere(10.0);
        const double radius = 10, tolerance = 0.01;
        ours(s, ball, tolerance);
        s.counters["bound"] = 4 * std::numbers::pi * radius * radius / ((3 * std::sqrt(3.0) / 4) * 2 * radius * tolerance);
    })->Unit(benchmark::kMillisecond);

    static std::vector<NamedSolid> solids = tessellation_solids();
    for (const NamedSolid& named : solids) {
        const Solid* solid = &named.solid;
        const double size = solid->bounding_box().diagonal();
        for (int exponent : tolerance_exponents) {
            const double tolerance = size * std::pow(10.0, -exponent);
            const std::string level = std::to_string(exponent);
            benchmark::RegisterBenchmark(benchmark_name({"tess", named.name, "ours", level}).c_str(),
                                         [solid, tolerance](benchmark::State& s) { ours(s, *solid, tolerance); })
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(benchmark_name({"tess", named.name, "BRepMesh", level}).c_str(),
                                         [solid, tolerance](benchmark::State& s) { brepmesh(s, *solid, tolerance); })
                ->Unit(benchmark::kMillisecond);
        }
    }
}

}  // namespace ratbez::bench

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
// Issue 24's corpus (tests/corpus/freecad/*.brep, solids made by FreeCAD): corpus/<model>/<ours|BRepMesh>/3,
// every solid of the file at 1e-3 of its size: ours tessellates the solid read by read_brep_all, BRepMesh
// meshes the file's own shape (analytic faces, as an OpenCASCADE user meshes it). `deviation` is the
// two-sided distance here (max_deviation and max_surface_to_mesh_distance, the larger), measured the same way
// on both meshes; `deviation_over_tolerance` the worst solid's.
//
// Issue 17's sphere: bound/sphere_r10_tol0.01/ours meshes a sphere of radius 10 at tolerance 0.01 and adds
// the counter `bound`, the fewest triangles any mesh with its vertices on the sphere needs,
// 4 pi r^2 / ((3 sqrt 3 / 4) 2 r tol) = 4,837 (equilateral triangles whose circumcircle's sagitta is the
// tolerance); ours straddle the sphere and may go below it.

#include <benchmark/benchmark.h>

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <TopAbs_Orientation.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "build_paths.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/occt/files.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::bench {
namespace {

constexpr int tolerance_exponents[] = {2, 3, 4};

// BRepMesh's triangulation of every face of `shape` as one ratbez::Mesh: nodes moved by the face's location,
// and triangles flipped on REVERSED faces so they stay outward.
Mesh mesh_from_occt(const TopoDS_Shape& shape) {
    Mesh mesh;
    for (TopExp_Explorer faces(shape, TopAbs_FACE); faces.More(); faces.Next()) {
        const TopoDS_Face& face = TopoDS::Face(faces.Current());
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

IMeshTools_Parameters brepmesh_parameters(double tolerance) {
    IMeshTools_Parameters parameters;
    parameters.Deflection = tolerance;
    parameters.Angle = 0.5;
    parameters.Relative = Standard_False;
    parameters.InParallel = Standard_False;
    return parameters;
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
    const IMeshTools_Parameters parameters = brepmesh_parameters(tolerance);
    for (auto _ : state) {
        state.PauseTiming();
        BRepTools::Clean(converted.solid);
        state.ResumeTiming();
        BRepMesh_IncrementalMesh mesher(converted.solid, parameters);
        benchmark::DoNotOptimize(mesher.IsDone());
    }
    report(state, solid, mesh_from_occt(converted.solid), tolerance);
}

// A corpus model: its solids as read_brep_all reads them, and the file's own TopoDS_Solids in the same order
// (TopExp_Explorer, as the reader walks them); the tolerance is 1e-3 of the largest solid's size.
struct CorpusModel {
    std::vector<Solid> solids;
    std::vector<TopoDS_Shape> shapes;
    double tolerance = 0;
};

CorpusModel corpus_model(const std::filesystem::path& file) {
    CorpusModel model;
    model.solids = occt::read_brep_all(file.string());
    TopoDS_Shape shape;
    BRep_Builder builder;
    BRepTools::Read(shape, file.string().c_str(), builder);
    for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next()) model.shapes.push_back(solids.Current());
    double size = 0;
    for (const Solid& solid : model.solids) size = std::max(size, solid.bounding_box().diagonal());
    model.tolerance = size * 1e-3;
    return model;
}

// The counters of a corpus run: triangles summed over the solids, the worst two-sided deviation.
void report_corpus(benchmark::State& state, const CorpusModel& model, const std::vector<Mesh>& meshes) {
    double deviation = 0, triangles = 0;
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        deviation = std::max({deviation, max_deviation(model.solids[k], meshes[k]),
                              max_surface_to_mesh_distance(model.solids[k], meshes[k])});
        triangles += static_cast<double>(meshes[k].triangles.size());
    }
    state.counters["solids"] = static_cast<double>(meshes.size());
    state.counters["triangles"] = triangles;
    state.counters["tolerance"] = model.tolerance;
    state.counters["deviation"] = deviation;
    state.counters["deviation_over_tolerance"] = deviation / model.tolerance;
}

void corpus_ours(benchmark::State& state, const CorpusModel& model) {
    std::vector<Mesh> meshes(model.solids.size());
    for (auto _ : state)
        for (std::size_t k = 0; k < meshes.size(); ++k) meshes[k] = tessellate(model.solids[k], model.tolerance);
    report_corpus(state, model, meshes);
}

void corpus_brepmesh(benchmark::State& state, const CorpusModel& model) {
    const IMeshTools_Parameters parameters = brepmesh_parameters(model.tolerance);
    for (auto _ : state)
        for (const TopoDS_Shape& shape : model.shapes) {
            state.PauseTiming();
            BRepTools::Clean(shape);
            state.ResumeTiming();
            BRepMesh_IncrementalMesh mesher(shape, parameters);
            benchmark::DoNotOptimize(mesher.IsDone());
        }
    std::vector<Mesh> meshes;
    for (const TopoDS_Shape& shape : model.shapes) meshes.push_back(mesh_from_occt(shape));
    report_corpus(state, model, meshes);
}

void register_corpus() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(build_paths::corpus_dir))
        if (entry.path().extension() == ".brep") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    static std::vector<CorpusModel> models;
    models.reserve(files.size());
    for (const auto& file : files) {
        const CorpusModel* model = &models.emplace_back(corpus_model(file));
        const std::string stem = file.stem().string();
        if (model->solids.size() != model->shapes.size()) continue;  // the file's open shells are not solids
        benchmark::RegisterBenchmark(benchmark_name({"corpus", stem, "ours", "3"}).c_str(),
                                     [model](benchmark::State& s) { corpus_ours(s, *model); })
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(benchmark_name({"corpus", stem, "BRepMesh", "3"}).c_str(),
                                     [model](benchmark::State& s) { corpus_brepmesh(s, *model); })
            ->Unit(benchmark::kMillisecond);
    }
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
    register_corpus();
}

}  // namespace ratbez::bench

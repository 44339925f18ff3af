// Mesh writers, measured without the disk: OpenSCAD polyhedron text and binary STL into a stream whose
// buffer is emptied into nothing when full (what an ofstream does, minus the write system call), for
// closed torus meshes of about 250k, 500k and 1M triangles. The meshes are grids of exact surface points
// (evaluate_grid), so every coordinate has the full 17 significant digits a real mesh has.
// Counters: `triangles_per_second`, `bytes_per_second`, `bytes`.
//
// Names: export/<scad|stl_binary>/<triangles>.

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include "bench_shapes.hpp"
#include "ratbez/export/writers.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez::bench {
namespace {

// A 64 KiB put area that is discarded when full and counts what passed through.
class DiscardingBuffer : public std::streambuf {
public:
    DiscardingBuffer() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    std::uint64_t bytes() const { return flushed_ + static_cast<std::uint64_t>(pptr() - pbase()); }

protected:
    int_type overflow(int_type c) override {
        flushed_ += static_cast<std::uint64_t>(pptr() - pbase());
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }

private:
    std::array<char, 1 << 16> buffer_{};
    std::uint64_t flushed_ = 0;
};

// A closed torus mesh of 2 n m triangles: the n x m grid of surface points with the seam rows and columns
// identified (the last grid row and column repeat the first), outward by the right-hand rule.
Mesh torus_mesh(std::size_t n, std::size_t m) {
    const Solid ring = torus(1.0, 0.3);
    const SurfaceGrid grid = evaluate_grid(ring.faces()[0].surface(), n + 1, m + 1);
    Mesh mesh;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) mesh.vertices.push_back(grid.point(i, j));
    auto index = [&](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>((i % n) * m + (j % m)); };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) {
            mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

template <class Write>
void writer(benchmark::State& state, const Mesh& mesh, const Write& write) {
    std::uint64_t bytes = 0;
    for (auto _ : state) {
        DiscardingBuffer buffer;
        std::ostream out(&buffer);
        write(mesh, out);
        bytes = buffer.bytes();
        benchmark::DoNotOptimize(bytes);
    }
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    state.counters["triangles_per_second"] = benchmark::Counter(static_cast<double>(mesh.triangles.size()),
                                                                benchmark::Counter::kIsIterationInvariantRate);
    state.counters["bytes"] = static_cast<double>(bytes);
    state.counters["bytes_per_second"] =
        benchmark::Counter(static_cast<double>(bytes), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

void register_benchmarks() {

    // 2 n m triangles with m = n / 2 (a torus's tube is shorter than its ring): 250k, 500k, 1M.
    static std::vector<Mesh> meshes;
    for (std::size_t n : {500u, 708u, 1000u}) meshes.push_back(torus_mesh(n, n / 2));
    for (const Mesh& mesh : meshes) {
        const Mesh* m = &mesh;
        const std::string triangles = std::to_string(mesh.triangles.size());
        benchmark::RegisterBenchmark(benchmark_name({"export", "scad", triangles}).c_str(), [m](benchmark::State& s) {
            writer(s, *m, [](const Mesh& mesh, std::ostream& out) { exporter::write_openscad(mesh, out); });
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(benchmark_name({"export", "stl_binary", triangles}).c_str(), [m](benchmark::State& s) {
            writer(s, *m, [](const Mesh& mesh, std::ostream& out) { exporter::write_stl_binary(mesh, out); });
        })->Unit(benchmark::kMillisecond);
    }
}

}  // namespace ratbez::bench

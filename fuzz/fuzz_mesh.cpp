// Fuzz target: the mesh writers and the CGAL mesh checks on arbitrary meshes. Vertices and triangles
// are decoded from the input; indices run a little past the vertex table now and then, and coordinates
// may be NaN, infinite or huge. Every consumer must reject a bad mesh with ratbez::Error (the writers)
// or a report problem (check_mesh), never read out of bounds. The OpenSCAD text of an accepted mesh
// must parse back (tests/reliability/polyhedron_parser.hpp) to the same vertices, bit for bit, and the
// same triangles.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include "harness.hpp"
#include "polyhedron_parser.hpp"
#include "ratbez/error.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/export/writers.hpp"
#include "ratbez/mesh.hpp"

namespace ratbez::fuzz {
namespace {

Mesh decode_mesh(ByteReader& in) {
    Mesh mesh;
    const std::size_t vertex_count = in.small(0, 40);
    const std::size_t triangle_count = in.small(0, 80);
    const bool grid = in.flag();  // coordinates on a small integer grid: many exact coincidences
    for (std::size_t i = 0; i < vertex_count; ++i) {
        if (grid) {
            const double x = in.small(-2, 2), y = in.small(-2, 2), z = in.small(-2, 2);
            mesh.vertices.push_back({x, y, z});
        } else {
            const double x = in.number(), y = in.number(), z = in.number();
            mesh.vertices.push_back({x, y, z});
        }
    }
    for (std::size_t t = 0; t < triangle_count && !in.empty(); ++t) {
        std::array<std::uint32_t, 3> triangle{};
        for (auto& index : triangle) {
            const std::uint8_t b = in.byte();
            index = b == 0xff ? in.u32() : static_cast<std::uint32_t>(b % (vertex_count + 2));
        }
        mesh.triangles.push_back(triangle);
    }
    return mesh;
}

}  // namespace

void run_mesh(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    const Mesh mesh = decode_mesh(in);
    const bool self_intersections = in.flag();

    (void)mesh.is_closed();
    attempt([&] { (void)mesh.volume(); });
    attempt([&] { (void)mesh.area(); });

    attempt([&] {
        std::ostringstream text;
        exporter::write_openscad(mesh, text);
        reliability::ParsedPolyhedron parsed;
        try {
            parsed = reliability::parse_polyhedron(text.str());
        } catch (const std::runtime_error& e) {
            std::fprintf(stderr, "%s\n", e.what());
            invariant_failed("fuzz_mesh", "write_openscad wrote text the polyhedron parser rejects");
        }
        if (std::string why; !reliability::same_mesh_bits(mesh, parsed.mesh, why)) {
            std::fprintf(stderr, "%s\n", why.c_str());
            invariant_failed("fuzz_mesh", "OpenSCAD text does not read back to the mesh");
        }
    });
    attempt([&] {
        std::ostringstream bytes;
        exporter::write_stl_binary(mesh, bytes);
        if (bytes.str().size() != 84 + 50 * mesh.triangles.size())
            invariant_failed("fuzz_mesh", "binary STL has the wrong size");
    });
    attempt([&] {
        std::ostringstream text;
        exporter::write_stl_ascii(mesh, text);
    });
    attempt([&] {
        std::ostringstream text;
        exporter::write_off(mesh, text);
    });

    exporter::MeshCheckOptions options;
    options.check_self_intersections = self_intersections;
    const exporter::MeshReport report = exporter::check_mesh(mesh, options);
    if (report.ok() && !mesh.is_closed()) invariant_failed("fuzz_mesh", "check_mesh passed a mesh that is not closed");
    if (report.ok() && !(report.volume > 0)) invariant_failed("fuzz_mesh", "check_mesh passed a mesh of volume <= 0");
}

}  // namespace ratbez::fuzz

#ifndef RATBEZ_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // A rejected input (ratbez::Error) is the one allowed outcome besides success.
    ratbez::fuzz::attempt([&] { ratbez::fuzz::run_mesh(data, size); });
    return 0;
}
#endif

// Fuzz target: the JSON shape spec end to end. The input is the spec text; a spec that parses and
// builds is tessellated at a tolerance clamped to at least 1/200 of the solid's size with a budget of
// 20,000 triangles (so one input stays fast), and the mesh must be closed with a positive volume.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "harness.hpp"
#include "ratbez/error.hpp"
#include "ratbez/tessellate.hpp"
#include "spec.hpp"

namespace ratbez::fuzz {

void run_spec(const std::uint8_t* data, std::size_t size) {
    ByteReader reader(data, size);
    const std::string_view text = reader.rest();
    spec::ShapeSpec shape = [&]() -> spec::ShapeSpec {
        try {
            return spec::parse_spec(text, "fuzz");
        } catch (const spec::SpecError& e) {
            if (e.path().empty()) invariant_failed("fuzz_spec", "a SpecError without a path");
            throw;
        }
    }();
    const double size_of_solid = shape.solid.bounding_box().diagonal();
    if (!(size_of_solid > 0) || !std::isfinite(size_of_solid)) return;  // nothing sensible to tessellate
    TessellationOptions options;
    options.tolerance = std::max(shape.tolerance.value_or(0.0), size_of_solid / 200.0);
    options.angle_deg = shape.tessellation_angle;
    options.max_triangles = 20'000;
    const Mesh mesh = tessellate(shape.solid, options);
    if (mesh.triangles.empty()) invariant_failed("fuzz_spec", "tessellation returned no triangles");
    for (const auto& t : mesh.triangles)
        for (auto index : t)
            if (index >= mesh.vertices.size()) invariant_failed("fuzz_spec", "triangle index past the vertices");
    if (!mesh.is_closed()) invariant_failed("fuzz_spec", "tessellation is not closed");
}

}  // namespace ratbez::fuzz

#ifndef RATBEZ_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // A rejected input (ratbez::Error) is the one allowed outcome besides success.
    ratbez::fuzz::attempt([&] { ratbez::fuzz::run_spec(data, size); });
    return 0;
}
#endif

#pragma once
// The harness of the readers' fuzz targets (fuzz_read_brep, fuzz_read_step) and of the soak campaign
// (fuzz/soak_readers.cpp): the input is a whole model file, written to a scratch file and read with every
// solid; each solid read must be consistent with itself (finite positive volume, a closed mesh enclosing that
// volume to within the mesh's tolerance) and go back to OpenCASCADE both ways (one face per face, one per
// Bézier patch). The readers' OpenCASCADE part runs in a child process (kernel/occt/src/child_process.hpp):
// what these targets find is in ratbez's own importer, validation and conversions, or a child that escapes.

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "harness.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/occt/files.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::fuzz {

// Why `solid` is not the solid its exact measures describe, or nullopt when it is consistent (a solid the
// tessellator refuses with ratbez::Error is not inconsistent: refusing is allowed).
inline std::optional<std::string> inconsistency(const Solid& solid) {
    const double volume = solid.volume(), area = solid.area();
    if (!std::isfinite(volume) || !std::isfinite(area)) return "its volume or area is not finite";
    if (!(volume > 0)) return "its volume " + std::to_string(volume) + " is not positive";
    try {
        TessellationOptions options;
        options.tolerance = 10 * default_tolerance(solid);  // 1e-2 of the diagonal: coarse, the check is global
        // 20,000 triangles: also the cap of a stray trimmed edge's refinement (tessellate.cpp), which took over
        // libFuzzer's 10 s under the sanitizers at 200,000.
        options.max_triangles = 20'000;
        const Mesh mesh = tessellate(solid, options);
        if (!mesh.is_closed()) return "its mesh is not closed";
        // Chords stay within the tolerance of the surface: the enclosed volumes differ by at most area x tolerance.
        const double slack = 2 * area * options.tolerance + 1e-9 * volume;
        if (std::abs(mesh.volume() - volume) > slack)
            return "its mesh encloses " + std::to_string(mesh.volume()) + ", its exact volume is " + std::to_string(volume);
    } catch (const Error&) {
    }
    return std::nullopt;
}

// The readers' time limit in the harness: a hang is a timeout past it, far below libFuzzer's -timeout.
inline void limit_read_time() { ::setenv("RATBEZ_READ_SECONDS", "2", /*overwrite=*/0); }

// Reads `data` as a file with `extension` (".brep", ".step") through `read_all`; aborts (a finding) on an
// inconsistent solid. Only ratbez::Error leaves it.
inline void run_read_file(const std::uint8_t* data, std::size_t size, const char* extension,
                          std::vector<Solid> (*read_all)(const std::string&, const Progress&, std::string*)) {
    limit_read_time();
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("ratbez_fuzz_read_" + std::to_string(::getpid()) + extension);
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    struct Remove {
        std::filesystem::path path;
        ~Remove() {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    } remove{file};
    std::string left_out;  // what no solid holds, said in words: never a reason to stop
    const std::vector<Solid> solids = read_all(file.string(), {}, &left_out);
    if (!left_out.empty() && solids.empty()) invariant_failed("read", "left part of a file out but read no solid");
    for (const Solid& solid : solids) {
        if (const auto why = inconsistency(solid)) invariant_failed("read", why->c_str());
        // Back to OpenCASCADE both ways; a refusal is fine, anything else a finding.
        attempt([&] { (void)occt::brep_string(solid, occt::ConvertOptions{false}); });
        attempt([&] { (void)occt::brep_string(solid, occt::ConvertOptions{true}); });
    }
}

}  // namespace ratbez::fuzz

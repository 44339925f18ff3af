#pragma once
// 3MF packages (the 3D Manufacturing Format: a ZIP of XML parts) through lib3mf 1.8, the library Debian's
// lib3mf-dev ships and OpenSCAD 2021.01 links for import(). Everything stays in memory: the exporter checks
// what a reader gets and hands the bytes to the one safe writer (ratbez/output_file.hpp). lib3mf's headers
// stay inside three_mf.cpp (they define SAL macros such as _In_ and Windows types).
//
// What lib3mf 1.8.1 writes (measured): each coordinate is a float32 printed in fixed notation with 6
// decimals, TRUNCATED, not rounded (0.1234567f is written "0.123456", 9.999999e-7f "0"), so a coordinate
// moves by up to 1e-6 below 2^3 and by its float32 rounding above; coordinates beyond 1e9 are refused.
// So the checks of an export run on read_three_mf of the package, never on the mesh that went in.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ratbez/export/writers.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::exporter {

// One object of a package: a closed mesh with its name (any UTF-8 text) and an optional colour.
struct ThreeMfObject {
    const Mesh* mesh = nullptr;
    std::string name;
    std::optional<Color> color;
};

// The largest coordinate lib3mf 1.8 accepts (NMR_MESH_MAXCOORDINATE, millimetres).
inline constexpr double three_mf_max_coordinate = 1e9;

// The package: unit millimetre, one mesh object per entry (object type "model") with one build item each,
// in order; a coloured object gets a base material of its colour (display colour #RRGGBBAA, named after the
// object) as its default property, which slicers show. `metadata` are (name, value) pairs of the model
// ("Application", "Title", "Description", ...). Errors: ratbez::Error naming "mesh" (a mesh lib3mf refuses,
// a coordinate beyond three_mf_max_coordinate) or "3mf" (lib3mf's own failure, with its message).
// `progress` (optional) is called while lib3mf writes; an exception it throws stops the writing and is
// rethrown here.
std::string write_three_mf(const std::vector<ThreeMfObject>& objects,
                           const std::vector<std::pair<std::string, std::string>>& metadata, const Progress& progress = {});

// A mesh object of a package as a reader gets it (float32 coordinates widened to double), with the
// display colour of its default base material (channels in 1/255 steps), if any.
struct ThreeMfMesh {
    std::string name;
    Mesh mesh;
    std::optional<Color> color;
};

// Every mesh object of a package, in the order of the file, read by lib3mf: what OpenSCAD's import() gets.
// Error naming "3mf" for bytes lib3mf cannot read.
std::vector<ThreeMfMesh> read_three_mf(std::string_view package);

// The model's metadata (name, value), in the order of the file.
std::vector<std::pair<std::string, std::string>> read_three_mf_metadata(std::string_view package);

}  // namespace ratbez::exporter

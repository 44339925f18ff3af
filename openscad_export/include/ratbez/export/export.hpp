#pragma once
// Exporting to files: check the mesh with CGAL first and refuse (ratbez::Error naming "mesh") rather than
// write a bad one; the format follows the extension (.scad, .stl, .off, .3mf). Unwritable paths and unknown
// extensions throw ratbez::Error naming "path". Every file goes through the one safe writer
// (ratbez/output_file.hpp); a 3MF package is made in memory by lib3mf first (three_mf.hpp).

#include <cstddef>
#include <optional>
#include <string>

#include "ratbez/brep.hpp"
#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/export/writers.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/progress.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::exporter {

struct ExportOptions {
    // Its header is filled in by the exporter. module_name also names the solid of an ASCII STL and the
    // object of a 3MF file (any text there); color also colours the 3MF object.
    OpenScadOptions openscad{};
    MeshCheckOptions checks{};
    bool binary_stl = true;
    // .scad only: the mesh goes to a binary STL beside it (the same name with .stl), which the module
    // import()s: OpenSCAD loads a large mesh from binary STL several times faster than from polyhedron().
    bool import_stl = false;
    std::string source = "a mesh";  // the .scad header's "source:" line ("spec vase.json", "Python")
    Progress progress;              // export_tessellation: called with the fraction done after each step
};

// The tessellation of `solid` for an export whose mesh `checks` will check: options.max_triangles lowered to
// checked_triangle_limit(checks) (the checks' limit, or the triangles the process's memory limit holds), so
// that a mesh the checks would refuse is refused from the tessellation's plan, before it is built, with the
// estimate and a tolerance that fits (TooFine, naming the checks' or the memory's limit when that is the
// lower one). Where the mesh intersects itself (a face's coarse mesh poking through a neighbour it meets at a
// shallow angle), the solid is meshed again at half the tolerance, up to three times, unless `checks` skip the
// self-intersection test.
Mesh tessellate_for_export(const Solid& solid, TessellationOptions options, const MeshCheckOptions& checks = {});

// Writes `mesh` as it is (a .scad header states its counts, bounding box and volume).
void export_mesh(const Mesh& mesh, const std::string& path, const ExportOptions& options = {});

// What export_tessellation wrote.
struct WrittenMesh {
    Mesh mesh;                    // the coordinates as a reader of the file gets them
    double max_deviation = 0;     // max_deviation(solid, mesh) of that mesh
    std::optional<int> decimals;  // coordinates rounded to this many decimals; unset: every double exact,
                                  // or float32 in a binary STL
};

// `mesh`, a tessellation of `solid` at `tolerance`, written to path. Text formats (.scad, .off, ASCII
// .stl) get the fewest decimals that keep the mesh AS WRITTEN within tolerance (max_deviation) and
// CGAL-clean; when no rounding passes, the exact doubles are written (the same checks must then pass,
// or Error "mesh"). Binary STL (also under import_stl) holds float32 coordinates, and 3MF what lib3mf
// writes (float32 cut to 6 decimals, read back from the package): the checks run on those, and a mesh
// they move beyond the tolerance or break is refused (Error "mesh" naming the format: write text, or a
// coarser tolerance). The .scad header (3MF: the model's Description metadata, with the version as
// Application) also states the tolerance, that deviation and the exact volume.
WrittenMesh export_tessellation(const Solid& solid, const Mesh& mesh, double tolerance, const std::string& path,
                                const ExportOptions& options = {});

// One solid of a library: its module name, the solid, its tessellation at `tolerance` and its colour.
struct LibraryPart {
    std::string module_name;
    const Solid* solid = nullptr;
    const Mesh* mesh = nullptr;
    double tolerance = 0;
    MeshCheckOptions checks{};  // tessellation_checks(solid, mesh, tolerance), or stricter
    std::optional<Color> color;
};

// Several solids in one .scad library: each mesh made and checked as export_tessellation does (the fewest
// decimals that keep it within its tolerance and CGAL-clean), one module per part, and the module
// options.openscad.module_name placing them all. The header lists every module with its triangles, its
// measured deviation and volumes. import_stl is refused (Error "import_stl"). Returns each part's mesh as written.
// A .3mf path gives one 3MF object per part instead (named module_name, any non-empty text, with its
// colour), each checked on the coordinates lib3mf wrote; the Description metadata lists every object. A .stl or
// .off path gives one mesh of all the parts, each prepared and checked on its own (they may touch or overlap,
// as an assembly's parts do), the OFF comments / ASCII STL header listing them.
std::vector<WrittenMesh> export_library(const std::vector<LibraryPart>& parts, const std::string& path,
                                        const ExportOptions& options = {});

// export_library's refusal of one part of several by the checks of its mesh ("mesh: 'Nut': ..."): part() is its
// index in the parts given, so that a caller may leave it out and export the others (the command does, with a note).
class PartRefused : public Error {
public:
    PartRefused(const Error& error, std::size_t part) : Error(error), part_(part) {}
    std::size_t part() const noexcept { return part_; }

private:
    std::size_t part_;
};

// The mesh checks for a tessellation of `solid` at `tolerance`: the volume lies within tolerance times
// the area of the exact one (the mesh stays within tolerance of the surface everywhere).
MeshCheckOptions tessellation_checks(const Solid& solid, const Mesh& mesh, double tolerance);

// Every coordinate written with `decimals` digits after the point (std::to_chars fixed) and read back.
Mesh rounded_mesh(const Mesh& mesh, int decimals);

}  // namespace ratbez::exporter

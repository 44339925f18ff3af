#pragma once
// Exporting to files: check the mesh with CGAL first and refuse (ratbez::Error) rather than write a bad
// one; the format follows the extension (.scad, .stl, .off). Unwritable paths and unknown extensions
// throw ratbez::Error naming "path".

#include <string>

#include "ratbez/export/mesh_checks.hpp"
#include "ratbez/export/writers.hpp"
#include "ratbez/mesh.hpp"

namespace ratbez::exporter {

struct ExportOptions {
    OpenScadOptions openscad{};
    MeshCheckOptions checks{};
    bool binary_stl = true;
};

void export_mesh(const Mesh& mesh, const std::string& path, const ExportOptions& options = {});

}  // namespace ratbez::exporter

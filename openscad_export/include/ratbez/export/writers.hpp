#pragma once
// Mesh writers: OpenSCAD polyhedron text, STL (binary and ASCII) and OFF. Numbers are written
// shortest-round-trip with std::to_chars. These write what they are given; export.hpp checks first.

#include <ostream>
#include <string>

#include "ratbez/mesh.hpp"

namespace ratbez::exporter {

struct OpenScadOptions {
    std::string module_name;  // non-empty: wrap as `module NAME() { polyhedron(...); }` for use <file.scad>
    int convexity = 10;
};

void write_openscad(const Mesh& mesh, std::ostream& out, const OpenScadOptions& options = {});
void write_stl_binary(const Mesh& mesh, std::ostream& out);
void write_stl_ascii(const Mesh& mesh, std::ostream& out, const std::string& solid_name = "ratbez");
void write_off(const Mesh& mesh, std::ostream& out);

}  // namespace ratbez::exporter

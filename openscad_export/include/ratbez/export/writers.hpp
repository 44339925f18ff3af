#pragma once
// Mesh writers: OpenSCAD library text (a module around polyhedron(...)), STL (binary and ASCII) and OFF. Numbers are written
// shortest-round-trip with std::to_chars. These write what they are given; export.hpp checks first.

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "ratbez/mesh.hpp"

namespace ratbez::exporter {

// Every .scad file is a library: `module NAME() { polyhedron(...); }` then one call `NAME();`, so that
// `use <file.scad>` imports the module (use ignores top-level calls) and opening the file renders it.
// An sRGB colour with alpha, each channel in [0, 1] (OpenSCAD's color([r, g, b, a]), 3MF's base colour).
struct Color {
    double red = 1, green = 1, blue = 1, alpha = 1;
};
// "#rrggbb" or "#rrggbbaa" (hexadecimal, either case), else ratbez::Error naming `argument`.
Color parse_color(std::string_view text, std::string_view argument = "color");

struct OpenScadOptions {
    std::string module_name = "shape";  // an OpenSCAD identifier (openscad_identifier makes one)
    int convexity = 10;
    std::vector<std::string> header;    // comment lines above the module, escaped by comment_text
    std::optional<Color> color;         // wraps the module's body in color([r, g, b, a])
};

// One module of a library of several solids.
struct LibraryModule {
    const Mesh* mesh = nullptr;
    std::string module_name;
    std::optional<Color> color;
};

// True for a name OpenSCAD 2021.01 already gives a meaning: a keyword (module, for, true, ...), a built-in
// module (sphere, cylinder, polyhedron, import, union, color, children, ...) or a built-in function (abs,
// len, str, ...). A library module of such a name shadows OpenSCAD's own in every file that `use`s the
// library (the user's `cylinder(r=2, h=12)` becomes ours), or calls itself (`polyhedron`, `import`).
bool is_openscad_builtin(std::string_view name);
// The suffix a derived module name that is a built-in gets ("sphere" gives "sphere_solid").
inline constexpr std::string_view builtin_suffix = "_solid";
// `text` made an OpenSCAD identifier: characters other than letters, digits and _ become _, a leading
// digit gets a _ in front, a built-in or keyword gets builtin_suffix behind; empty text gives "shape".
std::string openscad_identifier(std::string_view text);
// Module names for the solids of a library from their own names (Solid::name): each made an identifier, repeats
// numbered (_2, _3, ...), none equal to `placing`, the module placing them all. The CLI's and Python's libraries.
std::vector<std::string> library_module_names(const std::vector<std::string>& names, std::string_view placing);
// True when `name` is already an identifier openscad_identifier leaves as it is.
bool is_openscad_identifier(std::string_view name);
// Why `name` cannot be an explicitly chosen module name (not an identifier, or a built-in it would
// shadow), or "" when it can. One wording for the exporter, the CLI's --module and Python's module=.
std::string module_name_problem(std::string_view name);
// Throws ratbez::Error(argument, module_name_problem(name)) unless that is "".
void require_module_name(std::string_view name, std::string_view argument = "module_name");
// `text` fit for one comment line: backslash and control characters (a newline would end the comment
// and let the rest run as code) are written as C escapes (\\, \n, \r, \t, \xNN).
std::string comment_text(std::string_view text);

void write_openscad(const Mesh& mesh, std::ostream& out, const OpenScadOptions& options = {});
// A library of several solids: `module A() { polyhedron(...); }` for each, then `module NAME() { A(); B(); }`
// (NAME: options.module_name, distinct from every module's name) placing them all, then `NAME();`.
void write_openscad_library(const std::vector<LibraryModule>& modules, std::ostream& out, const OpenScadOptions& options = {});
// The library file for a mesh kept in an STL file beside it: `module NAME() { import("stl_file"); }` then
// `NAME();` (OpenSCAD resolves the name against the folder of the .scad file, also through `use`, and
// loads a large mesh from binary STL several times faster than from polyhedron() text).
void write_openscad_import(const std::string& stl_file, std::ostream& out, const OpenScadOptions& options = {});
// `mesh` as a reader of binary STL gets it: every coordinate rounded to float32, and the vertices that rounding
// brings together welded into one (mesh_welding.hpp), as readers join the corners of an STL file by coordinates.
Mesh float32_mesh(const Mesh& mesh);
void write_stl_binary(const Mesh& mesh, std::ostream& out);
void write_stl_ascii(const Mesh& mesh, std::ostream& out, const std::string& solid_name = "ratbez");
void write_off(const Mesh& mesh, std::ostream& out);

}  // namespace ratbez::exporter

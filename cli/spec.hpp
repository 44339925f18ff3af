#pragma once
// The JSON shape spec of the `ratbez` command (documented in examples/README.md): a document with a
// `shape` (cylinder, cone, sphere, torus, revolve, extrude, ruled, loft, sweep) and optional `name`, `description`,
// `tolerance` and `tessellation_angle`. Parsing is strict: wrong types, out-of-range values, missing
// and unknown fields (typos) all throw SpecError naming the JSON path of the field, e.g.
// `shape.profile[1].points[0]: must be a list of 2 or 3 numbers`. Kernel validation errors raised
// while building the solid are reported under the path of the part being built.
//
// A library of its own (no OCCT, no CGAL, no I/O beyond load_spec) so that a fuzzer can drive it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"

namespace ratbez::spec {

// A ratbez::Error whose argument is the JSON path of the field at fault.
class SpecError : public Error {
public:
    SpecError(std::string_view path, std::string_view reason) : Error(path, reason) {}
    explicit SpecError(const Error& error) : Error(error) {}  // a kernel error already put under its path
    std::string_view path() const noexcept { return argument(); }  // "shape.radius", "shape.profile[2].knots", ...
};

// The limits of a spec document, checked before the work grows with it (README, Input limits): its size in
// bytes (a file is read only up to one byte past it) and the nesting depth of its objects and arrays.
inline constexpr std::size_t max_spec_bytes = 16u << 20;
inline constexpr int max_json_depth = 64;

struct ShapeSpec {
    std::string name{};                       // `name`, else the fallback (the file's stem)
    std::string description{};
    std::string type{};                       // shape.type
    std::optional<double> tolerance{};        // absolute chordal tolerance for tessellation
    std::optional<double> tessellation_angle{};  // degrees
    Solid solid;                              // solid.construction(): what it was built as
    bool named = false;                       // the document gave `name` (else it is the fallback)
    std::optional<std::string> color{};       // `color`, "#rrggbb" or "#rrggbbaa": .scad output wraps the body in color()
};

// Parses and builds. `fallback_name` is used when the document has no `name`; it must itself be a
// valid name (letters, digits and _, not starting with a digit) or it is replaced by "shape".
ShapeSpec parse_spec(std::string_view json_text, const std::string& fallback_name = "shape");

// Reads the file and parses it; the name falls back to the file's stem. An unreadable file or text
// that is not JSON throws SpecError with the file path as its path.
ShapeSpec load_spec(const std::string& path);

// True for OpenSCAD-compatible identifiers, the rule `name` must follow.
bool is_valid_name(std::string_view name);

}  // namespace ratbez::spec

#include "ratbez/export/writers.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "ratbez/error.hpp"
#include "ratbez/mesh_welding.hpp"

namespace ratbez::exporter {
namespace {

// 'text', built by appending: gcc 12 takes "'" + std::string(...) for an overlapping copy (-Wrestrict).
std::string quoted(std::string_view text) {
    std::string result(1, '\'');
    result.append(text).push_back('\'');
    return result;
}

// Refuse to write a file that would be garbage: an index past the vertex table or a NaN/inf coordinate
// would produce text no reader accepts (or, worse, accepts wrongly). O(n), negligible beside the writing.
void validate_mesh(const Mesh& mesh) {
    const auto vertex_count = mesh.vertices.size();
    for (std::size_t i = 0; i < vertex_count; ++i)
        require(is_finite(mesh.vertices[i]), "mesh", [i] { return "vertex " + std::to_string(i) + " is not finite"; });
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t index : mesh.triangles[t])
            require(index < vertex_count, "mesh", [&] {
                return "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(index) +
                       " but there are only " + std::to_string(vertex_count) + " vertices";
            });
}

// Text and bytes go into one reserved buffer that is handed to the stream in large blocks: no
// per-number stringstream, no per-character virtual call. Numbers are std::to_chars shortest
// round-trip, so reading the file back gives the very same doubles.
class BufferedOutput {
public:
    explicit BufferedOutput(std::ostream& out) : out_(out), buffer_(capacity) {}
    BufferedOutput(const BufferedOutput&) = delete;
    BufferedOutput& operator=(const BufferedOutput&) = delete;

    void text(std::string_view s) {
        if (s.size() > capacity - used_) flush();
        if (s.size() > capacity) {
            write_through(s.data(), s.size());
            return;
        }
        std::memcpy(buffer_.data() + used_, s.data(), s.size());
        used_ += s.size();
    }
    void character(char c) {
        if (used_ == capacity) flush();
        buffer_[used_++] = c;
    }
    void number(double value) {
        make_room(max_number_chars);
        value += 0.0;  // -0 becomes +0: the files do not depend on the sign of a zero
        auto* begin = buffer_.data() + used_;
        const auto result = std::to_chars(begin, begin + max_number_chars, value);
        used_ += static_cast<std::size_t>(result.ptr - begin);
    }
    void index(std::uint64_t value) {
        make_room(max_number_chars);
        auto* begin = buffer_.data() + used_;
        const auto result = std::to_chars(begin, begin + max_number_chars, value);
        used_ += static_cast<std::size_t>(result.ptr - begin);
    }
    // Little-endian binary values (STL is little-endian whatever the host).
    template <class T>
    void binary(T value) {
        static_assert(std::is_trivially_copyable_v<T>);
        make_room(sizeof(T));
        std::array<char, sizeof(T)> bytes;
        std::memcpy(bytes.data(), &value, sizeof(T));
        if constexpr (std::endian::native == std::endian::big)
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
        std::memcpy(buffer_.data() + used_, bytes.data(), sizeof(T));
        used_ += sizeof(T);
    }
    void flush() {
        write_through(buffer_.data(), used_);
        used_ = 0;
    }

private:
    static constexpr std::size_t capacity = std::size_t{1} << 20;
    static constexpr std::size_t max_number_chars = 32;  // shortest double: at most 24 characters

    void make_room(std::size_t n) {
        if (n > capacity - used_) flush();
    }
    void write_through(const char* data, std::size_t n) {
        if (n == 0) return;
        out_.write(data, static_cast<std::streamsize>(n));
        if (!out_) throw Error("out", "writing the mesh failed");
    }

    std::ostream& out_;
    std::vector<char> buffer_;
    std::size_t used_ = 0;
};

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = cross(b - a, c - a);
    const double length = norm(n);
    return length > 0 ? n / length : Vec3{};
}

void vertex_triple(BufferedOutput& out, const Vec3& p, char separator) {
    out.number(p.x);
    out.character(separator);
    out.number(p.y);
    out.character(separator);
    out.number(p.z);
}

}  // namespace

bool is_openscad_builtin(std::string_view name) {
    // OpenSCAD 2021.01's keywords, built-in modules (with the deprecated ones it still accepts) and
    // built-in functions; a few names of later releases (roof, fill, textmetrics, ...) too, so a library
    // written today does not start shadowing them after an upgrade.
    static constexpr auto builtins = std::to_array<std::string_view>({
        // keywords and constants of the grammar
        "module", "function", "include", "use", "if", "else", "for", "let", "each", "assert", "echo", "true",
        "false", "undef",
        // modules: 3D and 2D primitives, import, transforms, booleans, control
        "cube", "sphere", "cylinder", "polyhedron", "square", "circle", "polygon", "text", "import", "surface",
        "linear_extrude", "rotate_extrude", "projection", "union", "difference", "intersection", "intersection_for",
        "hull", "minkowski", "render", "translate", "rotate", "scale", "mirror", "multmatrix", "color", "offset",
        "resize", "group", "children", "child", "parent_module", "assign", "dxf_linear_extrude",
        "dxf_rotate_extrude", "import_stl", "import_off", "import_dxf", "roof", "fill",
        // functions
        "abs", "sign", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "floor", "round", "ceil", "ln", "log",
        "pow", "sqrt", "exp", "rands", "min", "max", "norm", "cross", "len", "concat", "lookup", "str", "chr",
        "ord", "search", "version", "version_num", "is_undef", "is_bool", "is_num", "is_string", "is_list",
        "is_function", "is_object", "dxf_dim", "dxf_cross", "textmetrics", "fontmetrics", "object", "import_obj",
        "import_amf", "import_3mf"});
    return std::find(builtins.begin(), builtins.end(), name) != builtins.end();
}

bool is_openscad_identifier(std::string_view name) { return !name.empty() && openscad_identifier(name) == name; }

std::string openscad_identifier(std::string_view text) {
    if (text.empty()) return "shape";
    std::string name;
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (digit(text.front())) name += '_';
    for (char c : text) {
        const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        name += letter || digit(c) ? c : '_';
    }
    // `module for() {}` does not parse, and `module sphere()` shadows OpenSCAD's sphere() for the user.
    if (is_openscad_builtin(name)) name += builtin_suffix;
    return name;
}

std::vector<std::string> library_module_names(const std::vector<std::string>& names, std::string_view placing) {
    std::set<std::string> taken{std::string(placing)};
    std::vector<std::string> modules;
    for (const std::string& text : names) {
        const std::string base = openscad_identifier(text);
        std::string name = base;
        for (int k = 2; !taken.insert(name).second; ++k) name = base + "_" + std::to_string(k);
        modules.push_back(name);
    }
    return modules;
}

std::string module_name_problem(std::string_view name) {
    if (is_openscad_builtin(name))
        return quoted(name) + " is an OpenSCAD built-in or keyword: a module of that name would shadow OpenSCAD's own "
               "in every file that uses the library (try '" + std::string(name) + std::string(builtin_suffix) + "')";
    if (!is_openscad_identifier(name))
        return quoted(comment_text(name)) + " is not an OpenSCAD identifier (letters, digits, _; not starting with a digit)";
    return {};
}

std::string comment_text(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string escaped;
    escaped.reserve(text.size());
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\\') escaped += "\\\\";
        else if (c == '\n') escaped += "\\n";
        else if (c == '\r') escaped += "\\r";
        else if (c == '\t') escaped += "\\t";
        else if (byte < 0x20 || byte == 0x7f) escaped += std::string("\\x") + hex[byte >> 4] + hex[byte & 15];
        else escaped += c;
    }
    return escaped;
}

void require_module_name(std::string_view name, std::string_view argument) {
    if (const std::string problem = module_name_problem(name); !problem.empty()) throw Error(argument, problem);
}

namespace {

// The header comment lines and the line that says how the file is used (then `note`).
std::string library_preamble(const OpenScadOptions& options, std::string_view note) {
    std::string text;
    for (const std::string& line : options.header) text += "// " + comment_text(line) + "\n";
    text += "// use <this file> imports module " + options.module_name + "(); opening the file renders it.";
    return text.append(note) + "\n";
}

}  // namespace

Color parse_color(std::string_view text, std::string_view argument) {
    const auto bad = [&] {
        return Error(argument, quoted(comment_text(text)) + " is not a colour (expected \"#rrggbb\" or \"#rrggbbaa\", hexadecimal)");
    };
    if ((text.size() != 7 && text.size() != 9) || text.front() != '#') throw bad();
    double channels[4] = {1, 1, 1, 1};
    for (std::size_t i = 0; 1 + 2 * i < text.size(); ++i) {
        unsigned value = 0;
        const char* begin = text.data() + 1 + 2 * i;
        const auto result = std::from_chars(begin, begin + 2, value, 16);
        if (result.ec != std::errc() || result.ptr != begin + 2) throw bad();
        channels[i] = value / 255.0;
    }
    return {channels[0], channels[1], channels[2], channels[3]};
}

namespace {

void require_color(const std::optional<Color>& color) {
    if (!color) return;
    for (const double channel : {color->red, color->green, color->blue, color->alpha})
        require(channel >= 0 && channel <= 1, "color", "channels must lie in [0, 1]");
}

// `module NAME() { [color([r, g, b, a])] polyhedron(...); }`. The callers validate the mesh, the name and
// the colour before anything is written.
void write_polyhedron_module(BufferedOutput& buffer, const Mesh& mesh, const std::string& name,
                             const std::optional<Color>& color, int convexity) {
    buffer.text("module ");
    buffer.text(name);
    buffer.text("() {\n");
    if (color) {
        buffer.text("color([");
        const std::array<double, 4> channels = {color->red, color->green, color->blue, color->alpha};
        for (std::size_t i = 0; i < channels.size(); ++i) {
            buffer.number(channels[i]);
            buffer.character(i + 1 < channels.size() ? ',' : ']');
        }
        buffer.text(")\n");
    }
    buffer.text("polyhedron(points=[\n");
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        buffer.character('[');
        vertex_triple(buffer, mesh.vertices[i], ',');
        buffer.text(i + 1 < mesh.vertices.size() ? "],\n" : "]");
    }
    buffer.text("],\nfaces=[\n");
    // Our triangles are counterclockwise seen from outside (right-hand rule, outward). OpenSCAD 2021.01's
    // polyhedron() wants the opposite, CLOCKWISE seen from outside: checked with the real binary, where
    // `--preview=throwntogether` draws a tetrahedron written (a, c, b) in the normal face colour and one
    // written (a, b, c) in the magenta of inverted faces. So every triangle is written (a, c, b).
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        buffer.character('[');
        buffer.index(tri[0]);
        buffer.character(',');
        buffer.index(tri[2]);
        buffer.character(',');
        buffer.index(tri[1]);
        buffer.text(t + 1 < mesh.triangles.size() ? "],\n" : "]");
    }
    buffer.text("],\nconvexity=");
    buffer.index(static_cast<std::uint64_t>(convexity));
    buffer.text(");\n}\n");
}

}  // namespace

void write_openscad(const Mesh& mesh, std::ostream& out, const OpenScadOptions& options) {
    validate_mesh(mesh);
    require_module_name(options.module_name);
    require_color(options.color);
    require(options.convexity >= 1, "convexity", "must be at least 1");

    BufferedOutput buffer(out);
    buffer.text(library_preamble(options, " Faces are clockwise seen from outside (OpenSCAD's order)."));
    write_polyhedron_module(buffer, mesh, options.module_name, options.color, options.convexity);
    buffer.text(options.module_name);
    buffer.text("();\n");
    buffer.flush();
}

void write_openscad_library(const std::vector<LibraryModule>& modules, std::ostream& out, const OpenScadOptions& options) {
    require(!modules.empty(), "solids", "is empty");
    require_module_name(options.module_name);
    require(options.convexity >= 1, "convexity", "must be at least 1");
    for (std::size_t i = 0; i < modules.size(); ++i) {
        require(modules[i].mesh != nullptr, "solids", "a module has no mesh");
        validate_mesh(*modules[i].mesh);
        require_module_name(modules[i].module_name);
        require_color(modules[i].color);
        require(modules[i].module_name != options.module_name, "module_name", [&] {
            return "'" + options.module_name + "' is also the name of a solid: the module placing them all needs its own";
        });
        for (std::size_t j = 0; j < i; ++j)
            require(modules[j].module_name != modules[i].module_name, "solids",
                    [&] { return "two solids are named '" + modules[i].module_name + "'"; });
    }
    BufferedOutput buffer(out);
    std::string names;
    for (const LibraryModule& m : modules) names += (names.empty() ? "" : ", ") + m.module_name + "()";
    buffer.text(library_preamble(options, " It also has one module per solid: " + names +
                                              ". Faces are clockwise seen from outside (OpenSCAD's order)."));
    for (const LibraryModule& m : modules) write_polyhedron_module(buffer, *m.mesh, m.module_name, m.color, options.convexity);
    buffer.text("module ");
    buffer.text(options.module_name);
    buffer.text("() {\n");
    for (const LibraryModule& m : modules) {
        buffer.text(m.module_name);
        buffer.text("();\n");
    }
    buffer.text("}\n");
    buffer.text(options.module_name);
    buffer.text("();\n");
    buffer.flush();
}

void write_openscad_import(const std::string& stl_file, std::ostream& out, const OpenScadOptions& options) {
    require_module_name(options.module_name);
    require(!stl_file.empty(), "stl_file", "is empty");
    require(options.convexity >= 1, "convexity", "must be at least 1");
    // An OpenSCAD string literal: \\ and \" escaped; control characters cannot be written in one.
    std::string literal;
    for (const char c : stl_file) {
        require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "stl_file", "contains a control character");
        if (c == '\\' || c == '"') literal += '\\';
        literal += c;
    }
    out << library_preamble(options, " The mesh is in " + comment_text(stl_file) + " beside it.") << "module " << options.module_name << "() {\nimport(\"" << literal
        << "\", convexity=" << options.convexity << ");\n}\n"
        << options.module_name << "();\n";
}

namespace {

// `value` rounded to float32 and back. Not inlined: GCC 12.2's SLP vectorizer drops the round trip of a
// vertex's x and y (at -O2 for every vertex, at -O3 for the 1 to 3 past a multiple of 4), so the mesh checked
// was not the mesh written (ExportTessellation.BinaryStlWeldsTheVerticesFloat32BringsTogether).
[[gnu::noinline]] double as_float32(double value) { return static_cast<float>(value); }

}  // namespace

Mesh float32_mesh(const Mesh& mesh) {
    Mesh result = mesh;
    for (Vec3& p : result.vertices) p = {as_float32(p.x), as_float32(p.y), as_float32(p.z)};
    // STL has no vertex table: its readers join corners with equal coordinates, so vertices the rounding brought
    // together are one vertex to them (a Voron plug panel's 25 pairs, 1e-6 apart, at the default tolerance).
    return welded(result);
}

void write_stl_binary(const Mesh& mesh, std::ostream& out) {
    validate_mesh(mesh);
    require(mesh.triangles.size() <= std::numeric_limits<std::uint32_t>::max(), "mesh",
            "too many triangles for binary STL (at most 2^32 - 1)");
    BufferedOutput buffer(out);
    // 80-byte header that must not begin with "solid" (readers would take the file for ASCII STL).
    std::array<char, 80> header{};
    const std::string_view title = "ratbez binary STL";
    std::memcpy(header.data(), title.data(), title.size());
    buffer.text(std::string_view(header.data(), header.size()));
    buffer.binary(static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const auto& tri : mesh.triangles) {
        const Vec3& a = mesh.vertices[tri[0]];
        const Vec3& b = mesh.vertices[tri[1]];
        const Vec3& c = mesh.vertices[tri[2]];
        for (const Vec3& p : {unit_normal(a, b, c), a, b, c}) {
            buffer.binary(static_cast<float>(p.x));
            buffer.binary(static_cast<float>(p.y));
            buffer.binary(static_cast<float>(p.z));
        }
        buffer.binary(std::uint16_t{0});  // attribute byte count
    }
    buffer.flush();
}

void write_stl_ascii(const Mesh& mesh, std::ostream& out, const std::string& solid_name) {
    validate_mesh(mesh);
    for (char c : solid_name)
        require(c != '\n' && c != '\r', "solid_name", "must be a single line");
    BufferedOutput buffer(out);
    buffer.text("solid ");
    buffer.text(solid_name);
    buffer.character('\n');
    for (const auto& tri : mesh.triangles) {
        const Vec3& a = mesh.vertices[tri[0]];
        const Vec3& b = mesh.vertices[tri[1]];
        const Vec3& c = mesh.vertices[tri[2]];
        buffer.text("facet normal ");
        vertex_triple(buffer, unit_normal(a, b, c), ' ');
        buffer.text("\nouter loop\n");
        for (const Vec3* p : {&a, &b, &c}) {
            buffer.text("vertex ");
            vertex_triple(buffer, *p, ' ');
            buffer.character('\n');
        }
        buffer.text("endloop\nendfacet\n");
    }
    buffer.text("endsolid ");
    buffer.text(solid_name);
    buffer.character('\n');
    buffer.flush();
}

void write_off(const Mesh& mesh, std::ostream& out) {
    validate_mesh(mesh);
    BufferedOutput buffer(out);
    buffer.text("OFF\n");
    buffer.index(mesh.vertices.size());
    buffer.character(' ');
    buffer.index(mesh.triangles.size());
    buffer.text(" 0\n");
    for (const Vec3& p : mesh.vertices) {
        vertex_triple(buffer, p, ' ');
        buffer.character('\n');
    }
    // OFF faces are counterclockwise seen from outside, like ours.
    for (const auto& tri : mesh.triangles) {
        buffer.text("3 ");
        buffer.index(tri[0]);
        buffer.character(' ');
        buffer.index(tri[1]);
        buffer.character(' ');
        buffer.index(tri[2]);
        buffer.character('\n');
    }
    buffer.flush();
}

}  // namespace ratbez::exporter

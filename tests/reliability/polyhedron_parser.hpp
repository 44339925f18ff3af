#pragma once
// A small, strict reader of the OpenSCAD text ratbez::exporter::write_openscad produces:
//   // comment lines
//   module NAME() {
//   polyhedron(points=[[x,y,z],...], faces=[[a,b,c],...], convexity=N);
//   }
//   NAME();
// Whitespace is free; numbers are read with std::from_chars, so shortest-round-trip text gives back the
// very doubles that were written. Faces are CLOCKWISE seen from outside in the file (OpenSCAD's rule),
// so a file face [a, c, b] is the mesh triangle (a, b, c). Anything else throws std::runtime_error with
// the offset of the problem: the round-trip tests and the mesh fuzzer use it to check the writer.

#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ratbez/mesh.hpp"

namespace ratbez::reliability {

struct ParsedPolyhedron {
    Mesh mesh;
    std::string module_name;
    long long convexity = 0;
};

class PolyhedronParser {
public:
    explicit PolyhedronParser(std::string_view text) : text_(text) {}

    ParsedPolyhedron parse() {
        ParsedPolyhedron result;
        skip();
        word("module");
        result.module_name = identifier();
        expect('(');
        expect(')');
        expect('{');
        word("polyhedron");
        expect('(');
        word("points");
        expect('=');
        expect('[');
        if (!accept(']')) {
            do {
                expect('[');
                Vec3 p;
                p.x = real();
                expect(',');
                p.y = real();
                expect(',');
                p.z = real();
                expect(']');
                result.mesh.vertices.push_back(p);
            } while (accept(','));
            expect(']');
        }
        expect(',');
        word("faces");
        expect('=');
        expect('[');
        if (!accept(']')) {
            do {
                expect('[');
                const std::uint32_t a = index(), c = (expect(','), index()), b = (expect(','), index());
                expect(']');
                result.mesh.triangles.push_back({a, b, c});
            } while (accept(','));
            expect(']');
        }
        expect(',');
        word("convexity");
        expect('=');
        result.convexity = static_cast<long long>(index());
        expect(')');
        expect(';');
        expect('}');
        // The one call that renders the file when it is opened (use <file> ignores it).
        word(result.module_name);
        expect('(');
        expect(')');
        expect(';');
        if (position_ != text_.size()) fail("text after the module's call");
        return result;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("polyhedron text, offset " + std::to_string(position_) + ": " + what);
    }
    // Whitespace and // comments.
    void skip() {
        while (position_ < text_.size()) {
            const char c = text_[position_];
            if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
                ++position_;
            } else if (text_.substr(position_, 2) == "//") {
                while (position_ < text_.size() && text_[position_] != '\n') ++position_;
            } else {
                break;
            }
        }
    }
    bool accept(char c) {
        if (position_ < text_.size() && text_[position_] == c) {
            ++position_;
            skip();
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!accept(c)) fail(std::string("expected '") + c + "'");
    }
    static bool identifier_char(char c, bool first) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (!first && c >= '0' && c <= '9');
    }
    std::string_view peek_word() const {
        std::size_t end = position_;
        while (end < text_.size() && identifier_char(text_[end], end == position_)) ++end;
        return text_.substr(position_, end - position_);
    }
    std::string identifier() {
        const std::string_view w = peek_word();
        if (w.empty()) fail("expected an identifier");
        position_ += w.size();
        skip();
        return std::string(w);
    }
    void word(std::string_view expected) {
        if (peek_word() != expected) fail("expected '" + std::string(expected) + "'");
        position_ += expected.size();
        skip();
    }
    double real() {
        double value = 0;
        const char* begin = text_.data() + position_;
        const auto [end, error] = std::from_chars(begin, text_.data() + text_.size(), value);
        if (error != std::errc{} || end == begin) fail("expected a number");
        position_ += static_cast<std::size_t>(end - begin);
        skip();
        return value;
    }
    std::uint32_t index() {
        std::uint64_t value = 0;
        const char* begin = text_.data() + position_;
        const auto [end, error] = std::from_chars(begin, text_.data() + text_.size(), value);
        if (error != std::errc{} || end == begin || value > std::numeric_limits<std::uint32_t>::max())
            fail("expected an index");
        position_ += static_cast<std::size_t>(end - begin);
        skip();
        return static_cast<std::uint32_t>(value);
    }

    std::string_view text_;
    std::size_t position_ = 0;
};

inline ParsedPolyhedron parse_polyhedron(std::string_view text) { return PolyhedronParser(text).parse(); }

// Bit-exact equality of coordinates, except that -0 and +0 are the same (the writer prints -0 as 0).
inline bool same_coordinate(double written, double read) {
    return written == 0 ? read == 0 && !std::signbit(read) : std::bit_cast<std::uint64_t>(written) == std::bit_cast<std::uint64_t>(read);
}

// The same mesh as written: the same triangles, and vertices equal by same_coordinate. When they differ,
// `why` says where.
inline bool same_mesh_bits(const Mesh& written, const Mesh& read, std::string& why) {
    if (written.vertices.size() != read.vertices.size()) {
        why = "vertex counts differ";
        return false;
    }
    if (written.triangles != read.triangles) {
        why = "triangles differ";
        return false;
    }
    for (std::size_t i = 0; i < written.vertices.size(); ++i) {
        const Vec3 &a = written.vertices[i], &b = read.vertices[i];
        if (!same_coordinate(a.x, b.x) || !same_coordinate(a.y, b.y) || !same_coordinate(a.z, b.z)) {
            why = "vertex " + std::to_string(i) + " differs";
            return false;
        }
    }
    return true;
}

}  // namespace ratbez::reliability

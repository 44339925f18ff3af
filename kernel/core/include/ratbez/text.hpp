#pragma once
// User text on one line, safe to print and to write into a file: what a message quotes (a spec field, a
// file name) and what a writer puts into a comment (a FreeCAD Label, a spec's name) must not carry a
// newline that ends a `//` comment and turns the rest into code, an escape sequence that drives the
// terminal, a NUL that cuts the text short, or a Unicode line separator or bidirectional override that
// makes it read differently from what it is.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ratbez {

// `text` with every control character escaped: C0 controls and DEL as \xNN (\n, \r, \t by name), C1
// controls, U+2028/U+2029 (line and paragraph separators) and the bidirectional controls U+202A..U+202E,
// U+2066..U+2069 as \uXXXX, and bytes that are not UTF-8 as \xNN. Printable text, multi-byte UTF-8
// included, is kept as it is, so printable(printable(t)) == printable(t).
inline std::string printable(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    auto escape_byte = [&](unsigned char c) {
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
    };
    auto escape_code_point = [&](std::uint32_t c) {
        out += "\\u";
        for (int shift = 12; shift >= 0; shift -= 4) out += hex[(c >> shift) & 15];
    };
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            if (c == '\n') out += "\\n";
            else if (c == '\r') out += "\\r";
            else if (c == '\t') out += "\\t";
            else if (c < 0x20 || c == 0x7f) escape_byte(c);
            else out += static_cast<char>(c);
            ++i;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, then continuation bytes 10xxxxxx; overlong forms,
        // surrogates and values past U+10FFFF are not UTF-8 and are escaped byte by byte.
        const std::size_t length = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
        std::uint32_t code = length == 2 ? c & 0x1fu : length == 3 ? c & 0x0fu : c & 0x07u;
        bool valid = length != 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            valid = (next & 0xc0) == 0x80;
            code = (code << 6) | (next & 0x3fu);
        }
        valid = valid && !(length == 3 && (code < 0x800 || (code >= 0xd800 && code <= 0xdfff))) &&
                !(length == 4 && (code < 0x10000 || code > 0x10ffff));
        if (!valid) {
            escape_byte(c);
            ++i;
            continue;
        }
        const bool control = code < 0xa0 || code == 0x2028 || code == 0x2029 || (code >= 0x202a && code <= 0x202e) ||
                             (code >= 0x2066 && code <= 0x2069);
        if (control) escape_code_point(code);
        else out.append(text.substr(i, length));
        i += length;
    }
    return out;
}

}  // namespace ratbez

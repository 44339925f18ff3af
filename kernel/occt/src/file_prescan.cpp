#include "file_prescan.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "ratbez/error.hpp"

namespace ratbez::occt::detail {
namespace {

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", value);
    return text;
}

[[noreturn]] void refuse(const std::string& path, std::size_t line, const std::string& reason) {
    fail("path", "'" + path + "': line " + std::to_string(line) + ": " + reason);
}

// `token` as a number when all of it is one (strtod needs a terminated string; tokens are short).
bool parse_number(std::string_view token, double& value) {
    if (token.empty() || token.size() > 64) return false;
    const char c = token.front();
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.')) {
        // strtod would take these as numbers, and so may a reader.
        std::string lower;
        for (char ch : token) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (lower == "nan" || lower == "inf" || lower == "infinity") {
            value = NAN;
            return true;
        }
        return false;
    }
    const std::string copy(token);
    char* end = nullptr;
    value = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size();
}

void check_number(const std::string& path, std::size_t line, std::string_view token) {
    double value = 0;
    if (!parse_number(token, value)) return;
    if (!std::isfinite(value) || std::abs(value) > kMaxFileNumber)
        refuse(path, line, "the number " + std::string(token) + " is outside the input limits (finite, magnitude at most " +
                               number_text(kMaxFileNumber) + ")");
}

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

// A count or flag field: a non-negative integer (as a double, so that products of counts cannot overflow).
bool whole(std::string_view token, double& value) {
    return parse_number(token, value) && std::isfinite(value) && value >= 0 && value == std::floor(value);
}

// The header fields of a B-spline record read as OpenCASCADE's reader takes them, operator>> on a stream of
// integers: whitespace, an optional sign and the digits that follow, wherever they stop, across lines. A fuzzed
// file's "150000000 2PolygonOnTriangulations" read as 150000000 x 2 poles, which OpenCASCADE allocated (7.2 GB)
// while a check of whole tokens let it pass. Once a read finds no digits, or a flag (a bool) other than 0 or 1, the
// stream has failed, and every later field keeps its 0: a line of knots or poles that starts with 7 or 9 claims
// nothing unless it reads as a header.
class HeaderFields {
public:
    explicit HeaderFields(std::string_view text) : text_(text) {}

    double next() {
        if (failed_) return 0;
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
        const bool negative = at_ < text_.size() && text_[at_] == '-';
        if (at_ < text_.size() && (text_[at_] == '-' || text_[at_] == '+')) ++at_;
        const std::size_t digits = at_;
        double value = 0;
        while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_])))
            value = 10 * value + (text_[at_++] - '0');
        failed_ = at_ == digits;
        return failed_ ? 0 : (negative ? -value : value);
    }
    // The next field as a count: a negative one allocates nothing.
    double count() { return std::max(0.0, next()); }
    // The next field as a bool flag.
    void flag() {
        const double value = next();
        failed_ = failed_ || (value != 0 && value != 1);
    }

private:
    std::string_view text_;
    std::size_t at_ = 0;
    bool failed_ = false;
};

}  // namespace

void prescan_brep(const std::string& path, const std::string& text) {
    const double size = static_cast<double>(text.size());
    const auto claim = [&](std::size_t line, double bytes, const std::string& what) {
        if (bytes > size)
            refuse(path, line, what + ", more than a file of " + number_text(size) + " bytes can hold");
    };
    std::string_view section;
    std::size_t line_number = 0, start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + start, end - start);
        start = end + 1;
        ++line_number;
        const std::vector<std::string_view> t = split(line);
        if (t.empty()) continue;
        for (std::string_view token : t) check_number(path, line_number, token);
        double count = 0;
        static constexpr std::string_view kSections[] = {"Locations", "Curve2ds", "Curves", "Polygon3D", "PolygonOnTriangulations",
                                                         "Polygons2D", "Surfaces", "Triangulations", "TShapes"};
        if (t.size() == 2 && whole(t[1], count)) {
            bool is_section = false;
            for (std::string_view name : kSections) is_section = is_section || t[0] == name;
            if (is_section) {
                section = t[0];
                // Every entry takes at least a number and a separator.
                claim(line_number, 2 * count, std::string(section) + " claims " + number_text(count) + " entries");
                continue;
            }
        }
        // Lower bounds of the bytes a record takes: each coordinate, weight or knot at least a digit and a space.
        const std::size_t after_type = static_cast<std::size_t>(t[0].data() + t[0].size() - text.data());
        HeaderFields fields(std::string_view(text).substr(after_type));
        if ((section == "Curves" || section == "Curve2ds") && t[0] == "7") {
            fields.flag(), fields.flag(), fields.next();  // rational, periodic, degree
            const double poles = fields.count(), knots = fields.count();
            const double dimension = section == "Curves" ? 3 : 2;
            claim(line_number, 2 * dimension * poles + 4 * knots,
                  "a B-spline curve claims " + number_text(poles) + " poles and " + number_text(knots) + " knots");
        }
        if (section == "Surfaces" && t[0] == "9") {
            for (int k = 0; k < 4; ++k) fields.flag();  // rational and periodic, in u and v
            fields.next(), fields.next();                // degrees
            const double poles = fields.count(), poles_v = fields.count(), knots = fields.count(), knots_v = fields.count();
            claim(line_number, 6 * poles * poles_v + 4 * (knots + knots_v),
                  "a B-spline surface claims " + number_text(poles) + " x " + number_text(poles_v) + " poles");
        }
    }
}

void prescan_step(const std::string& path, const std::string& text) {
    std::unordered_set<std::uint64_t> defined;
    std::vector<std::pair<std::uint64_t, std::size_t>> references;  // (id, line)
    std::size_t line = 1, i = 0;
    int depth = 0;
    const std::size_t n = text.size();
    const auto is = [&](std::size_t k, auto predicate) { return k < n && predicate(static_cast<unsigned char>(text[k])); };
    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (c == '\'') {  // a string; '' is a quote inside it
            for (++i; i < n; ++i) {
                if (text[i] == '\n') ++line;
                if (text[i] == '\'') {
                    if (i + 1 < n && text[i + 1] == '\'') {
                        ++i;
                        continue;
                    }
                    break;
                }
            }
            ++i;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {  // a comment
            const std::size_t close = text.find("*/", i + 2);
            const std::size_t stop = close == std::string::npos ? n : close + 2;
            for (; i < stop; ++i)
                if (text[i] == '\n') ++line;
        } else if (c == '(') {
            if (++depth > kMaxStepNesting)
                refuse(path, line, "parentheses nest deeper than " + std::to_string(kMaxStepNesting) + " levels");
            ++i;
        } else if (c == ')') {
            --depth;
            ++i;
        } else if (c == ';') {
            depth = 0;
            ++i;
        } else if (c == '#') {
            std::size_t k = i + 1;
            std::uint64_t id = 0;
            while (is(k, ::isdigit)) {
                if (id > (std::uint64_t{1} << 40)) refuse(path, line, "an entity number is too large");
                id = id * 10 + static_cast<std::uint64_t>(text[k] - '0');
                ++k;
            }
            if (id > 2147483646) refuse(path, line, "the entity number #" + std::to_string(id) + " is too large (at most 2147483646)");
            std::size_t after = k;
            while (is(after, ::isspace)) ++after;
            if (depth == 0 && after < n && text[after] == '=')
                defined.insert(id);
            else if (k > i + 1)
                references.emplace_back(id, line);
            i = k;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {  // a keyword: its digits are no number
            while (is(i, ::isalnum) || (i < n && text[i] == '_')) ++i;
        } else if (c == '.' && is(i + 1, ::isalpha)) {  // an enumeration .T.
            ++i;
            while (i < n && text[i] != '.' && text[i] != '\n') ++i;
            ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
            const std::size_t begin = i;
            ++i;
            while (is(i, ::isdigit) || (i < n && (text[i] == '.' || text[i] == 'E' || text[i] == 'e' ||
                                                  ((text[i] == '-' || text[i] == '+') && (text[i - 1] == 'E' || text[i - 1] == 'e')))))
                ++i;
            check_number(path, line, std::string_view(text.data() + begin, i - begin));
        } else {
            ++i;
        }
    }
    for (const auto& [id, at] : references)
        if (!defined.contains(id)) refuse(path, at, std::string(1, '#').append(std::to_string(id)).append(" refers to no entity of the file"));
}

}  // namespace ratbez::occt::detail

#pragma once
// Structure-aware mutation of real .brep and STEP files, as the issue 29 campaign mutated them: a number
// made hostile (0, -1, 1e300, 1.E999, NaN, scaled), a count made huge or negative, an entity reference made
// dangling or pointing at its own entity, the file truncated at a line, a line dropped or doubled, a byte
// flipped. One source for the fuzz targets' custom mutators (fuzz_read_brep, fuzz_read_step) and the soak
// campaign (scripts/soak.sh), so that what the soak finds replays through the fuzzers' harness.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ratbez::fuzz {

namespace model_file_detail {

// A tiny deterministic generator (SplitMix64): the same seed mutates the same way on every platform.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }

private:
    std::uint64_t state_;
};

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_word(char c) { return is_digit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }

// [begin, end) of every number token (digits, sign, point, exponent) not part of a word or a reference.
inline std::vector<std::pair<std::size_t, std::size_t>> numbers(std::string_view text, bool integers_only) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        const bool starts = is_digit(c) || ((c == '-' || c == '+' || c == '.') && i + 1 < text.size() && is_digit(text[i + 1]));
        if (!starts || (i > 0 && (is_word(text[i - 1]) || text[i - 1] == '#' || text[i - 1] == '.'))) {
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        bool integer = c != '.';
        while (j < text.size() && (is_digit(text[j]) || text[j] == '.' || text[j] == 'e' || text[j] == 'E' ||
                                   ((text[j] == '-' || text[j] == '+') && (text[j - 1] == 'e' || text[j - 1] == 'E')))) {
            integer = integer && is_digit(text[j]);
            ++j;
        }
        if (!integers_only || integer) out.emplace_back(i, j);
        i = j;
    }
    return out;
}

// [begin, end) of the digits of every "#123".
inline std::vector<std::pair<std::size_t, std::size_t>> references(std::string_view text) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != '#' || !is_digit(text[i + 1])) continue;
        std::size_t j = i + 1;
        while (j < text.size() && is_digit(text[j])) ++j;
        out.emplace_back(i + 1, j);
        i = j - 1;
    }
    return out;
}

// The starts of the lines.
inline std::vector<std::size_t> line_starts(std::string_view text) {
    std::vector<std::size_t> out{0};
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n' && i + 1 < text.size()) out.push_back(i + 1);
    return out;
}

inline void replace(std::string& text, std::pair<std::size_t, std::size_t> span, const std::string& with) {
    text.replace(span.first, span.second - span.first, with);
}

}  // namespace model_file_detail

// One to three mutations of `text` chosen by `seed`.
inline std::string mutate_model_file(std::string text, std::uint64_t seed) {
    using namespace model_file_detail;
    Random random(seed);
    static const char* const kNumbers[] = {"0", "-1", "1e300", "-1e300", "1.E999", "nan", "1e-300", "3", "0.5", "-0", "1e100"};
    static const char* const kCounts[] = {"150000000", "0", "-1", "2147483647", "4294967297", "1", "2", "99999"};
    const std::size_t mutations = 1 + random.below(3);
    for (std::size_t m = 0; m < mutations && !text.empty(); ++m) {
        switch (random.below(7)) {
            case 0: {  // a number made hostile
                const auto spans = numbers(text, false);
                if (spans.empty()) break;
                replace(text, spans[random.below(spans.size())], kNumbers[random.below(std::size(kNumbers))]);
                break;
            }
            case 1: {  // a number scaled or shifted (the "u knots scaled to 1e300" kind of case, milder)
                const auto spans = numbers(text, false);
                if (spans.empty()) break;
                const auto span = spans[random.below(spans.size())];
                const std::string value = text.substr(span.first, span.second - span.first);
                static const char* const kScales[] = {"e6", "e300", "e-9"};
                replace(text, span, random.below(2) == 0 ? value + kScales[random.below(3)] : "-" + value);
                break;
            }
            case 2: {  // a count
                const auto spans = numbers(text, true);
                if (spans.empty()) break;
                replace(text, spans[random.below(spans.size())], kCounts[random.below(std::size(kCounts))]);
                break;
            }
            case 3: {  // a reference: dangling, another entity's, or its own entity's
                const auto spans = references(text);
                if (spans.empty()) break;
                const auto span = spans[random.below(spans.size())];
                const auto other = spans[random.below(spans.size())];
                const std::size_t line = text.rfind('\n', span.first);
                const auto own = references(text.substr(line == std::string::npos ? 0 : line, 24));
                std::string with = text.substr(other.first, other.second - other.first);
                if (random.below(3) == 0) with = "999999";
                if (random.below(3) == 0 && !own.empty()) {
                    const std::size_t base = line == std::string::npos ? 0 : line;
                    with = text.substr(base + own.front().first, own.front().second - own.front().first);
                }
                replace(text, span, with);
                break;
            }
            case 4: {  // truncated at the end of a line (as the "cut after Ed" file) or anywhere
                const auto lines = line_starts(text);
                const std::size_t at = random.below(2) == 0 ? lines[random.below(lines.size())] : random.below(text.size());
                text.resize(at);
                break;
            }
            case 5: {  // a line dropped or doubled
                const auto lines = line_starts(text);
                const std::size_t k = random.below(lines.size());
                const std::size_t end = k + 1 < lines.size() ? lines[k + 1] : text.size();
                const std::string line = text.substr(lines[k], end - lines[k]);
                if (random.below(2) == 0)
                    text.erase(lines[k], end - lines[k]);
                else
                    text.insert(lines[k], line);
                break;
            }
            default:  // a byte flipped
                text[random.below(text.size())] ^= static_cast<char>(1u << random.below(8));
                break;
        }
    }
    return text;
}

}  // namespace ratbez::fuzz

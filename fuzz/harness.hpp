#pragma once
// Shared pieces of the fuzz targets: a byte reader that decodes numbers, sizes and choices from the
// fuzzer's input, and the entry points of each harness, so that tests/reliability can replay crashing
// inputs through exactly the same decoding (the targets are compiled there with RATBEZ_FUZZ_REPLAY,
// which leaves out the LLVMFuzzerTestOneInput entry points).
//
// The contract every harness checks: for any input, the library either works or throws ratbez::Error.
// A harness catches ratbez::Error and nothing else, so any other exception (std::bad_alloc from an
// unvalidated size included), a crash, a leak or a sanitizer report is a finding.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string_view>

#include "ratbez/error.hpp"

namespace ratbez::fuzz {

// Reads values front to back; once the input is used up every read returns zeros, so decoding never
// fails and a short input is simply a small case.
class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    bool empty() const { return position_ >= size_; }
    std::size_t remaining() const { return empty() ? 0 : size_ - position_; }

    std::uint8_t byte() { return empty() ? 0 : data_[position_++]; }
    std::uint32_t u32() {
        std::uint32_t value = 0;
        for (int k = 0; k < 4; ++k) value |= static_cast<std::uint32_t>(byte()) << (8 * k);
        return value;
    }
    std::uint64_t u64() { return static_cast<std::uint64_t>(u32()) | (static_cast<std::uint64_t>(u32()) << 32); }
    bool flag() { return (byte() & 1) != 0; }

    // An integer in [low, high] (high - low < 256), from one byte.
    int small(int low, int high) { return low + static_cast<int>(byte() % static_cast<unsigned>(high - low + 1)); }

    // Any 64-bit pattern as a double: NaN, infinities, denormals and 1e±300 included.
    double raw_double() { return std::bit_cast<double>(u64()); }

    // A number for a coordinate, weight or parameter: mostly "reasonable" values the library must get
    // right (small integers, fractions, scaled values), sometimes hostile ones.
    double number() {
        const std::uint8_t kind = byte();
        switch (kind % 8) {
            case 0: return raw_double();
            case 1: return static_cast<double>(static_cast<std::int8_t>(byte()));          // -128 .. 127
            case 2: return static_cast<double>(byte()) / 255.0;                            // [0, 1]
            case 3: return (static_cast<double>(static_cast<std::int16_t>(u32() & 0xffff)) / 64.0);
            case 4: {  // a mantissa in [1, 2) times 10^e for e in [-30, 30], either sign
                const double mantissa = 1.0 + static_cast<double>(byte()) / 256.0;
                const int exponent = static_cast<int>(byte() % 61) - 30;
                return ((kind & 0x80) ? -1.0 : 1.0) * mantissa * std::pow(10.0, exponent);
            }
            case 5: return 0.0;
            case 6: return 1.0;
            default: return static_cast<double>(byte() % 16) / 4.0;  // 0 .. 3.75 in quarters
        }
    }
    // A positive-leaning value for weights: usually in (0, 4], sometimes anything.
    double weight() {
        const std::uint8_t kind = byte();
        if (kind % 8 == 0) return number();
        return 0.25 + static_cast<double>(kind % 16) / 4.0;
    }

    std::string_view rest() {
        if (empty()) return {};
        const std::string_view text(reinterpret_cast<const char*>(data_ + position_), size_ - position_);
        position_ = size_;
        return text;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t position_ = 0;
};

// Runs one step of a harness on its own, so that a rejected parameter in one query (ratbez::Error, the
// expected answer to bad input) does not hide the next; anything else escapes and is a finding.
template <class Step>
void attempt(Step&& step) {
    try {
        step();
    } catch (const ratbez::Error& error) {
        // RATBEZ_FUZZ_VERBOSE=1 prints what each rejected step said: how to see what a seed decodes to.
        static const bool verbose = std::getenv("RATBEZ_FUZZ_VERBOSE") != nullptr;
        if (verbose) std::fprintf(stderr, "rejected: %s\n", error.what());
    }
}

// A broken invariant: print what and abort, so libFuzzer keeps the input as a crash.
[[noreturn]] inline void invariant_failed(const char* target, const char* what) {
    std::fprintf(stderr, "%s: invariant broken: %s\n", target, what);
    std::abort();
}

// The harnesses (one per fuzz target). Each returns normally for accepted and rejected inputs alike.
void run_spec(const std::uint8_t* data, std::size_t size);      // fuzz_spec.cpp
void run_geometry(const std::uint8_t* data, std::size_t size);  // fuzz_geometry.cpp
void run_mesh(const std::uint8_t* data, std::size_t size);      // fuzz_mesh.cpp
void run_output(const std::uint8_t* data, std::size_t size);    // fuzz_output.cpp
void run_read_brep(const std::uint8_t* data, std::size_t size); // fuzz_read_brep.cpp
void run_read_step(const std::uint8_t* data, std::size_t size); // fuzz_read_step.cpp

}  // namespace ratbez::fuzz

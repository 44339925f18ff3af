// Fuzz target: read_brep_all on mutated real files (issue 29 item 6). Seeds are real .brep files
// (fuzz/corpus/fuzz_read_brep/: FreeCAD's and ratbez's solids, and the files of past findings); the custom
// mutator makes the campaign's structure-aware mutations (model_file_mutation.hpp) three times in four and
// libFuzzer's byte mutations otherwise. read_harness.hpp says what is checked.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "harness.hpp"
#include "model_file_mutation.hpp"
#include "read_harness.hpp"

namespace ratbez::fuzz {

void run_read_brep(const std::uint8_t* data, std::size_t size) { run_read_file(data, size, ".brep", occt::read_brep_all); }

}  // namespace ratbez::fuzz

#ifndef RATBEZ_FUZZ_REPLAY
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
    if (seed % 4 == 0) return LLVMFuzzerMutate(data, size, max_size);
    std::string text = ratbez::fuzz::mutate_model_file(std::string(reinterpret_cast<const char*>(data), size), seed);
    if (text.size() > max_size) text.resize(max_size);
    std::memcpy(data, text.data(), text.size());
    return text.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ratbez::fuzz::attempt([&] { ratbez::fuzz::run_read_brep(data, size); });
    return 0;
}
#endif

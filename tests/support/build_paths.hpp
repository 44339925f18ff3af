#pragma once
// Paths of this checkout and build, for the suites and benchmarks that read files or run programs: each target
// defines those it uses with ratbez_build_paths (CMakeLists.txt), in a generated source of its own, so that its
// other sources compile the same in every clone.

namespace ratbez::build_paths {

extern const char* const examples_dir;           // examples/
extern const char* const corpus_dir;             // tests/corpus/freecad
extern const char* const fuzz_corpus_dir;        // fuzz/corpus
extern const char* const reliability_files_dir;  // tests/reliability/files
extern const char* const cli_data_dir;           // tests/cli/data
extern const char* const cli;                    // the built `ratbez` command
extern const char* const openscad;               // the openscad executable found when configuring

}  // namespace ratbez::build_paths

#pragma once
// A look at a .brep or STEP file before OpenCASCADE reads it: every count the file claims is held against what
// the file's size can hold, and every number against the input limits, so that a 2 KB file claiming
// 150,000,000 poles is refused naming the count instead of OpenCASCADE allocating gigabytes first (or a knot
// of 1e300 sending its translator into an endless loop). Plain text scanning, linear in the file, no OCCT.
// What this cannot see (a reference cycle, a construction OCCT loops on) the child process bounds
// (child_process.hpp).

#include <string>

namespace ratbez::occt::detail {

// Numbers of larger magnitude are refused: the coordinate limit 1e100 (README "Input limits") with room for
// OpenCASCADE's own "infinite" 2e100.
inline constexpr double kMaxFileNumber = 1e101;
// Parentheses nested deeper in one STEP entity are refused (real entities nest a handful of levels; OCCT's
// parser recurses on each, 10^5 of them overflow its stack).
inline constexpr int kMaxStepNesting = 32;

// Throw Error("path", "'<path>': line N: ...") naming the count or number that the file cannot hold or that
// is outside the limits; `text` is the file's content.
void prescan_brep(const std::string& path, const std::string& text);
void prescan_step(const std::string& path, const std::string& text);

}  // namespace ratbez::occt::detail

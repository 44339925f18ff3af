#pragma once
// Work that may crash, loop or balloon whatever we do (OpenCASCADE's translators on hostile files: stack
// overflows, endless loops, allocations of what a count claims) run in a forked child process under limits,
// so that none of it can take the caller down. The child hands back bytes; the parent polls it and the
// caller's Progress every few milliseconds, so a Progress that throws (Ctrl-C) kills the child at once.
// Signal handlers inside OpenCASCADE cannot do this: a stack overflow or a runaway allocation is not a signal
// one can return from. No OCCT header here.

#include <cstddef>
#include <functional>
#include <string>

#include "ratbez/progress.hpp"

namespace ratbez::occt::detail {

struct ChildLimits {
    double seconds = 0;              // wall clock (the parent kills the child) and CPU time (RLIMIT_CPU)
    std::size_t memory_bytes = 0;    // address space the child may add to what it inherits (RLIMIT_AS)
};

// The limits for reading a file of `file_bytes` bytes: 10 s + 5 s per MB, 1 GiB + 64 bytes per byte of the
// file. RATBEZ_READ_SECONDS / RATBEZ_READ_MEGABYTES in the environment override them (README "Input limits").
ChildLimits reader_limits(std::size_t file_bytes);

// How the parent words its refusals, a reader's by default: Error(argument, what + ": " + doing + " took longer than
// " + limit + ...). The check's BOP analysis runs in a child too, in its own words.
struct ChildWords {
    std::string argument = "path";
    std::string doing = "reading it";
    std::string limit = "the reader's limit";
    std::string seconds_setting = " (RATBEZ_READ_SECONDS sets it)";
    std::string memory_setting = " (RATBEZ_READ_MEGABYTES sets it)";
    std::string crashed = "OpenCASCADE's reader crashed on it";
    std::string crash_reason = "the file is damaged or hostile";
};

// What the child's work may call to report its fraction done (forwarded to the parent's Progress).
using ChildProgress = std::function<void(double fraction)>;

// Runs `work` in a forked child under `limits` and returns the bytes it returned. In the child, a ratbez::Error
// is handed back and rethrown here as it was; any other exception becomes Error("path", what + ": " + text).
// The parent throws Error(words.argument, ...) naming `what` (e.g. "'a.step'") when the child crashes (the signal),
// runs past the time limit, or runs out of its memory; whatever `progress` throws is rethrown after the child
// is killed (within one poll interval, 20 ms). `work` must not touch the parent's threads or interpreter: it
// runs in a copy of the process with one thread.
std::string run_in_child(const std::string& what, const ChildLimits& limits, const Progress& progress,
                         const std::function<std::string(const ChildProgress&)>& work, const ChildWords& words = {});

}  // namespace ratbez::occt::detail

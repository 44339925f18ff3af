// The readers' mutation campaign (issue 29 item 6; scripts/soak.sh runs it): thousands of real .brep and STEP
// files mutated as fuzz_read_brep / fuzz_read_step mutate them (fuzz/model_file_mutation.hpp), each read with
// read_brep_all / read_step_all in a child process of its own, as a user would: a Progress that presses Ctrl-C
// after 1 s, and the solids read held against their own meshes and converted back both ways
// (fuzz/read_harness.hpp). Counts, per format: read, refused (ratbez::Error), cancelled within the 0.5 s Ctrl-C
// latency, and the failures: crashes, hangs (no answer in 20 s, or Ctrl-C landing later than 0.5 s),
// inconsistent solids, exceptions other than ratbez::Error; and, apart, check_hang: a solid read whose
// consistency check (its tessellation) ran past 8 s. Each failure's file is kept in the findings folder.
// Usage: reliability_soak_readers COUNT SEED_FOLDER FINDINGS_FOLDER [FIRST_SEED]
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "model_file_mutation.hpp"
#include "ratbez/progress.hpp"
#include "read_harness.hpp"

namespace {

using namespace ratbez;
using Clock = std::chrono::steady_clock;

enum Outcome : int { kRead = 0, kRefused = 1, kInconsistent = 2, kLateCancel = 3, kOtherException = 4, kCancelled = 5, kMeshHang = 6 };

// The consistency check after a read (tessellation, conversions) has no Ctrl-C of its own here: past 8 s it
// is a hang of the check, counted apart from the readers' (it is not the reader that hangs).
void check_took_too_long(int) { ::_exit(kMeshHang); }

// In the child: one read as a user would do it, the outcome as the exit code.
[[noreturn]] void read_one(const std::string& file, bool step) {
    ::setenv("RATBEZ_READ_SECONDS", "10", 1);
    const Clock::time_point start = Clock::now();
    Clock::time_point pressed;
    const Progress ctrl_c = [&](double) {
        if (Clock::now() - start > std::chrono::seconds(1)) {
            pressed = Clock::now();
            throw Cancelled();
        }
    };
    try {
        const std::vector<Solid> solids = step ? occt::read_step_all(file, ctrl_c) : occt::read_brep_all(file, ctrl_c);
        ::signal(SIGALRM, check_took_too_long);
        ::alarm(8);
        for (const Solid& solid : solids) {
            if (const auto why = fuzz::inconsistency(solid)) {
                std::fprintf(stderr, "%s: inconsistent: %s\n", file.c_str(), why->c_str());
                ::_exit(kInconsistent);
            }
            try {
                (void)occt::brep_string(solid, occt::ConvertOptions{false});
                (void)occt::brep_string(solid, occt::ConvertOptions{true});
            } catch (const Error&) {
            }
        }
        ::_exit(kRead);
    } catch (const Cancelled&) {
        ::_exit(Clock::now() - pressed > std::chrono::milliseconds(500) ? kLateCancel : kCancelled);
    } catch (const Error&) {
        ::_exit(kRefused);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", file.c_str(), e.what());
        ::_exit(kOtherException);
    } catch (...) {
        ::_exit(kOtherException);
    }
}

std::string read_all(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s COUNT SEED_FOLDER FINDINGS_FOLDER [FIRST_SEED]\n", argv[0]);
        return 2;
    }
    const long count = std::atol(argv[1]);
    const std::filesystem::path findings = argv[3];
    const std::uint64_t first = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 0;
    std::vector<std::filesystem::path> seeds;
    for (const auto& entry : std::filesystem::directory_iterator(argv[2])) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".brep" || ext == ".step" || ext == ".stp")) seeds.push_back(entry.path());
    }
    std::sort(seeds.begin(), seeds.end());
    if (seeds.empty()) {
        std::fprintf(stderr, "no .brep / .step seeds in %s\n", argv[2]);
        return 2;
    }
    std::filesystem::create_directories(findings);
    const std::filesystem::path work = std::filesystem::temp_directory_path() / ("ratbez_soak_" + std::to_string(::getpid()));
    std::filesystem::create_directories(work);
    std::map<std::string, std::map<std::string, long>> counts;  // format -> outcome -> count
    for (long i = 0; i < count; ++i) {
        const std::filesystem::path& seed = seeds[static_cast<std::size_t>(i) % seeds.size()];
        const bool step = seed.extension() != ".brep";
        const std::string format = step ? "step" : "brep";
        const std::uint64_t mutation = first + static_cast<std::uint64_t>(i);
        const std::string mutated = fuzz::mutate_model_file(read_all(seed), mutation);
        const std::filesystem::path file = work / (seed.stem().string() + "." + std::to_string(mutation) + "." + format);
        std::ofstream(file, std::ios::binary) << mutated;
        std::fflush(nullptr);
        const pid_t pid = ::fork();
        if (pid == 0) {
            const rlimit memory{rlim_t{4} << 30, rlim_t{4} << 30};  // the reader's child adds its own limit
            ::setrlimit(RLIMIT_AS, &memory);
            read_one(file.string(), step);
        }
        int status = 0;
        const Clock::time_point deadline = Clock::now() + std::chrono::seconds(20);
        bool hung = false;
        while (::waitpid(pid, &status, WNOHANG) == 0) {
            if (Clock::now() > deadline) {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, &status, 0);
                hung = true;
                break;
            }
            ::usleep(5000);
        }
        std::string outcome;
        if (hung) {
            outcome = "hang";
        } else if (WIFSIGNALED(status)) {
            outcome = "crash";
        } else {
            switch (WEXITSTATUS(status)) {
                case kRead: outcome = "read"; break;
                case kRefused: outcome = "refused"; break;
                case kCancelled: outcome = "cancelled"; break;
                case kInconsistent: outcome = "inconsistent"; break;
                case kLateCancel: outcome = "hang"; break;  // Ctrl-C landed later than 0.5 s
                case kMeshHang: outcome = "check_hang"; break;
                default: outcome = "other_exception"; break;
            }
        }
        ++counts[format][outcome];
        if (outcome == "hang" || outcome == "crash" || outcome == "inconsistent" || outcome == "other_exception" ||
            outcome == "check_hang") {
            std::filesystem::copy_file(file, findings / (outcome + "-" + file.filename().string()),
                                       std::filesystem::copy_options::overwrite_existing);
            std::printf("%s: %s\n", outcome.c_str(), file.filename().c_str());
            std::fflush(stdout);
        }
        std::filesystem::remove(file);
    }
    std::filesystem::remove_all(work);
    long failures = 0;
    for (const auto& [format, by_outcome] : counts) {
        std::printf("%s:", format.c_str());
        for (const auto& [outcome, n] : by_outcome) {
            std::printf(" %s %ld", outcome.c_str(), n);
            if (outcome == "hang" || outcome == "crash" || outcome == "inconsistent" || outcome == "other_exception") failures += n;
        }
        std::printf("\n");
    }
    return failures == 0 ? 0 : 1;
}

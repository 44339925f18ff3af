// Issue 14, items 1-5 through the real command: a kill during the write leaves the old file (SIGKILL) and
// no temporary file behind (every signal that ends the command, issue 29 item 7, each saying why in one
// line; SIGXFSZ, the file size limit, an error line and exit code 2); a symbolic link at the target is
// refused for every format; a long file name works.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "build_paths.hpp"
#include "temp_directory_test_support.hpp"

namespace {

namespace fs = std::filesystem;

using ratbez::test::read_file;

class OutputFile : public ratbez::test::TempDirectoryTest {
protected:
    OutputFile() : TempDirectoryTest("output_test") {}

    // The command started in the background, its stdout discarded and its stderr to `error_file` (default:
    // discarded), with a file size limit of `file_size_limit` bytes when given; returns its pid.
    static pid_t start(const std::vector<std::string>& args, const std::string& error_file = "/dev/null",
                       rlim_t file_size_limit = RLIM_INFINITY) {
        const pid_t pid = fork();
        if (pid == 0) {
            std::vector<char*> argv{const_cast<char*>(ratbez::build_paths::cli)};
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            // No progress line on the stderr the tests read, however slow the build (a sanitizer's).
            setenv("RATBEZ_PROGRESS_AFTER", "1e9", 1);
            // A background test runner may have signals ignored or blocked: the command gets the defaults.
            for (const int s : {SIGHUP, SIGINT, SIGQUIT, SIGPIPE, SIGALRM, SIGTERM, SIGUSR1, SIGXFSZ}) signal(s, SIG_DFL);
            sigset_t none;
            sigemptyset(&none);
            sigprocmask(SIG_SETMASK, &none, nullptr);
            const rlimit no_core{0, 0};  // SIGQUIT's default action dumps core: not into the test's folder
            setrlimit(RLIMIT_CORE, &no_core);
            if (file_size_limit != RLIM_INFINITY) {
                const rlimit size{file_size_limit, file_size_limit};
                setrlimit(RLIMIT_FSIZE, &size);
            }
            std::freopen("/dev/null", "w", stdout);
            std::freopen(error_file.c_str(), "w", stderr);
            execv(ratbez::build_paths::cli, argv.data());
            _exit(127);
        }
        return pid;
    }
    static int wait_status(pid_t pid) {
        int status = 0;
        waitpid(pid, &status, 0);
        return status;
    }
    std::vector<std::string> temporaries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(directory_))
            if (entry.path().filename().string().starts_with(".ratbez-")) names.push_back(entry.path().filename());
        return names;
    }
    // Polls (0.1 ms) until the writer's temporary file exists or the process has ended; true if it was seen
    // while the process still ran.
    bool wait_for_temporary(pid_t pid) const {
        for (int i = 0; i < 200000; ++i) {
            if (!temporaries().empty()) return true;
            int status = 0;
            if (waitpid(pid, &status, WNOHANG) == pid) return false;
            std::this_thread::sleep_for(std::chrono::microseconds(100));
        }
        return false;
    }
    // Writes the STEP file of examples/vase.json to `target` and kills the command with `signal_number`
    // while its temporary file exists (the conversion and the write happen then); retried a few times in
    // case the machine is fast enough to finish first.
    int interrupt_step_export(const fs::path& target, int signal_number, const std::string& error_file = "/dev/null") const {
        for (int attempt = 0; attempt < 5; ++attempt) {
            const pid_t pid =
                start({"export", std::string(ratbez::build_paths::examples_dir) + "/vase.json", "-o", target.string()}, error_file);
            if (wait_for_temporary(pid)) {
                kill(pid, signal_number);
                return wait_status(pid);
            }
            wait_status(pid);
            std::ofstream(target) << "old";
        }
        ADD_FAILURE() << "the command finished before it could be interrupted, 5 times";
        return 0;
    }

};

TEST_F(OutputFile, SigkillDuringAStepWriteLeavesTheOldFile) {
    const fs::path target = directory_ / "vase.step";
    std::ofstream(target) << "old";
    const int status = interrupt_step_export(target, SIGKILL);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    EXPECT_EQ(read_file(target), "old");  // written in place, it was a 0-byte or partial file
}

TEST_F(OutputFile, SigtermAndSigintRemoveTheTemporaryFile) {
    for (const int signal_number : {SIGTERM, SIGINT}) {
        const fs::path target = directory_ / "vase.step";
        std::ofstream(target) << "old";
        const int status = interrupt_step_export(target, signal_number);
        // The handler removes the temporary, then the signal ends the command as it would have.
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number)
            << signal_number << " status " << status;
        EXPECT_EQ(read_file(target), "old");
        EXPECT_TRUE(temporaries().empty()) << temporaries().front();
    }
}

// Issue 29 item 7: SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1 and SIGALRM left the temporary file behind (only SIGINT and
// SIGTERM removed it), and no signal said why the command stopped. Each now removes it, writes one line
// naming the signal and the file not written, and ends the command as the signal would have.
TEST_F(OutputFile, EverySignalThatEndsTheCommandRemovesTheTemporaryAndSaysWhy) {
    const struct {
        int number;
        const char* name;
    } signals[] = {{SIGHUP, "SIGHUP"},   {SIGQUIT, "SIGQUIT"}, {SIGPIPE, "SIGPIPE"}, {SIGUSR1, "SIGUSR1"},
                   {SIGALRM, "SIGALRM"}, {SIGINT, "SIGINT"},   {SIGTERM, "SIGTERM"}};
    const fs::path errors = directory_ / "stderr.txt";
    for (const auto& [number, name] : signals) {
        const fs::path target = directory_ / "vase.step";
        std::ofstream(target) << "old";
        const int status = interrupt_step_export(target, number, errors.string());
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == number) << name << " status " << status;
        EXPECT_EQ(read_file(target), "old") << name;
        EXPECT_TRUE(temporaries().empty()) << name << ": " << temporaries().front();
        const std::string line = read_file(errors);
        EXPECT_EQ(line.rfind(std::string("ratbez: stopped by ") + name + " (", 0), 0u) << line;
        EXPECT_NE(line.find(target.string() + "' not written"), std::string::npos) << line;
        EXPECT_EQ(line.find('\n'), line.size() - 1) << "not one line: " << line;
    }
}

// Issue 29 item 7: a write past the file size limit (ulimit -f) raised SIGXFSZ, whose default action ended
// the command with a core dump, no message and the temporary left behind. It is now the write's error: one
// line "error: path: ...", exit code 2, the old file kept, no temporary; for the streamed writers (.stl) and
// OpenCASCADE's writer by name (.step) alike, and for a SIGXFSZ sent by kill during a write.
TEST_F(OutputFile, TheFileSizeLimitIsAOneLineErrorAndLeavesNoTemporary) {
    const fs::path errors = directory_ / "stderr.txt";
    for (const std::string extension : {".stl", ".step"}) {
        const fs::path target = directory_ / ("out" + extension);
        std::ofstream(target) << "old";
        const pid_t pid = start({"export", std::string(ratbez::build_paths::examples_dir) + "/vase.json", "-o", target.string()},
                                errors.string(), 2048);
        const int status = wait_status(pid);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << extension << " status " << status;
        EXPECT_EQ(read_file(target), "old") << extension;
        EXPECT_TRUE(temporaries().empty()) << extension;
        EXPECT_EQ(read_file(errors), "error: path: '" + target.string() +
                                         "' reached the file size limit (ulimit -f) and was not written\n");
    }
    const fs::path target = directory_ / "vase.step";
    std::ofstream(target) << "old";
    const int status = interrupt_step_export(target, SIGXFSZ, errors.string());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
    EXPECT_EQ(read_file(target), "old");
    EXPECT_TRUE(temporaries().empty());
    EXPECT_EQ(read_file(errors),
              "error: path: '" + target.string() + "' reached the file size limit (ulimit -f) and was not written\n");
}

TEST_F(OutputFile, SymbolicLinkAtTheTargetIsRefusedForEveryFormat) {
    const fs::path victim = directory_ / "victim.txt";
    std::ofstream(victim) << "precious";
    for (const std::string extension : {".scad", ".stl", ".off", ".step", ".brep"}) {
        const fs::path link = directory_ / ("out" + extension);
        fs::create_symlink(victim, link);
        const pid_t pid = start({"export", std::string(ratbez::build_paths::examples_dir) + "/cylinder.json", "-o", link.string()});
        const int status = wait_status(pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << extension;
        EXPECT_EQ(read_file(victim), "precious") << extension;
        EXPECT_TRUE(fs::is_symlink(link)) << extension;
    }
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(OutputFile, LongFileNamesWork) {
    for (const std::string extension : {".scad", ".step"}) {
        const fs::path target = directory_ / (std::string(255 - extension.size(), 'n') + extension);
        const pid_t pid = start({"export", std::string(ratbez::build_paths::examples_dir) + "/cylinder.json", "-o", target.string()});
        const int status = wait_status(pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << extension;
        EXPECT_GT(fs::file_size(target), 100u) << extension;
    }
}

}  // namespace

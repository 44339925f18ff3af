// Issue 14, items 1-5 through the real command: a kill during the write leaves the old file (SIGKILL) and
// no temporary file behind (SIGINT, SIGTERM); a symbolic link at the target is refused for every format;
// a long file name works.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "temp_directory_test_support.hpp"

namespace {

namespace fs = std::filesystem;

using ratbez::test::read_file;

class OutputFile : public ratbez::test::TempDirectoryTest {
protected:
    OutputFile() : TempDirectoryTest("output_test") {}

    // The command started in the background, its output discarded; returns its pid.
    static pid_t start(const std::vector<std::string>& args) {
        const pid_t pid = fork();
        if (pid == 0) {
            std::vector<char*> argv{const_cast<char*>(RATBEZ_CLI)};
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            signal(SIGINT, SIG_DFL);  // a background test runner may have them ignored
            signal(SIGTERM, SIG_DFL);
            std::freopen("/dev/null", "w", stdout);
            std::freopen("/dev/null", "w", stderr);
            execv(RATBEZ_CLI, argv.data());
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
    int interrupt_step_export(const fs::path& target, int signal_number) const {
        for (int attempt = 0; attempt < 5; ++attempt) {
            const pid_t pid = start({"export", std::string(RATBEZ_EXAMPLES_DIR) + "/vase.json", "-o", target.string()});
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

TEST_F(OutputFile, SymbolicLinkAtTheTargetIsRefusedForEveryFormat) {
    const fs::path victim = directory_ / "victim.txt";
    std::ofstream(victim) << "precious";
    for (const std::string extension : {".scad", ".stl", ".off", ".step", ".brep"}) {
        const fs::path link = directory_ / ("out" + extension);
        fs::create_symlink(victim, link);
        const pid_t pid = start({"export", std::string(RATBEZ_EXAMPLES_DIR) + "/cylinder.json", "-o", link.string()});
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
        const pid_t pid = start({"export", std::string(RATBEZ_EXAMPLES_DIR) + "/cylinder.json", "-o", target.string()});
        const int status = wait_status(pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << extension;
        EXPECT_GT(fs::file_size(target), 100u) << extension;
    }
}

}  // namespace

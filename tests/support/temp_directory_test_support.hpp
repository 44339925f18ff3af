#pragma once
// The fixture of every test that writes files (the output writer, exports, STEP/BREP, the command): a fresh
// folder per test under the system's temporary folder, removed afterwards, and a whole-file read.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

namespace ratbez::test {

inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// directory_ is "<temp>/ratbez_<prefix>_<test name>_<process id>", empty when each test starts. The process id
// keeps two runs of the suite apart (two build trees tested at once: one's TearDown removed the other's folder).
class TempDirectoryTest : public ::testing::Test {
protected:
    explicit TempDirectoryTest(std::string prefix) : prefix_(std::move(prefix)) {}

    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("ratbez_" + prefix_ + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                      std::to_string(getpid()));
        std::filesystem::remove_all(directory_);
        std::filesystem::create_directories(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }

    std::string path(const std::string& name) const { return (directory_ / name).string(); }

    std::filesystem::path directory_;

private:
    std::string prefix_;
};

}  // namespace ratbez::test

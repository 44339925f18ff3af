// The safe writer of every output file (issue 14, items 1-6): new exclusive temporary, rename over the target.

#include "ratbez/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "temp_directory_test_support.hpp"
#include "ratbez/error.hpp"

namespace {

namespace fs = std::filesystem;
using ratbez::output::write_file;
using ratbez::output::write_file_by_name;

using ratbez::test::read_file;

class OutputFile : public ratbez::test::TempDirectoryTest {
protected:
    OutputFile() : TempDirectoryTest("output_file") {}
    std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(directory_), {})); }
};

// The reason of the Error `call` throws; the argument must be "path".
template <class Call>
std::string path_error(Call call) {
    try {
        call();
    } catch (const ratbez::Error& e) {
        EXPECT_EQ(e.argument(), "path") << e.what();
        return std::string(e.reason());
    }
    ADD_FAILURE() << "no ratbez::Error";
    return {};
}

void write_text(const fs::path& path, const std::string& text) {
    write_file(path.string(), [&](std::ostream& out) { out << text; });
}

TEST_F(OutputFile, WritesAndReplacesKeepingTheMode) {
    const fs::path target = directory_ / "a.txt";
    write_text(target, "first");
    EXPECT_EQ(read_file(target), "first");
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    write_text(target, "second");
    EXPECT_EQ(read_file(target), "second");
    EXPECT_EQ(fs::status(target).permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    EXPECT_EQ(entries(), 1u);  // no temporary left
}

TEST_F(OutputFile, AFailingWriterLeavesTheTargetAndNoTemporary) {
    const fs::path target = directory_ / "a.txt";
    write_text(target, "old");
    EXPECT_THROW(write_file(target.string(),
                            [](std::ostream& out) {
                                out << std::string(200000, 'x');  // past the buffer: bytes are on disk
                                throw ratbez::Error("mesh", "refused");
                            }),
                 ratbez::Error);
    EXPECT_EQ(read_file(target), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFile, SymbolicLinkAtTheTargetIsRefusedAndItsFileUntouched) {
    const fs::path victim = directory_ / "victim.txt", link = directory_ / "out.scad";
    write_text(victim, "precious");
    fs::create_symlink(victim, link);
    EXPECT_NE(path_error([&] { write_text(link, "attack"); }).find("symbolic link"), std::string::npos);
    EXPECT_NE(path_error([&] { write_file_by_name(link.string(), [](const std::string&) {}); }).find("symbolic link"),
              std::string::npos);
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_TRUE(fs::is_symlink(link));
    // The old fixed temporary name, planted as a link, is never used.
    fs::create_symlink(victim, directory_ / "out.stl.ratbez-partial");
    write_text(directory_ / "out.stl", "mesh");
    EXPECT_EQ(read_file(victim), "precious");
    EXPECT_EQ(read_file(directory_ / "out.stl"), "mesh");
}

TEST_F(OutputFile, ConcurrentWritersEachLeaveAWholeFile) {
    const fs::path target = directory_ / "shared.txt";
    std::vector<std::string> texts;
    for (int k = 0; k < 16; ++k) texts.push_back(std::string(100000 + 7919 * k, static_cast<char>('a' + k)));
    std::vector<std::thread> writers;
    for (const std::string& text : texts) writers.emplace_back([&] { write_text(target, text); });
    for (std::thread& writer : writers) writer.join();
    const std::string result = read_file(target);
    EXPECT_NE(std::find(texts.begin(), texts.end(), result), texts.end()) << "a splice of " << result.size() << " bytes";
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFile, BadPathsAreRefusedNamingTheCause) {
    EXPECT_NE(path_error([&] { write_text("", "x"); }).find("empty"), std::string::npos);
    EXPECT_NE(path_error([&] { write_text(directory_.string() + "/a.stl" + std::string(1, '\0') + ".txt", "x"); }).find("NUL"),
              std::string::npos);
    EXPECT_NE(path_error([&] { write_text(directory_, "x"); }).find("folder"), std::string::npos);
    const std::string missing = path_error([&] { write_text(directory_ / "missing" / "a.txt", "x"); });
    EXPECT_NE(missing.find((directory_ / "missing").string() + "' of"), std::string::npos) << missing;
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    EXPECT_NE(path_error([&] { write_text(directory_ / std::string(256, 'n'), "x"); }).find("limit 255"), std::string::npos);
    EXPECT_EQ(entries(), 0u);
}

TEST_F(OutputFile, NamesOfNameMaxBytesWork) {
    const fs::path target = directory_ / (std::string(251, 'n') + ".stl");  // 255 bytes: no room for any suffix
    write_text(target, "long");
    EXPECT_EQ(read_file(target), "long");
}

TEST_F(OutputFile, ByNameWriterGetsTheTemporaryFile) {
    const fs::path target = directory_ / "a.step";
    write_text(target, "old");
    write_file_by_name(target.string(), [](const std::string& name) { std::ofstream(name) << "by name"; });
    EXPECT_EQ(read_file(target), "by name");
    EXPECT_THROW(write_file_by_name(target.string(),
                                    [](const std::string& name) {
                                        std::ofstream(name) << "partial";
                                        throw std::runtime_error("writer failed");
                                    }),
                 std::runtime_error);
    EXPECT_EQ(read_file(target), "by name");
    EXPECT_EQ(entries(), 1u);
}

}  // namespace

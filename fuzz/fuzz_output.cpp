// Fuzz target: the safe file writer (kernel/output, output_file.hpp) against whatever the folder holds.
// An input is a short script of writes into a fresh scratch folder. Each write decodes: the target's
// name (plain, odd bytes, a NUL inside, near or past NAME_MAX, under a missing folder or under a file,
// "." and ".."), what is at the target before (nothing, a file, a read-only file, a symbolic link to a
// file outside the folder, a dangling link, a folder), the bytes to write, where the writer fails
// part-way (ratbez::Error, another exception, or not at all) and which entry point writes
// (write_file, or write_file_by_name as OpenCASCADE's writers use it). After every write the guarantees
// are checked on the folder as a whole:
//  - success: the target is a regular file holding exactly the bytes, with the permission bits an
//    existing file had; nothing else in the folder changed;
//  - failure: the folder is exactly as it was (names, kinds, contents, link targets);
//  - the file outside that links point to never changes, and no temporary file is ever left behind;
//  - only ratbez::Error naming "path" (or the writer's own exception) comes out.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>

#include "harness.hpp"
#include "ratbez/error.hpp"
#include "ratbez/output_file.hpp"

namespace ratbez::fuzz {
namespace {

namespace fs = std::filesystem;

// The writer's own failure, which must come out of write_file unchanged.
struct WriterFailure : std::runtime_error {
    WriterFailure() : std::runtime_error("the writer failed part-way") {}
};

// Everything observable about one folder entry.
struct Entry {
    fs::file_type type = fs::file_type::none;
    std::string content;  // a regular file's bytes, a link's target
    fs::perms permissions = fs::perms::none;
    bool operator==(const Entry&) const = default;
};
using Snapshot = std::map<std::string, Entry>;

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Snapshot snapshot(const fs::path& folder) {
    Snapshot result;
    for (const auto& item : fs::directory_iterator(folder)) {
        const fs::file_status status = fs::symlink_status(item.path());
        Entry entry{status.type(), {}, status.permissions()};
        if (status.type() == fs::file_type::regular) entry.content = read_all(item.path());
        if (status.type() == fs::file_type::symlink) entry.content = fs::read_symlink(item.path()).string();
        result[item.path().filename().string()] = entry;
    }
    return result;
}

// One scratch folder per process: `work` (the folder written into, emptied before each input) and
// `outside` (the file links point to).
struct Scratch {
    fs::path root, work, outside;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "ratbez-fuzz-output-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) invariant_failed("fuzz_output", "cannot make a scratch folder");
        root = pattern;
        work = root / "work";
        outside = root / "outside.txt";
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(root, ignored);
    }
    void reset() const {
        std::error_code ignored;
        fs::permissions(work, fs::perms::owner_all, ignored);
        fs::remove_all(work, ignored);
        fs::create_directory(work);
        std::ofstream(outside, std::ios::binary) << "a file of the user's, outside the folder";
    }
};

std::string decode_name(ByteReader& in) {
    switch (in.small(0, 7)) {
        case 0: return "out" + std::to_string(in.small(0, 2)) + ".scad";  // a few names, so writes meet
        case 1: {  // odd bytes (no '/': that is case 5)
            std::string name;
            for (int k = in.small(1, 24); k > 0; --k) {
                const char c = static_cast<char>(in.byte());
                name += c == '/' ? '_' : c;
            }
            return name;
        }
        case 2: return std::string(static_cast<std::size_t>(in.small(240, 260)), 'n');  // about NAME_MAX (255)
        case 3: return std::string("nul") + '\0' + ".scad";
        case 4: return "missing/out.scad";
        case 5: return "plain.txt/out.scad";  // under a regular file
        case 6: return in.flag() ? "." : "..";
        default: return "";
    }
}

// Puts `kind` of thing at `path` (nothing when the name cannot hold one).
void plant(const fs::path& path, int kind, const fs::path& outside) {
    std::error_code ignored;
    switch (kind) {
        case 1: std::ofstream(path, std::ios::binary) << "old contents"; break;
        case 2:
            std::ofstream(path, std::ios::binary) << "read-only contents";
            fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read, ignored);
            break;
        case 3: fs::create_symlink(outside, path, ignored); break;
        case 4: fs::create_symlink(path.parent_path() / "nowhere", path, ignored); break;
        case 5: fs::create_directory(path, ignored); break;
        default: break;
    }
}

void write_once(ByteReader& in, const Scratch& scratch) {
    const std::string name = decode_name(in);
    const int before = in.small(0, 5);
    std::string bytes;
    for (int k = in.small(0, 64); k > 0; --k) bytes += static_cast<char>(in.byte());
    const int failure = in.small(0, 3);  // 0, 1: none; 2: ratbez::Error; 3: another exception
    const std::size_t fail_after = static_cast<std::size_t>(in.small(0, 64)) % (bytes.size() + 1);
    const bool by_name = in.flag();

    const std::string path = (scratch.work / name).string();
    if (name.find('\0') == std::string::npos && !name.empty() && name != "." && name != "..") plant(path, before, scratch.outside);
    std::ofstream(scratch.work / "plain.txt", std::ios::binary) << "a neighbour";
    const std::string outside_before = read_all(scratch.outside);
    const Snapshot folder_before = snapshot(scratch.work);

    const auto fail_now = [&] {
        if (failure == 2) throw Error("content", "the writer refused part-way");
        if (failure == 3) throw WriterFailure();
    };
    bool written = false;
    try {
        if (by_name) {
            output::write_file_by_name(path, [&](const std::string& temporary) {
                std::ofstream out(temporary, std::ios::binary);
                out.write(bytes.data(), static_cast<std::streamsize>(fail_after));
                out.flush();
                fail_now();
                out.write(bytes.data() + fail_after, static_cast<std::streamsize>(bytes.size() - fail_after));
            });
        } else {
            output::write_file(path, [&](std::ostream& out) {
                out.write(bytes.data(), static_cast<std::streamsize>(fail_after));
                fail_now();
                out.write(bytes.data() + fail_after, static_cast<std::streamsize>(bytes.size() - fail_after));
            });
        }
        written = true;
    } catch (const WriterFailure&) {
        if (failure != 3) invariant_failed("fuzz_output", "the writer's exception came out of a write that did not throw it");
    } catch (const Error& e) {
        if (e.argument() != "path" && !(failure == 2 && e.argument() == "content"))
            invariant_failed("fuzz_output", "an Error naming neither the path nor the writer's own came out");
    }
    if (written && failure >= 2) invariant_failed("fuzz_output", "a write whose writer threw reported success");

    if (read_all(scratch.outside) != outside_before) invariant_failed("fuzz_output", "the file a link points to changed");
    Snapshot expected = folder_before;
    if (written) {
        const fs::path target(path);
        if (target.parent_path() != scratch.work) invariant_failed("fuzz_output", "wrote outside the folder");
        const std::string leaf = target.filename().string();
        const auto old = folder_before.find(leaf);
        Entry& entry = expected[leaf];
        if (old != folder_before.end() && old->second.type != fs::file_type::regular)
            invariant_failed("fuzz_output", "replaced something that was not a regular file");
        entry.type = fs::file_type::regular;
        entry.content = bytes;
        if (old == folder_before.end()) entry.permissions = fs::symlink_status(target).permissions();
    }
    if (snapshot(scratch.work) != expected)
        invariant_failed("fuzz_output", written ? "a successful write changed more than its target, or not to the bytes"
                                                : "a failed write changed the folder (a temporary or the target)");
}

}  // namespace

void run_output(const std::uint8_t* data, std::size_t size) {
    static const Scratch scratch;
    scratch.reset();
    ByteReader in(data, size);
    for (int writes = in.small(1, 3); writes > 0; --writes) write_once(in, scratch);
}

}  // namespace ratbez::fuzz

#ifndef RATBEZ_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ratbez::fuzz::run_output(data, size);
    return 0;
}
#endif

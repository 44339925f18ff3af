#include "ratbez/output_file.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <exception>
#include <random>
#include <streambuf>
#include <string_view>
#include <tuple>
#include <utility>

#include "ratbez/error.hpp"

namespace ratbez::output {
namespace {

// Built by appending: GCC 12's -Wrestrict misreads the inlined "'" + std::string(text) (a false positive).
std::string quoted(std::string_view text) {
    std::string result;
    result.reserve(text.size() + 2);
    result += '\'';
    result += text;
    result += '\'';
    return result;
}

// ---- The temporary files in flight, for the signal handler --------------------------------------------------
// A fixed table (no allocation, no lock: a signal may arrive anywhere); a slot is claimed with `used`, filled,
// then published with `ready`, so the handler only ever reads a complete name. More concurrent writes than
// slots are written just the same; only their cleanup on a signal is skipped. The target's name is kept too:
// the handler's line says which file was not written.
struct TemporarySlot {
    std::atomic<bool> used{false};
    std::atomic<bool> ready{false};
    char name[PATH_MAX + 1]{};
    char target[PATH_MAX + 1]{};
};
std::array<TemporarySlot, 64> temporaries;

TemporarySlot* register_temporary(const std::string& name, const std::string& target) {
    if (name.size() > PATH_MAX || target.size() > PATH_MAX) return nullptr;
    for (TemporarySlot& slot : temporaries) {
        bool expected = false;
        if (!slot.used.compare_exchange_strong(expected, true)) continue;
        std::memcpy(slot.name, name.c_str(), name.size() + 1);
        std::memcpy(slot.target, target.c_str(), target.size() + 1);
        slot.ready.store(true);
        return &slot;
    }
    return nullptr;
}

void release(TemporarySlot* slot) {
    if (!slot) return;
    slot->ready.store(false);
    slot->used.store(false);
}

// ---- The signals that end the program -----------------------------------------------------------------------
// Every signal whose default action ends the process and that arrives from outside (a terminal, kill, a
// closed pipe, a timer, a resource limit): the handler removes the temporaries, says in one line on stderr
// why the program stopped and which file it did not write, then ends the process as the signal would have.
// Synchronous faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS) are left to their default
// action and to the sanitizers, which report them better than a line could.
struct EndingSignal {
    int number;
    const char* name;
    const char* reason;
};
constexpr EndingSignal ending_signals[] = {
    {SIGHUP, "SIGHUP", "the terminal hung up"},
    {SIGINT, "SIGINT", "interrupted"},
    {SIGQUIT, "SIGQUIT", "quit"},
    {SIGPIPE, "SIGPIPE", "the pipe it writes to was closed"},
    {SIGALRM, "SIGALRM", "a timer expired"},
    {SIGTERM, "SIGTERM", "asked to terminate"},
    {SIGUSR1, "SIGUSR1", "user signal 1"},
    {SIGUSR2, "SIGUSR2", "user signal 2"},
    {SIGXCPU, "SIGXCPU", "the CPU time limit (ulimit -t) was reached"},
    {SIGXFSZ, "SIGXFSZ", "the file size limit (ulimit -f) was reached"},
    {SIGVTALRM, "SIGVTALRM", "a virtual timer expired"},
    {SIGPROF, "SIGPROF", "a profiling timer expired"},
    {SIGPOLL, "SIGPOLL", "a pollable event"},
    {SIGPWR, "SIGPWR", "power failure"},
    {SIGSTKFLT, "SIGSTKFLT", "a stack fault"},
};

// The program name that starts the handler's line ("ratbez"); a fixed buffer, set before any handler.
char program_name[64] = "ratbez";

// An async-signal-safe line buffer: text appended up to its size, written with one write(2).
struct SignalLine {
    char text[1024];
    std::size_t size = 0;
    void add(const char* s) {
        while (*s != '\0' && size + 1 < sizeof text) text[size++] = *s++;
    }
    // A file name quoted, its control bytes escaped as \xNN (a name cannot forge lines or drive the terminal).
    void add_quoted(const char* s) {
        static constexpr char hex[] = "0123456789abcdef";
        add("'");
        for (; *s != '\0' && size + 5 < sizeof text; ++s) {
            const auto c = static_cast<unsigned char>(*s);
            if (c < 0x20 || c == 0x7f) {
                const char escaped[] = {'\\', 'x', hex[c >> 4], hex[c & 15], '\0'};
                add(escaped);
            } else {
                text[size++] = static_cast<char>(c);
            }
        }
        add("'");
    }
    // Written with SIGPIPE ignored: a closed stderr must not replace the signal being handled by another.
    void write_out() {
        if (size + 1 < sizeof text) text[size++] = '\n';
        else text[sizeof text - 1] = '\n', size = sizeof text;
        struct sigaction ignore {}, previous {};
        ignore.sa_handler = SIG_IGN;
        sigemptyset(&ignore.sa_mask);
        ::sigaction(SIGPIPE, &ignore, &previous);
        write_all();
        ::sigaction(SIGPIPE, &previous, nullptr);
    }
    void write_all() const {
        const char* data = text;
        std::size_t left = size;
        while (left > 0) {
            const ssize_t written = ::write(STDERR_FILENO, data, left);
            if (written <= 0) {
                if (written < 0 && errno == EINTR) continue;
                return;
            }
            data += written;
            left -= static_cast<std::size_t>(written);
        }
    }
};

extern "C" void remove_temporaries_and_reraise(int signal_number) {
    const int saved_errno = errno;
    SignalLine line;
    const EndingSignal* which = nullptr;
    for (const EndingSignal& s : ending_signals)
        if (s.number == signal_number) which = &s;
    // SIGXFSZ comes from a write past the file size limit: that is the write's error, worded as the
    // command's other errors are (its "error: path: ..." line and exit code 2), not a crash.
    const bool file_too_large = signal_number == SIGXFSZ;
    if (file_too_large) {
        line.add("error: path: ");
    } else {
        line.add(program_name);
        line.add(": stopped by ");
        line.add(which != nullptr ? which->name : "a signal");
        line.add(" (");
        line.add(which != nullptr ? which->reason : "ended");
        line.add(")");
    }
    bool first = true;
    for (TemporarySlot& slot : temporaries) {
        if (!slot.ready.load()) continue;
        ::unlink(slot.name);  // async-signal-safe
        line.add(first ? (file_too_large ? "" : "; ") : ", ");
        line.add_quoted(slot.target);
        first = false;
    }
    if (file_too_large) {
        if (first) line.add("a file");
        line.add(" reached the file size limit (ulimit -f) and was not written");
    } else if (!first) {
        line.add(" not written (its temporary file was removed)");
    }
    line.write_out();
    if (file_too_large) _exit(2);
    errno = saved_errno;
    std::raise(signal_number);  // SA_RESETHAND restored the default action
}

// The handled signals as a set (blocked while a temporary file is created and registered).
sigset_t handled_signals() {
    sigset_t set;
    sigemptyset(&set);
    for (const EndingSignal& s : ending_signals) sigaddset(&set, s.number);
    return set;
}

// ---- An ostream over a file descriptor ---------------------------------------------------------------------
// Buffered writes straight to the descriptor; the first failing write() is remembered (errno) and reported by
// the caller, naming the file, whatever the writer made of the stream's bad state.
class DescriptorBuffer : public std::streambuf {
public:
    explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    int error() const { return error_; }
    bool flush_all() { return drain() && error_ == 0; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const char* data = pbase();
        std::size_t left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0 && error_ == 0) {
            const ssize_t written = ::write(fd_, data, left);
            if (written < 0) {
                if (errno != EINTR) error_ = errno;
                continue;
            }
            data += written;
            left -= static_cast<std::size_t>(written);
        }
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return error_ == 0;
    }

    int fd_;
    int error_ = 0;
    std::array<char, 1 << 16> buffer_{};
};

// ---- The target and its folder ------------------------------------------------------------------------------
struct Target {
    std::string folder;       // as given ("" for the current folder): the temporary goes here
    std::string folder_name;  // for messages
    bool exists = false;
    mode_t mode = 0;  // the permission bits of an existing target, kept
};

Target inspect_target(const std::string& path) {
    require(!path.empty(), "path", "is empty");
    require(path.find('\0') == std::string::npos, "path", "contains a NUL character");
    require(path.back() != '/', "path", quoted(path) + " names a folder, not a file");
    Target target;
    const std::size_t slash = path.rfind('/');
    target.folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    target.folder_name = target.folder.empty() ? "." : target.folder == "/" ? "/" : path.substr(0, slash);
    const std::string_view name = slash == std::string::npos ? std::string_view(path) : std::string_view(path).substr(slash + 1);
    require(name != "." && name != "..", "path", quoted(path) + " names a folder, not a file");
    require(name.size() <= NAME_MAX, "path", [&] {
        return "the file name in " + quoted(path) + " has " + std::to_string(name.size()) + " bytes, above the limit " +
               std::to_string(NAME_MAX) + " of the file system";
    });

    struct stat folder_status {};
    const std::string folder_path = target.folder.empty() ? "." : target.folder;
    if (::stat(folder_path.c_str(), &folder_status) != 0) {
        const int error = errno;
        throw Error("path", "the folder " + quoted(target.folder_name) + " of " + quoted(path) + " " +
                                (error == ENOENT ? std::string("does not exist") : std::strerror(error)));
    }
    require(S_ISDIR(folder_status.st_mode), "path", quoted(target.folder_name) + " is not a folder");

    struct stat status {};
    if (::lstat(path.c_str(), &status) != 0) {
        const int error = errno;
        require(error == ENOENT, "path", [&] { return "cannot inspect " + quoted(path) + ": " + std::strerror(error); });
        return target;
    }
    require(!S_ISLNK(status.st_mode), "path",
            quoted(path) + " is a symbolic link: ratbez neither writes through a link nor replaces it; give the "
                           "file it points to, or remove the link");
    require(!S_ISDIR(status.st_mode), "path", quoted(path) + " is a folder");
    require(S_ISREG(status.st_mode), "path", quoted(path) + " exists and is not a regular file");
    // As a shell redirect: replace only what the user may write (a read-only file stays as it is).
    require(::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) == 0, "path",
            quoted(path) + " is read-only: refusing to replace it (make it writable or remove it first)");
    target.exists = true;
    target.mode = status.st_mode & 07777;
    return target;
}

// A new file in the target's folder, created exclusively under a random name; its descriptor and name.
std::pair<int, std::string> create_temporary(const std::string& path, const Target& target) {
    static constexpr char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    thread_local std::mt19937_64 random{std::random_device{}()};
    std::uniform_int_distribution<std::size_t> pick(0, sizeof alphabet - 2);
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string name = target.folder + ".ratbez-";
        for (int i = 0; i < 12; ++i) name += alphabet[pick(random)];
        name += ".tmp";
        // The mode of a replaced file, else an ordinary new file's (0666 less the umask).
        const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                              target.exists ? target.mode : 0666);
        if (fd >= 0) return {fd, name};
        if (errno == EEXIST) continue;
        const int error = errno;
        if (error == EACCES || error == EPERM || error == EROFS)
            throw Error("path", "cannot write " + quoted(path) + ": the folder " + quoted(target.folder_name) +
                                    " is not writable (" + std::strerror(error) + ")");
        throw Error("path", "cannot create a file in the folder " + quoted(target.folder_name) + " for " + quoted(path) +
                                ": " + std::strerror(error));
    }
    throw Error("path", "cannot create a temporary file in the folder " + quoted(target.folder_name));
}

// The temporary file from creation to rename: removed unless committed, also on a signal (see above).
class Temporary {
public:
    Temporary(const std::string& path, const Target& target) : path_(path), target_(target) {
        // The handled signals wait until the new file is registered for removal (else one arriving between
        // creation and registration would leave it behind).
        const sigset_t blocked = handled_signals();
        sigset_t previous;
        pthread_sigmask(SIG_BLOCK, &blocked, &previous);
        try {
            std::tie(fd_, name_) = create_temporary(path, target);
            slot_ = register_temporary(name_, path);
        } catch (...) {
            pthread_sigmask(SIG_SETMASK, &previous, nullptr);
            throw;
        }
        pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;
    ~Temporary() {
        if (fd_ >= 0) ::close(fd_);
        if (!committed_) ::unlink(name_.c_str());
        release(slot_);
    }

    int fd() const { return fd_; }
    const std::string& name() const { return name_; }

    [[noreturn]] void fail(const std::string& what, int error = errno) const {
        throw Error("path", what + " " + quoted(path_) + ": " + std::strerror(error));
    }

    // fsync, close and rename over the target.
    void commit() {
        // open() applied the umask; a replaced file keeps its exact bits.
        if (target_.exists && ::fchmod(fd_, target_.mode) != 0) fail("cannot set the permissions of");
        if (::fsync(fd_) != 0 && errno != EINVAL) fail("writing");
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) fail("writing");
        if (::rename(name_.c_str(), path_.c_str()) != 0) fail("cannot replace");
        committed_ = true;
        release(slot_);  // written: a signal from now on must not call it unwritten
        slot_ = nullptr;
    }

private:
    std::string path_;
    Target target_;
    int fd_ = -1;
    std::string name_;
    TemporarySlot* slot_ = nullptr;
    bool committed_ = false;
};

}  // namespace

void write_file(const std::string& path, const std::function<void(std::ostream& out)>& write) {
    const Target target = inspect_target(path);
    Temporary temporary(path, target);
    DescriptorBuffer buffer(temporary.fd());
    std::ostream out(&buffer);
    try {
        write(out);
        out.flush();
    } catch (const std::exception&) {
        // A stream failure is the file's (disk full, quota); the writer's own errors pass as they are.
        if (buffer.error() != 0) temporary.fail("writing", buffer.error());
        throw;
    }
    if (!buffer.flush_all()) temporary.fail("writing", buffer.error());
    if (!out) throw Error("path", "writing " + quoted(path) + " failed");
    temporary.commit();
}

void write_file_by_name(const std::string& path, const std::function<void(const std::string& name)>& write) {
    const Target target = inspect_target(path);
    Temporary temporary(path, target);
    // /proc/self/fd/N opens the file the descriptor refers to, not whatever bears its name by then.
    const std::string bound = "/proc/self/fd/" + std::to_string(temporary.fd());
    struct stat status {};
    write(::stat(bound.c_str(), &status) == 0 ? bound : temporary.name());
    temporary.commit();
}

void remove_temporaries_on_signals(const char* program) {
    if (program != nullptr) {
        std::strncpy(program_name, program, sizeof program_name - 1);
        program_name[sizeof program_name - 1] = '\0';
    }
    for (const EndingSignal& s : ending_signals) {
        struct sigaction previous {};
        ::sigaction(s.number, nullptr, &previous);
        if (previous.sa_handler == SIG_IGN) continue;  // ignored when we started (nohup, a background job): stays so
        struct sigaction action {};
        action.sa_handler = remove_temporaries_and_reraise;
        // The other handled signals wait while the handler runs: one line, one cleanup.
        action.sa_mask = handled_signals();
        action.sa_flags = SA_RESETHAND;
        ::sigaction(s.number, &action, nullptr);
    }
}

}  // namespace ratbez::output

#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <optional>
#include <vector>

#include "ratbez/error.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define RATBEZ_CHILD_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RATBEZ_CHILD_UNDER_ASAN 1
#endif
#endif

namespace ratbez::occt::detail {
namespace {

// The pipe from child to parent carries records: a tag byte, a 64-bit size, that many bytes.
constexpr char kProgress = 'P', kResult = 'R', kError = 'E';
constexpr auto kPollInterval = std::chrono::milliseconds(20);
// The least memory a reader may be given (RATBEZ_READ_MEGABYTES): at 1 MB OpenCASCADE's STEP reader failed
// inside its own error handling and a 16 KB file was called "not a readable STEP file"; at 16 MB a 2.5 MB file
// was refused in the right words, and at 64 MB it was read.
constexpr double kLeastMegabytes = 64;

bool write_all(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

void write_record(int fd, char tag, const std::string& bytes) {
    const std::uint64_t size = bytes.size();
    char header[1 + sizeof size];
    header[0] = tag;
    std::memcpy(header + 1, &size, sizeof size);
    if (!write_all(fd, header, sizeof header) || !write_all(fd, bytes.data(), bytes.size())) ::_exit(3);
}

// A limit set in the environment: unset or empty keeps the default. Anything else but a number in [least,
// most] is an Error naming the variable, not the default kept silently (a mistyped limit the user relies on);
// `most` keeps the deadline within the clock's range (1e10 s overflowed it and failed every read at once).
std::optional<double> environment_limit(const char* name, double least, double most, const char* unit) {
    const char* text = std::getenv(name);
    if (text == nullptr || *text == '\0') return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    require(end != text && *end == '\0' && value >= least && value <= most, name, [&] {
        return std::string("must be a number of ") + unit + " from " + exact_number(least) + " to " +
               exact_number(most) + ", got '" + printable(text) + "'";
    });
    return value;
}

#ifndef RATBEZ_CHILD_UNDER_ASAN
// Bytes of address space the process holds now (the child inherits the parent's: the libraries, the
// interpreter); the child's limit is this plus its budget.
std::size_t address_space_now() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    statm >> pages;
    return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}
#endif

// The child's side: limits, a quiet stdout, default signal actions (the parent's handlers — Python's, the
// CLI's that remove its temporaries — are not the child's business), then the work; never returns.
[[noreturn]] void child_main(int fd, pid_t parent, const ChildLimits& limits, const std::function<std::string(const ChildProgress&)>& work) {
    // A parent that ends without reaping it (killed, or a signal handler that re-raises, as the CLI's does) takes
    // the child with it instead of leaving it running to its time limit.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(4);  // the parent ended before the line above
    // Ctrl-C reaches the whole process group: the parent decides, the child ignores it.
    ::signal(SIGINT, SIG_IGN);
    for (int s : {SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGUSR2, SIGALRM, SIGXFSZ, SIGXCPU, SIGSEGV, SIGBUS,
                  SIGFPE, SIGILL, SIGABRT})
        ::signal(s, SIG_DFL);
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDOUT_FILENO);
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    const auto cpu = static_cast<rlim_t>(std::ceil(limits.seconds)) + 1;
    const rlimit cpu_limit{cpu, cpu + 1};
    ::setrlimit(RLIMIT_CPU, &cpu_limit);
#ifndef RATBEZ_CHILD_UNDER_ASAN
    // AddressSanitizer reserves terabytes of shadow address space: no address-space limit under it.
    const rlim_t memory = address_space_now() + limits.memory_bytes;
    const rlimit memory_limit{memory, memory};
    ::setrlimit(RLIMIT_AS, &memory_limit);
#endif
    double reported = -1;
    const ChildProgress report = [fd, &reported](double fraction) {
        // A record per 0.1% is plenty; OpenCASCADE polls far more often than that.
        if (!(std::abs(fraction - reported) >= 1e-3)) return;
        reported = fraction;
        std::string bytes(sizeof fraction, '\0');
        std::memcpy(bytes.data(), &fraction, sizeof fraction);
        write_record(fd, kProgress, bytes);
    };
    try {
        write_record(fd, kResult, work(report));
    } catch (const Error& e) {
        write_record(fd, kError, std::string(e.argument()) + '\0' + std::string(e.reason()));
    } catch (const std::bad_alloc&) {
        write_record(fd, kError, std::string("memory") + '\0');
    } catch (const std::exception& e) {
        write_record(fd, kError, std::string("path") + '\0' + e.what());
    } catch (...) {
        write_record(fd, kError, std::string("path") + '\0' + "an unknown exception");
    }
    ::_exit(0);
}

// The parent's side: the records read so far, and the child's final answer once it has come.
class Records {
public:
    void add(const char* data, std::size_t size) {
        buffer_.append(data, size);
        constexpr std::size_t kHeader = 1 + sizeof(std::uint64_t);
        while (buffer_.size() - start_ >= kHeader) {
            std::uint64_t size_of = 0;
            std::memcpy(&size_of, buffer_.data() + start_ + 1, sizeof size_of);
            if (buffer_.size() - start_ - kHeader < size_of) break;
            const char tag = buffer_[start_];
            std::string bytes = buffer_.substr(start_ + kHeader, size_of);
            start_ += kHeader + size_of;
            if (tag == kProgress && bytes.size() == sizeof(double)) {
                std::memcpy(&fraction_, bytes.data(), sizeof(double));
                fresh_.push_back(fraction_);
            } else if (tag == kResult || tag == kError) {
                answer_ = std::move(bytes);
                failed_ = tag == kError;
            }
        }
        if (start_ > (1u << 20)) {
            buffer_.erase(0, start_);
            start_ = 0;
        }
    }
    // The fractions the child reported since the last call (each one: a caller counting reports sees them
    // all), or the latest again when there is none new (so that the caller's Progress is polled anyway).
    std::vector<double> take_fractions() {
        std::vector<double> out;
        out.swap(fresh_);
        if (out.empty()) out.push_back(fraction_);
        return out;
    }
    const std::optional<std::string>& answer() const { return answer_; }
    bool failed() const { return failed_; }

private:
    std::string buffer_;
    std::size_t start_ = 0;
    double fraction_ = 0;
    std::vector<double> fresh_;
    std::optional<std::string> answer_;
    bool failed_ = false;
};

// Kills and reaps the child unless it was reaped: every way out of run_in_child leaves no process behind.
class ChildGuard {
public:
    explicit ChildGuard(pid_t pid) : pid_(pid) {}
    ~ChildGuard() {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            int status = 0;
            while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
            }
        }
    }
    // The child's wait status once it has ended (nullopt when it cannot be waited for: SIGCHLD ignored).
    std::optional<int> wait() {
        int status = 0;
        pid_t got;
        while ((got = ::waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
        }
        pid_ = 0;
        if (got < 0) return std::nullopt;
        return status;
    }
    void kill() {
        ::kill(pid_, SIGKILL);
        wait();
    }
    ChildGuard(const ChildGuard&) = delete;
    ChildGuard& operator=(const ChildGuard&) = delete;

private:
    pid_t pid_;
};

class FileDescriptor {
public:
    explicit FileDescriptor(int fd = -1) : fd_(fd) {}
    ~FileDescriptor() { reset(); }
    void reset() {
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }
    int get() const { return fd_; }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;

private:
    int fd_;
};

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g s", seconds);
    return text;
}

}  // namespace

ChildLimits reader_limits(std::size_t file_bytes) {
    const double megabytes = static_cast<double>(file_bytes) / 1e6;
    ChildLimits limits{10 + 5 * megabytes, (std::size_t{1} << 30) + 64 * file_bytes};
    if (const auto seconds = environment_limit("RATBEZ_READ_SECONDS", 0.01, 1e7, "seconds")) limits.seconds = *seconds;
    if (const auto megabytes_limit = environment_limit("RATBEZ_READ_MEGABYTES", kLeastMegabytes, 1e9, "megabytes"))
        limits.memory_bytes = static_cast<std::size_t>(*megabytes_limit * 1e6);
    return limits;
}

std::string run_in_child(const std::string& what, const ChildLimits& limits, const Progress& progress,
                         const std::function<std::string(const ChildProgress&)>& work, const ChildWords& words) {
    const char* argument_name = words.argument.c_str();
    int fds[2];
    require(::pipe2(fds, O_CLOEXEC) == 0, argument_name, what + ": cannot start a child process (" + std::strerror(errno) + ")");
    FileDescriptor read_end(fds[0]), write_end(fds[1]);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    require(pid >= 0, argument_name, what + ": cannot start a child process (" + std::strerror(errno) + ")");
    if (pid == 0) {
        ::close(fds[0]);
        child_main(fds[1], parent, limits, work);
    }
    ChildGuard child(pid);
    write_end.reset();  // so that the read end sees end-of-file when the child ends, however it ends

    const auto start = std::chrono::steady_clock::now();
    const auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(limits.seconds));
    Records records;
    std::string chunk(65536, '\0');
    for (;;) {
        if (progress)
            for (double fraction : records.take_fractions()) progress(fraction);  // may throw: the guard kills the child
        if (std::chrono::steady_clock::now() > deadline) {
            child.kill();
            fail(argument_name, what + ": " + words.doing + " took longer than " + words.limit + " of " +
                                    seconds_text(limits.seconds) + words.seconds_setting);
        }
        pollfd poll_fd{read_end.get(), POLLIN, 0};
        const int ready = ::poll(&poll_fd, 1, static_cast<int>(kPollInterval.count()));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        const ssize_t n = ::read(read_end.get(), chunk.data(), chunk.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        records.add(chunk.data(), static_cast<std::size_t>(n));
    }
    const std::optional<int> status = child.wait();
    if (status && WIFSIGNALED(*status)) {
        const int signal = WTERMSIG(*status);
        if (signal == SIGXCPU || signal == SIGKILL)
            fail(argument_name, what + ": " + words.doing + " took longer than " + words.limit + " of " +
                                    seconds_text(limits.seconds) + " of CPU time" + words.seconds_setting);
        fail(argument_name, what + ": " + words.crashed + " (signal " + std::to_string(signal) + ", " +
                                ::strsignal(signal) + "); " + words.crash_reason);
    }
    require(records.answer().has_value(), argument_name, what + ": the child process ended without an answer (exit status " +
                                                      std::to_string(status ? WEXITSTATUS(*status) : -1) + ")");
    if (records.failed()) {
        const std::string& text = *records.answer();
        const std::size_t split = text.find('\0');
        const std::string argument = text.substr(0, split);
        if (argument == "memory")
            fail(argument_name, what + ": " + words.doing + " needs more memory than " + words.limit + " of " +
                                    std::to_string(limits.memory_bytes / 1000000) + " MB" + words.memory_setting);
        throw Error(argument, split == std::string::npos ? std::string() : text.substr(split + 1));
    }
    return *records.answer();
}

}  // namespace ratbez::occt::detail

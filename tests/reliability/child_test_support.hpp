#pragma once
// Running a test's body where a crash or a hang cannot take the test binary down: a forked child with a memory
// and a time limit; the test asks whether it returned normally.

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <functional>

namespace ratbez::test {

// Runs `body` in a child process with at most `address_space` bytes of memory (none under AddressSanitizer,
// which reserves terabytes of address space) and `seconds` of time; true when it returned normally.
inline bool completes_in_child(const std::function<void()>& body, rlim_t address_space, unsigned seconds) {
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
#if !defined(__SANITIZE_ADDRESS__)
        const rlimit limit{address_space, address_space};
        setrlimit(RLIMIT_AS, &limit);
#else
        (void)address_space;
#endif
        alarm(seconds);  // a hang ends the child (SIGALRM), and the test fails
        try {
            body();
        } catch (...) {
            _exit(1);
        }
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace ratbez::test

// Test support: run a program (no shell) in a chosen working directory with a timeout and
// capture its stdout, stderr and exit status; plus a self-deleting temporary directory.
// Header-only, POSIX (fork/execv). Used by the conformance, golden-image and CLI tests.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rays::test {

/// Outcome of runProcess. Exactly one of: startError non-empty, timedOut, termSignal != 0,
/// or exitCode >= 0 (normal exit).
struct ProcessResult {
    std::string out;         ///< everything the program wrote to stdout
    std::string err;         ///< everything the program wrote to stderr
    int exitCode = -1;       ///< exit status when it exited normally, else -1
    int termSignal = 0;      ///< signal that killed it (not counting our timeout kill), else 0
    bool timedOut = false;   ///< killed by runProcess after the timeout
    std::string startError;  ///< why it could not be started (fork, chdir, execv), else empty

    /// True when the program ran to completion and exited with status 0.
    bool ok() const { return startError.empty() && !timedOut && termSignal == 0 && exitCode == 0; }

    /// One line saying how the program ended, e.g. "exit status 2" or "killed by signal 11 (...)".
    std::string summary() const {
        if (!startError.empty()) return "could not start: " + startError;
        if (timedOut) return "timed out (killed)";
        if (termSignal != 0)
            return "killed by signal " + std::to_string(termSignal) + " (" + strsignal(termSignal) + ")";
        return "exit status " + std::to_string(exitCode);
    }
};

namespace detail {

inline void writeErrno(int fd, const char* what) {
    // Async-signal-safe report from the forked child: "<what>: <errno>".
    const int e = errno;
    char buf[64];
    size_t n = 0;
    for (const char* p = what; *p && n < 40; ++p) buf[n++] = *p;
    buf[n++] = ':';
    char digits[12];
    int d = 0;
    int v = e < 0 ? 0 : e;
    do {
        digits[d++] = char('0' + v % 10);
        v /= 10;
    } while (v && d < 11);
    while (d) buf[n++] = digits[--d];
    ssize_t ignored = ::write(fd, buf, n);
    (void)ignored;
}

inline std::string decodeStartError(const std::string& msg) {
    // msg is "<what>:<errno>" as written by writeErrno.
    const size_t colon = msg.rfind(':');
    if (colon == std::string::npos) return msg;
    const int e = std::atoi(msg.c_str() + colon + 1);
    return msg.substr(0, colon) + " failed: " + std::strerror(e);
}

}  // namespace detail

/// Runs `program` (a path; no PATH search, no shell) with `args` as argv[1..] in `workDir`
/// (empty = inherit), stdin = /dev/null; kills its process group after `timeout`. Never throws.
inline ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                                const std::string& workDir = {},
                                std::chrono::milliseconds timeout = std::chrono::seconds(120)) {
    ProcessResult result;

    // Everything the child needs is prepared before fork (no allocation after fork).
    std::vector<std::string> argStore;
    argStore.reserve(args.size() + 1);
    argStore.push_back(program);
    argStore.insert(argStore.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argStore) argv.push_back(a.data());
    argv.push_back(nullptr);
    const char* dir = workDir.empty() ? nullptr : workDir.c_str();

    int outPipe[2], errPipe[2], failPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0) {
        result.startError = std::string("pipe failed: ") + std::strerror(errno);
        return result;
    }
    if (::pipe2(errPipe, O_CLOEXEC) != 0) {
        result.startError = std::string("pipe failed: ") + std::strerror(errno);
        ::close(outPipe[0]);
        ::close(outPipe[1]);
        return result;
    }
    if (::pipe2(failPipe, O_CLOEXEC) != 0) {
        result.startError = std::string("pipe failed: ") + std::strerror(errno);
        for (int fd : {outPipe[0], outPipe[1], errPipe[0], errPipe[1]}) ::close(fd);
        return result;
    }

    const pid_t pid = ::fork();
    if (pid < 0) {
        result.startError = std::string("fork failed: ") + std::strerror(errno);
        for (int fd : {outPipe[0], outPipe[1], errPipe[0], errPipe[1], failPipe[0], failPipe[1]})
            ::close(fd);
        return result;
    }
    if (pid == 0) {
        // Child: own process group (so a timeout kills grandchildren too), redirect, exec.
        ::setpgid(0, 0);
        ::signal(SIGPIPE, SIG_DFL);
        if (dir && ::chdir(dir) != 0) {
            detail::writeErrno(failPipe[1], "chdir");
            ::_exit(127);
        }
        const int devNull = ::open("/dev/null", O_RDONLY);
        if (devNull >= 0) ::dup2(devNull, STDIN_FILENO);
        if (::dup2(outPipe[1], STDOUT_FILENO) < 0 || ::dup2(errPipe[1], STDERR_FILENO) < 0) {
            detail::writeErrno(failPipe[1], "dup2");
            ::_exit(127);
        }
        ::execv(argv[0], argv.data());
        detail::writeErrno(failPipe[1], "execv");
        ::_exit(127);
    }

    // Parent.
    ::setpgid(pid, pid);  // also done in the child; whichever runs first wins, both are fine
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    ::close(failPipe[1]);

    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + timeout;
    std::string failMsg;
    struct Stream {
        int fd;
        std::string* sink;
    } streams[3] = {{outPipe[0], &result.out}, {errPipe[0], &result.err}, {failPipe[0], &failMsg}};
    int openCount = 3;
    char buf[65536];
    while (openCount > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0) {
            result.timedOut = true;
            break;
        }
        pollfd fds[3];
        int idx[3];
        int n = 0;
        for (int i = 0; i < 3; ++i) {
            if (streams[i].fd < 0) continue;
            fds[n] = {streams[i].fd, POLLIN, 0};
            idx[n++] = i;
        }
        const int ready = ::poll(fds, nfds_t(n), int(std::min<long long>(left.count(), 1000)));
        if (ready < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (int k = 0; k < n; ++k) {
            if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            Stream& s = streams[idx[k]];
            const ssize_t got = ::read(s.fd, buf, sizeof buf);
            if (got > 0) {
                s.sink->append(buf, size_t(got));
            } else if (got == 0 || (errno != EINTR && errno != EAGAIN)) {
                ::close(s.fd);
                s.fd = -1;
                --openCount;
            }
        }
    }
    for (auto& s : streams)
        if (s.fd >= 0) ::close(s.fd);

    // Pipes are closed (or we timed out); reap the child, still honouring the deadline.
    int status = 0;
    bool reaped = false;
    while (!result.timedOut) {
        const pid_t w = ::waitpid(pid, &status, WNOHANG);
        if (w == pid) {
            reaped = true;
            break;
        }
        if (w < 0 && errno != EINTR) break;
        if (Clock::now() >= deadline) {
            result.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (result.timedOut) {
        ::kill(-pid, SIGKILL);
        ::kill(pid, SIGKILL);
    }
    if (!reaped) {
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    }

    if (!failMsg.empty()) {
        result.startError = detail::decodeStartError(failMsg);
    } else if (!result.timedOut) {
        if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
        else if (WIFSIGNALED(status)) result.termSignal = WTERMSIG(status);
    }
    return result;
}

/// A fresh, empty directory under the system temp dir, named "<prefix>XXXXXX"; removed with its
/// contents on destruction unless keep() was called. path() is empty if creation failed.
class TempDir {
public:
    explicit TempDir(const std::string& prefix = "rays-test-") {
        std::error_code ec;
        std::string tmpl = (std::filesystem::temp_directory_path(ec) / (prefix + "XXXXXX")).string();
        if (ec) tmpl = "/tmp/" + prefix + "XXXXXX";
        if (::mkdtemp(tmpl.data())) path_ = tmpl;
    }
    ~TempDir() {
        if (!keep_ && !path_.empty()) {
            std::error_code ec;
            std::filesystem::remove_all(path_, ec);
        }
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    /// Absolute path of the directory (empty if mkdtemp failed).
    const std::filesystem::path& path() const { return path_; }
    /// Leave the directory on disk after destruction (e.g. to inspect a failure).
    void keep() { keep_ = true; }

private:
    std::filesystem::path path_;
    bool keep_ = false;
};

}  // namespace rays::test

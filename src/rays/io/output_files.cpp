#include "rays/io/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "rays/error.h"

namespace rays {
namespace {

std::atomic<unsigned> tempCounter{0};

std::string errnoText(int e) { return std::strerror(e); }

/// Writes all of data to fd; returns 0 or an errno value.
int writeAll(int fd, const uint8_t* data, size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, std::min(size, size_t(1) << 30));
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        data += n;
        size -= size_t(n);
    }
    return 0;
}

}  // namespace

OutputFiles::~OutputFiles() {
    for (const Pending& p : pending_) ::unlink(p.tmp.c_str());
}

void OutputFiles::stage(const std::string& path, const std::vector<uint8_t>& data) {
    const std::string tmp =
        path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(tempCounter.fetch_add(1));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) failFile(path, "cannot create file: " + errnoText(errno));

    // The file replaced keeps its permissions: the temporary takes them before the rename.
    int e = 0;
    struct stat old {};
    if (::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode) && ::fchmod(fd, old.st_mode & 07777) != 0) e = errno;
    // No fsync: the rename makes the update atomic for readers of the file, which is what matters for a
    // renderer overwriting its output; durability across a power cut is not worth the latency here.
    if (e == 0) e = writeAll(fd, data.data(), data.size());
    if (::close(fd) != 0 && e == 0) e = errno;
    if (e != 0) {
        ::unlink(tmp.c_str());
        failFile(path, "write failed: " + errnoText(e));
    }
    pending_.push_back({path, tmp, {}});
}

// The hidden backup name of path: ".NAME.bak.PID.N" in the same folder.
static std::string backupPath(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + name + ".bak." + std::to_string(::getpid()) + "." + std::to_string(tempCounter.fetch_add(1));
}

// Each destination that exists (and is not a folder, which the rename will refuse anyway) gets a
// backup: a hard link, or where the file system has none the file itself renamed aside. Throws,
// with every backup undone and every temporary removed, when one cannot be made.
void OutputFiles::keepBackups(std::vector<Pending>& todo) {
    for (size_t i = 0; i < todo.size(); ++i) {
        struct stat st {};
        if (::lstat(todo[i].path.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) continue;
        const std::string backup = backupPath(todo[i].path);
        if (::link(todo[i].path.c_str(), backup.c_str()) == 0 || ::rename(todo[i].path.c_str(), backup.c_str()) == 0) {
            todo[i].backup = backup;
            continue;
        }
        const int e = errno;
        rollBack(todo, 0);
        for (const Pending& p : todo) ::unlink(p.tmp.c_str());
        failFile(todo[i].path, "cannot keep a backup of the file: " + errnoText(e));
    }
}

// Undoes the first `replaced` renames (backups back over their files, new files removed) and
// puts back files renamed aside for the others; removes the backups left. Returns "" or what
// could not be undone, for the message.
std::string OutputFiles::rollBack(std::vector<Pending>& todo, size_t replaced) {
    std::string failed;
    for (size_t j = 0; j < todo.size(); ++j) {
        const Pending& p = todo[j];
        if (p.backup.empty()) {
            if (j < replaced) ::unlink(p.path.c_str());
            continue;
        }
        struct stat st {};
        const bool aside = j >= replaced && ::lstat(p.path.c_str(), &st) != 0;  // renamed, not linked
        if (j < replaced || aside) {
            if (::rename(p.backup.c_str(), p.path.c_str()) != 0) failed += (failed.empty() ? "" : ", ") + p.path;
        } else {
            ::unlink(p.backup.c_str());
        }
    }
    return failed;
}

void OutputFiles::commit() {
    std::vector<Pending> todo;
    todo.swap(pending_);  // from here the destructor has nothing left to remove
    keepBackups(todo);
    for (size_t i = 0; i < todo.size(); ++i) {
        if (::rename(todo[i].tmp.c_str(), todo[i].path.c_str()) == 0) continue;
        const int e = errno;
        for (size_t j = i; j < todo.size(); ++j) ::unlink(todo[j].tmp.c_str());
        const std::string failed = rollBack(todo, i);
        failFile(todo[i].path, "cannot replace file: " + errnoText(e) +
                                   (failed.empty() ? "" : " (and could not put back the earlier file " + failed + ")"));
    }
    for (const Pending& p : todo)
        if (!p.backup.empty()) ::unlink(p.backup.c_str());
}

}  // namespace rays

#include "rays/io/file_text.h"

#include <fstream>
#include <iterator>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#define RAYS_HAVE_POSIX_FILES 1
#endif

namespace rays {

#ifdef RAYS_HAVE_POSIX_FILES
FileText::FileText(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;  // CannotOpen
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
        int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
        flags |= MAP_POPULATE;  // page tables filled in one call instead of a fault per page
#endif
        void* p = ::mmap(nullptr, size_t(st.st_size), PROT_READ, flags, fd, 0);
        if (p != MAP_FAILED) {
            mapped_ = static_cast<const char*>(p);
            mappedSize_ = size_t(st.st_size);
            ::close(fd);
            status_ = Status::Ok;
            return;
        }
    }
    // Not mappable (empty, a pipe, a device): read from the descriptor already open, so that a
    // named pipe is not opened twice.
    status_ = Status::Ok;
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0) {
            read_.append(buf, size_t(n));
        } else if (n == 0) {
            break;
        } else if (errno != EINTR) {
            status_ = Status::CannotRead;
            break;
        }
    }
    ::close(fd);
}

FileText::~FileText() {
    if (mapped_) ::munmap(const_cast<char*>(mapped_), mappedSize_);
}
#else
FileText::FileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // CannotOpen
    read_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    status_ = in.bad() ? Status::CannotRead : Status::Ok;
}

FileText::~FileText() = default;
#endif

}  // namespace rays

#include "rays/io/file_text.h"

#include <cstring>
#include <algorithm>
#include <fstream>
#include <iterator>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#define RAYS_HAVE_POSIX_FILES 1
#endif

namespace rays {

#ifdef RAYS_HAVE_POSIX_FILES
FileText::FileText(const std::string& path, TextForm form, size_t maxBytes) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;  // CannotOpen
    struct stat st {};
    // A regular file's length sizes the buffer; anything else (a pipe, a device) gets the ceiling's
    // worth of address space, of which only the pages read are ever touched: no copies as it grows,
    // so an endless source costs maxBytes of memory at most.
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    size_t capacity = regular && st.st_size > 0 ? size_t(st.st_size) : 0;
    if (capacity > maxBytes) {
        ::close(fd);
        status_ = Status::TooLarge;
        return;
    }
    capacity = capacity > 0 ? capacity + 1 : regular ? size_t(1) << 16 : maxBytes + 1;  // +1: the end is seen in one read
    data_.reset(new char[capacity]);
    status_ = Status::Ok;
    for (;;) {
        if (size_ > maxBytes) {  // grown past the ceiling (a pipe, /dev/zero, a file still growing)
            data_.reset();
            size_ = 0;
            status_ = Status::TooLarge;
            break;
        }
        if (size_ == capacity) {
            const size_t grown = std::min(2 * capacity, maxBytes + 1);  // never far past the ceiling
            std::unique_ptr<char[]> bigger(new char[grown]);
            std::memcpy(bigger.get(), data_.get(), size_);
            data_ = std::move(bigger);
            capacity = grown;
        }
        const ssize_t n = ::read(fd, data_.get() + size_, capacity - size_);
        if (n > 0) {
            size_ += size_t(n);
        } else if (n == 0) {
            break;
        } else if (errno != EINTR) {
            status_ = Status::CannotRead;
            break;
        }
    }
    ::close(fd);
    if (status_ == Status::Ok && form == TextForm::Source) start_ = makeSourceText(data_.get(), size_);
}
#else
FileText::FileText(const std::string& path, TextForm form, size_t maxBytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // CannotOpen
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        status_ = Status::CannotRead;
        return;
    }
    if (all.size() > maxBytes) {
        status_ = Status::TooLarge;
        return;
    }
    data_.reset(new char[all.size() + 1]);
    all.copy(data_.get(), all.size());
    size_ = all.size();
    status_ = Status::Ok;
    if (form == TextForm::Source) start_ = makeSourceText(data_.get(), size_);
}
#endif

size_t makeSourceText(char* text, size_t size) {
    for (size_t i = 0; i < size; ++i)
        if (text[i] == '\r' && (i + 1 == size || text[i + 1] != '\n')) text[i] = '\n';
    return size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
}

std::string FileText::describe(size_t bytes) {
    if (bytes >= (size_t(1) << 30) && bytes % (size_t(1) << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
    if (bytes >= (size_t(1) << 20) && bytes % (size_t(1) << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
    return std::to_string(bytes) + " bytes";
}

}  // namespace rays

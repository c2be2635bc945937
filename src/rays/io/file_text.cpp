#include "rays/io/file_text.h"

#include <cstring>
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
FileText::FileText(const std::string& path, TextForm form) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;  // CannotOpen
    struct stat st {};
    // A regular file's length sizes the buffer; anything else grows it as it arrives.
    size_t capacity = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 ? size_t(st.st_size) : 0;
    capacity = capacity > 0 ? capacity + 1 : size_t(1) << 16;  // +1: the end of the file is seen in one read
    data_.reset(new char[capacity]);
    status_ = Status::Ok;
    for (;;) {
        if (size_ == capacity) {
            std::unique_ptr<char[]> bigger(new char[2 * capacity]);
            std::memcpy(bigger.get(), data_.get(), size_);
            data_ = std::move(bigger);
            capacity *= 2;
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
FileText::FileText(const std::string& path, TextForm form) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // CannotOpen
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        status_ = Status::CannotRead;
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

}  // namespace rays

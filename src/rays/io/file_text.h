// FileText: the whole contents of a file, opened once. A regular file is mapped read-only (POSIX
// mmap) instead of copied: a 2 MB scene read into a string costs some hundred page faults, slow on
// virtual machines, before parsing starts. Anything else (a pipe such as `<(make-scene)`, or a
// system without mmap) is read into memory.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace rays {

class FileText {
public:
    enum class Status { Ok, CannotOpen, CannotRead };

    explicit FileText(const std::string& path);
    ~FileText();
    FileText(const FileText&) = delete;
    FileText& operator=(const FileText&) = delete;

    Status status() const { return status_; }
    /// The contents (valid while this object lives) when status() is Ok.
    std::string_view text() const { return mapped_ ? std::string_view(mapped_, mappedSize_) : std::string_view(read_); }

private:
    Status status_ = Status::CannotOpen;
    const char* mapped_ = nullptr;
    size_t mappedSize_ = 0;
    std::string read_;
};

}  // namespace rays

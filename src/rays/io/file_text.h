// FileText: the whole contents of a file, opened once and read into memory. The buffer is sized
// from the file's length and left uninitialised before the read (a zero-filled std::string would
// touch every page twice); a file whose length is unknown (a pipe such as `<(make-scene)`) is read
// in chunks from the same descriptor. Copying instead of mapping the file keeps a file truncated
// by another program mid-read an ordinary short read, not a SIGBUS.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace rays {

class FileText {
public:
    enum class Status { Ok, CannotOpen, CannotRead };

    explicit FileText(const std::string& path);

    Status status() const { return status_; }
    /// The contents (valid while this object lives) when status() is Ok.
    std::string_view text() const { return {data_.get(), size_}; }

private:
    Status status_ = Status::CannotOpen;
    std::unique_ptr<char[]> data_;
    size_t size_ = 0;
};

}  // namespace rays

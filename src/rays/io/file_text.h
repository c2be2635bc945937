// FileText: the whole contents of a file, opened once and read into memory. The buffer is sized
// from the file's length and left uninitialised before the read (a zero-filled std::string would
// touch every page twice); a file whose length is unknown (a pipe such as `<(make-scene)`) is read
// into a buffer of the ceiling's size whose pages are touched only as they fill. Copying instead of mapping the file keeps a file truncated
// by another program mid-read an ordinary short read, not a SIGBUS.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace rays {

/// The largest text file Rays reads: scene files, include files, #read files and OBJ files (1 GiB).
/// The reader's tokens take up to 12 bytes per byte of text on top, so a bigger file would not
/// leave room for the render on most machines; /dev/zero stops here instead of filling memory.
inline constexpr size_t kMaxTextFileBytes = size_t(1) << 30;

class FileText {
public:
    enum class Status { Ok, CannotOpen, CannotRead, TooLarge };

    /// Reads at most maxBytes; a longer file (or an endless source) gives TooLarge.
    explicit FileText(const std::string& path, size_t maxBytes = kMaxTextFileBytes);

    Status status() const { return status_; }
    /// "1 GiB", "64 KiB": a ceiling for messages.
    static std::string describe(size_t bytes);
    /// The contents (valid while this object lives) when status() is Ok.
    std::string_view text() const { return {data_.get(), size_}; }

private:
    Status status_ = Status::CannotOpen;
    std::unique_ptr<char[]> data_;
    size_t size_ = 0;
};

}  // namespace rays

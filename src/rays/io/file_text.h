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

/// How the bytes are handed out: as they are, or as source text (scene files, include files, files
/// #read): a UTF-8 byte-order mark at the start is skipped (editors write one) and a lone carriage
/// return (old Mac OS line ends) becomes a line feed, so that every reader numbers lines as an editor
/// does; "\r\n" is left as it is, and no line changes length.
enum class TextForm { Bytes, Source };
/// The largest text file Rays reads: scene files, include files, #read files and OBJ files (1 GiB).
/// The reader's tokens take up to 12 bytes per byte of text on top, so a bigger file would not
/// leave room for the render on most machines; /dev/zero stops here instead of filling memory.
inline constexpr size_t kMaxTextFileBytes = size_t(1) << 30;

class FileText {
public:
    enum class Status { Ok, CannotOpen, CannotRead, TooLarge };

    /// Reads at most maxBytes; a longer file (or an endless source) gives TooLarge. form: the
    /// bytes as they are, or as source text (TextForm).
    explicit FileText(const std::string& path, TextForm form = TextForm::Bytes, size_t maxBytes = kMaxTextFileBytes);

    Status status() const { return status_; }
    /// "1 GiB", "64 KiB": a ceiling for messages.
    static std::string describe(size_t bytes);
    /// The contents (valid while this object lives) when status() is Ok.
    std::string_view text() const { return {data_.get() + start_, size_ - start_}; }

private:
    Status status_ = Status::CannotOpen;
    std::unique_ptr<char[]> data_;
    size_t size_ = 0;
    size_t start_ = 0;  ///< bytes skipped at the start (a byte-order mark)
};

/// The source form of text (TextForm::Source) in place; returns how many bytes to skip at the start.
size_t makeSourceText(char* text, size_t size);

}  // namespace rays

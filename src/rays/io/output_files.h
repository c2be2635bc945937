// OutputFiles: the files one run writes, committed together. Each file is first written in full to
// a temporary beside its destination (PATH.tmp.PID.N); commit() renames them over their
// destinations only once every one of them was written, so a run that fails or is interrupted
// before commit() changes none of its outputs and leaves no temporary. commit() itself is all or
// nothing as far as POSIX allows: each file about to be replaced is first kept as a hidden backup
// (a hard link .NAME.bak.PID.N beside it), and when a rename fails the files already replaced get
// their backups back and the new ones are removed. A file replaced keeps its permission bits (a
// mode 600 image stays 600); a new one gets 666 less the umask.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

class OutputFiles {
public:
    OutputFiles() = default;
    /// Removes the temporaries of files not committed.
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    /// Writes data to a temporary beside path. Throws rays::Error "PATH: error: ..." (cannot create,
    /// write failed); the temporary is then removed and the files staged before stay staged.
    void stage(const std::string& path, const std::vector<uint8_t>& data);

    /// Renames every staged file over its destination, in the order staged. Throws rays::Error
    /// "PATH: error: cannot replace file: ..." when a rename fails (or "cannot keep a backup of the
    /// file: ..." before any rename): every destination is then as it was before commit() (unless
    /// putting a backup back fails too, which the message then says) and no temporary or backup is
    /// left.
    void commit();

private:
    struct Pending {
        std::string path;
        std::string tmp;
        std::string backup;  ///< set by commit() when path existed (a hard link to it, or path renamed)
    };
    void keepBackups(std::vector<Pending>& todo);
    static std::string rollBack(std::vector<Pending>& todo, size_t replaced);
    std::vector<Pending> pending_;
};

}  // namespace rays

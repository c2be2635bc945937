// OutputFiles: the files one run writes, committed together. Each file is first written in full to
// a temporary beside its destination (PATH.tmp.PID.N); commit() renames them over their
// destinations only once every one of them was written, so a run that fails or is interrupted
// before commit() changes none of its outputs and leaves no temporary. A file replaced keeps its
// permission bits (a mode 600 image stays 600); a new one gets 666 less the umask.
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
    /// "PATH: error: cannot replace file: ..." when a rename fails (the rest are removed; the files
    /// renamed before it stay replaced: a rename within one folder fails only in rare cases).
    void commit();

private:
    struct Pending {
        std::string path;
        std::string tmp;
    };
    std::vector<Pending> pending_;
};

}  // namespace rays

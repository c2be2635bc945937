// File-name rules the commands share: whether a file exists, whether two names are one file (an
// output must never overwrite an input or another output of the same run), and where a name's
// extension starts.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rays::cli {

/// True when something exists at path (errors count as "no").
bool fileExists(const std::string& path);

/// True when a and b name one file: by identity when both exist ("./b.png", an absolute path, a
/// link or a hard link to it), else by their absolute names with links and ".." resolved.
bool sameFile(const std::string& a, const std::string& b);

/// Throws Error "OUTPUT: error: output would overwrite the input file 'INPUT'" when they are one
/// file (sameFile); an empty input is no file.
void checkOutputIsNotInput(const std::string& output, const std::string& input);

/// One file a run writes and what it is ("output image", "edge mask").
struct NamedOutput {
    std::string path;
    const char* what;
};

/// Throws Error "B: error: the WHAT-B would overwrite the WHAT-A 'A' of the same run" when two of
/// the outputs are one file (sameFile); empty paths are skipped.
void checkOutputsDiffer(const std::vector<NamedOutput>& outputs);

/// The index of the '.' that starts path's extension, or npos when the last component has none
/// ("dir/out.x.png" → the second dot; "dir.d/out" and the hidden file ".png" have none).
size_t extensionDot(const std::string& path);

}  // namespace rays::cli

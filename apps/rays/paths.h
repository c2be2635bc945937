// File-name rules the commands share: whether a file exists, whether two names are one existing
// file (an output must never overwrite an input), and where a name's extension starts.
#pragma once
#include <cstddef>
#include <string>

namespace rays::cli {

/// True when something exists at path (errors count as "no").
bool fileExists(const std::string& path);

/// Throws Error "OUTPUT: error: output would overwrite the input file 'INPUT'" when both exist and
/// are the same file (by identity: "./b.png", an absolute path or a link to it); an empty input is
/// no file.
void checkOutputIsNotInput(const std::string& output, const std::string& input);

/// The index of the '.' that starts path's extension, or npos when the last component has none
/// ("dir/out.x.png" → the second dot; "dir.d/out" and the hidden file ".png" have none).
size_t extensionDot(const std::string& path);

}  // namespace rays::cli

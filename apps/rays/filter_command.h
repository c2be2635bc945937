// `rays filter INPUT OUTPUT KERNEL [KERNEL ...]`: read an image, apply image-processing kernels in
// order (blurs, edge detection, Sobel, sharpen, emboss, median, brighten, custom matrices; see
// docs/filters.md) and write the result atomically.
#pragma once
#include <string>
#include <vector>

namespace rays::cli {

/// Runs `rays filter` with `args`, the words after "filter" on the command line (options
/// --border clamp|zero|white|reflect, --quality Q, --threads T, -q/--quiet may appear anywhere).
/// Prints help on stdout and returns 0 for -h/--help; returns 0 after writing OUTPUT. Bad input of
/// any kind (options, kernel specs or files, unreadable or unsupported images, an output that cannot
/// be written) throws rays::Error with a one-line message, OUTPUT left as it was.
int runFilterCommand(const std::vector<std::string>& args);

}  // namespace rays::cli

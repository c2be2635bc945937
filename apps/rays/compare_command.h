// `rays compare A B [--diff DIFF] [--scale K] [--threshold N] [--fail-ssim S]`: compare two images
// of the same size (SSIM, PSNR, mean and max difference, pixels over a threshold; see
// docs/cli.md for the output layout) and optionally write the difference image atomically.
#pragma once
#include <string>
#include <vector>

namespace rays::cli {

/// Runs `rays compare` with `args`, the words after "compare". Prints the figures on stdout and
/// returns 0, or 1 when --fail-ssim S is given and the SSIM is below S; prints help and returns 0
/// for -h/--help. Bad options, unreadable images, different sizes, or a diff path that names an
/// input or cannot be written throw rays::Error with a one-line message (the caller exits 2).
int runCompareCommand(const std::vector<std::string>& args);

}  // namespace rays::cli

#include "filter_command.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "rays/error.h"
#include "rays/image/filter.h"
#include "rays/io/image_io.h"
#include "paths.h"
#include "rays/util/memory_limit.h"
#include "subcommand_args.h"

namespace rays::cli {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Fails before any work when the output could not be written where asked (writeImage would fail
// later anyway, atomically; this only saves reading and filtering).
void checkOutputPath(const std::string& output) {
    if (!isSupportedImageExtension(output))
        failFile(output, "unsupported output image format (use .png, .jpg, .jpeg, .bmp, .tga or .ppm)");
    std::error_code ec;
    if (std::filesystem::is_directory(output, ec)) failFile(output, "cannot write the image: is a directory");
    const std::filesystem::path parent = std::filesystem::absolute(output, ec).parent_path();
    if (!std::filesystem::is_directory(parent, ec))
        failFile(output, "cannot write the image: directory '" + parent.string() + "' does not exist");
    if (access(parent.c_str(), W_OK) != 0)
        failFile(output, "cannot write the image: directory '" + parent.string() + "' is not writable");
}

}  // namespace

int runFilterCommand(const std::vector<std::string>& args) {
    CLI::App app{"Apply image-processing kernels, in order, to the colour channels of an image (alpha is kept).",
                 "rays filter"};
    std::string input, output, borderName = "clamp";
    std::vector<std::string> kernelArgs;
    int quality = 90, threads = 0;
    bool quiet = false;
    app.add_option("input", input, "input image: .png .jpg .jpeg .bmp .tga .ppm")->required();
    app.add_option("output", output, "output image, format by extension: .png .jpg .jpeg .bmp .tga .ppm")->required();
    app.add_option("kernels", kernelArgs, "kernels applied in order: " + validKernelNames())->required();
    app.add_option("--border", borderName, "outside the image: clamp (default), zero, white (as the original) or reflect");
    app.add_option("--quality", quality, "JPEG quality 1-100 (default 90)")->check(CLI::Range(1, 100));
    app.add_option("--threads", threads, "worker threads (default 0: all cores)")->check(CLI::Range(0, 1024));
    app.add_flag("-q,--quiet", quiet, "no summary line on stderr");
    app.footer("Kernels: box_blur_N, gaussian_blur_N[:SIGMA] (sigma N/6 by default), median_N (N odd), edge_detect_1,\n"
               "edge_detect_2, sobel, sharpen, emboss, brighten_X, kernel:FILE (see docs/filters.md).");
    if (parseSubcommandArgs(app, args, "filter",
                            "rays filter INPUT OUTPUT KERNEL [KERNEL ...] [--border MODE] [--quality Q] [--threads T] [-q]"))
        return 0;

    const BorderMode border = parseBorderMode(borderName);
    const std::vector<KernelSpec> kernels = parseKernelList(kernelArgs);
    checkOutputPath(output);
    checkOutputIsNotInput(output, input);
    for (const KernelSpec& k : kernels) checkOutputIsNotInput(output, k.file);

    auto t0 = Clock::now();
    Image8 out = readImage(input);
    const double readMs = msSince(t0);
    // The filters keep planar float copies besides the 8-bit image: about 10 bytes per channel and
    // pixel (measured: 7.1 GB for a 16384x16384 RGB image).
    const double need = double(out.width) * double(out.height) * double(out.channels) * 10.0;
    if (need > double(memoryLimit()))
        throw Error("rays: error: filtering a " + std::to_string(out.width) + "x" + std::to_string(out.height) +
                    " image needs about " + formatBytes(need) + ", more than the memory limit of " +
                    formatBytes(double(memoryLimit())) + memoryLimitSource());

    t0 = Clock::now();
    applyFiltersInPlace(out, kernels, border, threads);
    const double filterMs = msSince(t0);

    t0 = Clock::now();
    writeImage(output, out, quality);
    const double writeMs = msSince(t0);

    if (!quiet)
        std::fprintf(stderr, "rays: wrote %s (%dx%d, %d channel%s): read %.1f ms, filter %.1f ms (%zu kernel%s, %s border), write %.1f ms\n",
                     printableMessage(output).c_str(), out.width, out.height, out.channels, out.channels == 1 ? "" : "s", readMs,
                     filterMs, kernels.size(), kernels.size() == 1 ? "" : "s", borderModeName(border), writeMs);
    return 0;
}

}  // namespace rays::cli

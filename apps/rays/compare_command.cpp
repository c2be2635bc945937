#include "compare_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "rays/error.h"
#include "rays/image/compare.h"
#include "rays/io/image_io.h"
#include "flag_values.h"
#include "paths.h"
#include "stdout_check.h"
#include "subcommand_args.h"

namespace rays::cli {
namespace {

// Refuses a diff path that would overwrite an input or that has no image format.
void checkDiffPath(const std::string& diff, const std::string& a, const std::string& b) {
    for (const std::string& input : {a, b}) checkOutputIsNotInput(diff, input);
    if (!isSupportedImageExtension(diff))
        failFile(diff, "unsupported diff image format (use .png, .jpg, .jpeg, .bmp, .tga or .ppm)");
}

std::string sizeText(const Image8& img) { return std::to_string(img.width) + "x" + std::to_string(img.height); }

// The figures, one "key value..." line each (layout documented in docs/cli.md).
void printFigures(const ImageComparison& r) {
    std::printf("ssim %.6f\n", r.ssim.mean());
    std::printf("ssim_rgb %.6f %.6f %.6f\n", r.ssim.channel[0], r.ssim.channel[1], r.ssim.channel[2]);
    std::printf("ssim_luma %.6f\n", r.ssim.luma);
    if (std::isinf(r.psnr)) std::printf("psnr inf\n");
    else std::printf("psnr %.2f\n", r.psnr);
    std::printf("mean %.3f\n", r.meanAbs);
    std::printf("max %d\n", r.maxAbs);
    std::printf("over %zu %.2f%% threshold %g\n", r.pixelsOver, r.percentOver(), r.threshold);
    std::printf("size %dx%d\n", r.width, r.height);
}

}  // namespace

int runCompareCommand(const std::vector<std::string>& args) {
    CLI::App app{"Compare two images of the same size: SSIM, PSNR, mean and max difference, pixels over a threshold.",
                 "rays compare"};
    std::string a, b, diff;
    double scale = 1, threshold = 5, failSsim = -2;
    app.add_option("a", a, "first image: .png .jpg .jpeg .bmp .tga .ppm")->required();
    app.add_option("b", b, "second image, same width and height")->required();
    app.add_option("--diff", diff, "write |A-B|*scale per channel as an RGB image (must not be an input)");
    app.add_option("--scale", scale, "factor applied to the differences in the diff image (default 1)")
        ->check(finiteNumberCheck())->check(CLI::Range(0.0, 1e6));
    app.add_option("--threshold", threshold, "count pixels whose largest channel difference exceeds N, 0..255 (default 5)")
        ->check(finiteNumberCheck())->check(CLI::Range(0.0, 255.0));
    CLI::Option* failOpt = app.add_option("--fail-ssim", failSsim, "exit with status 1 when the SSIM is below S")
                               ->check(finiteNumberCheck())->check(CLI::Range(-1.0, 1.0));
    app.footer("Output (stdout), one figure a line: ssim, ssim_rgb, ssim_luma, psnr, mean, max, over, size\n"
               "(see docs/cli.md). Exit status 0, 1 when --fail-ssim S is given and ssim < S, 2 on errors.");
    if (parseSubcommandArgs(app, args, "compare",
                            "rays compare A B [--diff DIFF] [--scale K] [--threshold N] [--fail-ssim S]"))
        return 0;
    if (!diff.empty()) checkDiffPath(diff, a, b);

    const Image8 imgA = readImage(a);
    const Image8 imgB = readImage(b);
    if (imgA.width != imgB.width || imgA.height != imgB.height)
        throw Error("rays: error: compare: images differ in size: " + a + " is " + sizeText(imgA) + ", " + b + " is " +
                    sizeText(imgB));
    const ImageComparison r = compareImages(imgA, imgB, threshold);
    if (!diff.empty()) writeImage(diff, differenceImage(imgA, imgB, scale));
    printFigures(r);
    flushStdout();  // the figures come before the verdict on stderr, and must have arrived
    if (failOpt->count() > 0 && r.ssim.mean() < failSsim) {
        std::fprintf(stderr, "rays: compare: SSIM %.6f is below %g\n", r.ssim.mean(), failSsim);
        return 1;
    }
    return 0;
}

}  // namespace rays::cli

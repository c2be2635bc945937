#include "pov_settings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "rays/error.h"
#include "rays/io/image_io.h"

namespace rays::cli {
namespace {

namespace fs = std::filesystem;

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The scene's name: the input file without folders and extension (reference 3.2.4.2).
std::string sceneName(const std::string& input) {
    const std::string stem = fs::path(input).stem().string();
    return stem.empty() ? "output" : stem;
}

// A row or column bound as a 0-based pixel index: a fraction f of n pixels is ⌊f·n⌋ for a start
// and ⌊f·n⌋ − 1 for an end; a number k from 1 on is pixel k − 1 (measured with POV-Ray 3.7 at
// 32×24: +SR0.3 +ER0.7 renders rows 7 to 15, +SC0.1 +EC0.9 columns 3 to 27, +SR5 +ER10 rows 4 to 9).
int startIndex(const PovBound& b, int n) { return b.value < 1 ? int(std::floor(b.value * n)) : int(b.value) - 1; }
// An end bound of exactly 1 is 100 % (POV-Ray 3.7 renders rows 1 to h with End_Row=1, as
// advanced/benchmark/benchmark.ini asks); a start bound of 1 is the first pixel.
int endIndex(const PovBound& b, int n) { return b.value <= 1 ? int(std::floor(b.value * n)) - 1 : int(b.value) - 1; }

}  // namespace

AaChoice mapPovAntialias(const PovAntialias& aa) {
    AaChoice c;
    if (!aa.on || aa.threshold >= 3.0) return c;  // "If the threshold is 3.0 then no anti-aliasing is done"
    const int n = std::max(2, aa.method == 2 ? aa.depth + 1 : aa.depth);
    c.spp = n * n;
    c.mode = aa.jitter ? AaMode::Stratified : AaMode::Grid;
    c.edges = aa.threshold > 0;  // threshold 0: "every pixel is super-sampled"
    c.threshold = aa.threshold;
    c.gamma = aa.gamma;
    return c;
}

std::string fileTypeExtension(char type) {
    switch (type) {
        case 'P': return ".ppm";
        case 'T':
        case 'C':
        case 'S': return ".tga";  // 'S', system-specific, is Targa on Unix (reference 3.2.4.1)
        case 'J': return ".jpg";
        case 'B': return ".bmp";
        default: return ".png";
    }
}

std::string povOutputPath(const PovOptions& o, bool povForm) {
    const std::string ext = fileTypeExtension(o.fileType);
    if (o.outputFile.empty()) return (povForm ? sceneName(o.inputFile) : std::string("output")) + ext;
    if (o.outputExact) return o.outputFile;
    std::error_code ec;
    if (o.outputFile.back() == '/' || fs::is_directory(o.outputFile, ec)) {
        const std::string folder = o.outputFile.back() == '/' ? o.outputFile : o.outputFile + "/";
        return folder + sceneName(o.inputFile) + ext;
    }
    if (o.fileType) {
        const bool hasIt = endsWith(o.outputFile, ext) || (o.fileType == 'J' && endsWith(o.outputFile, ".jpeg"));
        return hasIt ? o.outputFile : o.outputFile + ext;
    }
    return isSupportedImageExtension(o.outputFile) ? o.outputFile : o.outputFile + ext;
}

void setImageRegion(const PovOptions& o, RenderSettings& s) {
    if (!o.startRow.given && !o.endRow.given && !o.startColumn.given && !o.endColumn.given) return;
    const int r0 = std::max(0, o.startRow.given ? startIndex(o.startRow, s.height) : 0);
    const int r1 = std::min(s.height - 1, o.endRow.given ? endIndex(o.endRow, s.height) : s.height - 1);
    const int c0 = std::max(0, o.startColumn.given ? startIndex(o.startColumn, s.width) : 0);
    const int c1 = std::min(s.width - 1, o.endColumn.given ? endIndex(o.endColumn, s.width) : s.width - 1);
    if (r1 < r0 || c1 < c0)
        throw Error("rays: error: the part of the image asked for (Start_Row, End_Row, Start_Column, End_Column; "
                    "+SR +ER +SC +EC) is empty: rows " + std::to_string(r0 + 1) + "-" + std::to_string(r1 + 1) +
                    " and columns " + std::to_string(c0 + 1) + "-" + std::to_string(c1 + 1) + " of " +
                    std::to_string(s.width) + "x" + std::to_string(s.height));
    if (r0 == 0 && c0 == 0 && r1 == s.height - 1 && c1 == s.width - 1) return;  // the whole image
    s.regionX0 = c0, s.regionX1 = c1, s.regionY0 = r0, s.regionY1 = r1;
}

void applyPovOptions(const PovOptions& o, bool povForm, RenderJob& job) {
    RenderSettings& s = job.settings;
    if (!o.inputFile.empty()) job.scenePath = o.inputFile;
    s.width = o.width == -1 ? 640 : o.width;
    s.height = o.height == -1 ? 480 : o.height;
    if (o.antialias.given) {
        const AaChoice aa = mapPovAntialias(o.antialias);
        s.aa = aa.mode;
        s.spp = aa.spp;
        s.aaEdges = aa.edges;
        s.aaThreshold = aa.edges ? aa.threshold : -1;
    }
    s.aaGamma = o.antialias.gamma;
    s.fileGamma = o.fileGamma;
    if (o.threads >= 0) s.threads = o.threads;
    if (o.jpegQuality > 0) job.jpegQuality = o.jpegQuality;
    job.outputPath = povOutputPath(o, povForm);
    job.outputToFile = o.outputToFile;
    job.bitsPerColor = o.bitsPerColor;
    job.language.libraryPaths = o.libraryPaths;
    job.language.declares = o.declares;
    job.language.includeHeader = o.includeHeader;
    job.language.version = o.version;
    setImageRegion(o, s);
}

}  // namespace rays::cli

// Fuzzing regressions: every input saved in tests/regressions/ (a crash, hang or sanitizer report
// found by the fuzzers in fuzz/, see docs/fuzzing.md) is run through the same entry point as the
// fuzzer (fuzz/entry_points.h) and must now end normally; the reader it exercises must refuse it
// with the one-line message listed here. File names start with the fuzz target: scene-, obj-,
// kernel-, image-, pov-, ini-, font-. The sanitizer builds (scripts/sanitize.sh) run these too, which is where a
// regression of a memory or UB fix would show.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../fuzz/entry_points.h"
#include "../fuzz/entry_points_ini.h"  // the INI reader's code is linked in by pov_options_test.cpp
#include "rays/error.h"
#include "rays/image/kernels.h"
#include "rays/io/image_io.h"
#include "rays/io/obj_loader.h"
#include "rays/io/scene_parser.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;

using rays::test::readFile;

namespace { namespace RAYS_TEST_UNIT {

const fs::path kDir = fs::path(RAYS_SOURCE_DIR) / "tests" / "regressions";

struct Regression {
    std::string file;     ///< name in tests/regressions/
    std::string message;  ///< part of the Error the reader now throws for it
};

void PrintTo(const Regression& r, std::ostream* os) { *os << r.file; }

// Mirrors the "Findings" table of docs/fuzzing.md (same order).
std::vector<Regression> regressions() {
    return {
        {"image-jpeg-dht-overflow.jpg", "cannot read image: corrupt JPEG (Huffman table with more than 256 codes)"},
        {"image-tga-truncated-huge.tga", "cannot read image: file of 459 bytes is too small for a 8308x26223 image"},
        {"image-ppm-zero-height.ppm", "cannot read image: image has no pixels (5x0)"},
        {"image-ppm-width-overflow.ppm", "cannot read image: corrupt PPM/PGM header (number too large)"},
        {"image-png-empty-idat.png", "cannot read image: "},
        {"scene-deep-parentheses.pov", "fuzz.pov:1:279: error: expression nested too deeply (more than 256 levels)"},
        {"scene-adaptive-huge.pov", "fuzz.pov:3:78: error: adaptive level must be a whole number from 0 to 1000"},
        {"scene-mesh2-index-huge.pov", "fuzz.pov:12:21: error: mesh2 indices must be whole numbers from 0 to 4294967295"},
        {"obj-skin-weight-joint-huge.obj", "6:1: error: invalid joint id '1e390' in 'vw' line (a number from 0 to 16777216)"},
        {"image-png-chunk-length-huge.png", "cannot read image: corrupt PNG (a chunk runs past the end of the file)"},
        {"image-jpeg-corrupt-scan.jpg", "cannot read image: corrupt JPEG (Corrupt JPEG data: premature end of data segment)"},
        {"pov-bitwise-huge.pov", "fuzz.pov:2:1: error: #error: bitwise 0 -2147483648 -2147483648"},
        {"pov-internal-number-huge.pov", "fuzz.pov:1:34: error: the internal function number is out of range"},
        {"pov-array-index-huge.pov", "fuzz.pov:2:11: error: array index 1e+300 is out of range 0..1"},
        {"pov-builder-counts-huge.pov", ""},  // accepted: the counts are clamped (FuzzPovFindings)
        {"pov-mesh2-index-huge.pov", "fuzz.pov:1:1: error: mesh2 face index 4294967295 is out of range (3 vertices)"},
        {"pov-function-sum-huge.pov", "fuzz.pov:2:14: error: loops ran more than 20000 iterations (sum, prod or calls of other functions in a function called while parsing)"},
        // Nesting errors name the count limit, or the stack when it runs short first (sanitizer builds).
        {"pov-deep-macro-arguments.pov", ": error: nesting "},
        {"pov-deep-directives.pov", ": error: nesting "},
        {"pov-deep-vectors.pov", ": error: nesting "},
        {"pov-deep-colour-keywords.pov", ": error: nesting "},
        {"pov-deep-string-functions.pov", ": error: nesting "},
        {"pov-deep-pattern-blocks.pov", ": error: nesting "},
        {"pov-parentheses-3990.pov", ""},  // within the count limit: parses, or the stack guard stops it
        {"pov-array-copies-many.pov", "fuzz.pov:3:26: error: more than 1048576 array elements and spline points made (new and copied) in this parse (runaway loop?)"},
        {"pov-array-copies-nested.pov", "fuzz.pov:3:71: error: more than 1048576 array elements and spline points made (new and copied) in this parse (runaway loop?)"},
        {"pov-strings-many-long.pov", "fuzz.pov:4:34: error: more than 134217728 bytes of strings made by string functions in this parse (runaway loop?)"},
        {"pov-concat-long-arguments.pov", "fuzz.pov:3:14: error: concat made a string longer than 16 MiB"},
        {"pov-write-many.pov", "fuzz.pov:4:18: error: more than 67108864 bytes written by #write in this parse (runaway loop?)"},
        {"pov-object-copies-doubling.pov", "fuzz.pov:2:38: error: more than 65536 items used again through identifiers (each use counts the item's whole tree) in this parse (runaway loop?)"},
        {"pov-mesh-copies-doubling.pov", "fuzz.pov:2:38: error: more than 65536 items used again through identifiers (each use counts the item's whole tree) in this parse (runaway loop?)"},
        {"pov-item-chain-deep.pov", "fuzz.pov:2:41: error: more than 65536 items used again through identifiers (each use counts the item's whole tree) in this parse (runaway loop?)"},  // with the default limits the depth limit stops it (FuzzPovFindings)
        {"pov-default-loop.pov", ""},  // accepted, in linear time (FuzzPovFindings.DefaultsAreAppendedAndSharedNotCopied)
        {"pov-function-calls-doubling.pov", "fuzz.pov:3:14: error: loops ran more than 20000 iterations (sum, prod or calls of other functions in a function called while parsing)"},
        {"pov-spline-copies-quadratic.pov", "fuzz.pov:2:33: error: more than 1048576 array elements and spline points made (new and copied) in this parse (runaway loop?)"},
        {"pov-transform-copies-doubling.pov", "fuzz.pov:2:52: error: more than 65536 items used again through identifiers (each use counts the item's whole tree) in this parse (runaway loop?)"},
        {"pov-fopen-name-too-long.pov", "fuzz.pov:1:1: error: cannot open \"aaaa"},  // a name the system refuses, across two lines: one line, no filesystem exception
        {"pov-finish-copies-doubling.pov", "fuzz.pov:2:30: error: more than 65536 items used again through identifiers (each use counts the item's whole tree) in this parse (runaway loop?)"},
    };
}

std::string prefixOf(const std::string& file) { return file.substr(0, file.find('-')); }

/// The message of the Error the target's reader throws for the bytes ("" when it accepts them).
std::string errorOf(const std::string& target, const std::string& bytes, const fs::path& scratch) {
    try {
        if (target == "pov") {
            rays::fuzz::parseFuzzPov(bytes);
        } else if (target == "scene") {
            rays::ParseOptions opt;
            opt.warn = [](const std::string&) {};
            rays::parseScene(bytes, "fuzz.pov", opt);
        } else {
            const fs::path p = scratch / ("input." + target);
            std::ofstream(p, std::ios::binary) << bytes;
            if (target == "image") rays::readImage(p.string());
            else if (target == "obj") rays::loadObj(p.string());
            else if (target == "kernel") rays::parseKernelText(bytes, p.string());
            else if (target == "font") {
                rays::TtfFont font(p.string());
            }
            else if (target == "ini") {
                rays::cli::PovOptions options;
                rays::cli::PovOptionReader(options, [](const std::string&) {}).readIniFile(p.string(), "");
            }
        }
    } catch (const rays::Error& e) {
        return e.what();
    }
    return "";
}

class Regressions : public ::testing::TestWithParam<Regression> {};

TEST_P(Regressions, SameEntryPointAsTheFuzzerEndsNormally) {
    const Regression& r = GetParam();
    const std::string bytes = readFile(kDir / r.file);
    ASSERT_FALSE(bytes.empty()) << "missing " << (kDir / r.file);
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const std::string target = prefixOf(r.file);
    if (target == "scene") rays::fuzz::fuzzScene(data, bytes.size());
    else if (target == "obj") rays::fuzz::fuzzObj(data, bytes.size());
    else if (target == "kernel") rays::fuzz::fuzzKernel(data, bytes.size());
    else if (target == "image") rays::fuzz::fuzzImage(data, bytes.size());
    else if (target == "pov") rays::fuzz::fuzzPov(data, bytes.size());
    else if (target == "ini") rays::fuzz::fuzzIni(data, bytes.size());
    else if (target == "font") rays::fuzz::fuzzFont(data, bytes.size());
    else FAIL() << "unknown target prefix in " << r.file;
}

TEST_P(Regressions, ReaderRefusesItWithItsMessage) {
    const Regression& r = GetParam();
    rays::test::TempDir dir;
    const std::string msg = errorOf(prefixOf(r.file), readFile(kDir / r.file), dir.path());
    EXPECT_NE(msg.find(r.message), std::string::npos) << "message: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
}

INSTANTIATE_TEST_SUITE_P(Fuzz, Regressions, ::testing::ValuesIn(regressions()),
                         [](const ::testing::TestParamInfo<Regression>& info) {
                             std::string n = info.param.file;
                             std::replace_if(n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                             return n;
                         });

TEST(RegressionsFolder, EveryInputIsListed) {
    std::vector<std::string> listed;
    for (const Regression& r : regressions()) listed.push_back(r.file);
    for (const auto& e : fs::directory_iterator(kDir))
        EXPECT_NE(std::find(listed.begin(), listed.end(), e.path().filename().string()), listed.end())
            << e.path().filename() << " is not in the table of tests/regressions_test.cpp";
}

// The fix for image-png-empty-idat.png drops zero-length IDAT chunks before stb_image sees them;
// they are legal, so a valid PNG with one must still read back exactly.
TEST(RegressionsPng, EmptyIdatChunkInAValidPngIsHarmless) {
    rays::test::TempDir dir;
    rays::Image8 img(7, 5, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 13);
    std::vector<uint8_t> png = rays::encodeImage("png", img);
    // Insert "length 0, IDAT, CRC" before the first IDAT chunk.
    const std::string s(png.begin(), png.end());
    const size_t idat = s.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    const uint8_t empty[12] = {0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xAF, 0x06, 0x1E};
    png.insert(png.begin() + long(idat - 4), empty, empty + 12);
    const fs::path p = dir.path() / "empty-idat.png";
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), long(png.size()));
    const rays::Image8 back = rays::readImage(p.string());
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.pixels, img.pixels);
}

// Size-scaling mode (fuzz/run.sh --scaled): "@@" regions repeated 2^(first byte mod 18) times.
TEST(FuzzScaling, RegionsAreRepeatedByTheFirstBytesPowerOfTwo) {
    const std::string in = std::string("\x03") + "f@@ 1@@\n";
    const std::string out = rays::fuzz::scaledInput(reinterpret_cast<const uint8_t*>(in.data()), in.size());
    EXPECT_EQ(out, "f 1 1 1 1 1 1 1 1\n");
    const std::string plain = std::string("\x05") + "no markers @@ here";
    EXPECT_EQ(rays::fuzz::scaledInput(reinterpret_cast<const uint8_t*>(plain.data()), plain.size()), "no markers @@ here");
}

// Every size-scaling seed, expanded (up to 65536 repetitions: a face of 65536 corners, a prism of
// 65537 points, 4096 nested unions), runs through its target and ends normally.
TEST(FuzzScaling, EverySeedRunsThroughItsTarget) {
    const fs::path dir = fs::path(RAYS_SOURCE_DIR) / "fuzz" / "seeds-scaled";
    size_t seeds = 0;
    for (const auto& target : fs::directory_iterator(dir))
        for (const auto& seed : fs::directory_iterator(target.path())) {
            const std::string bytes = readFile(seed.path());
            const std::string big = rays::fuzz::scaledInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
            const auto* data = reinterpret_cast<const uint8_t*>(big.data());
            const std::string t = target.path().filename().string();
            if (t == "obj") rays::fuzz::fuzzObj(data, big.size());
            else if (t == "kernel") rays::fuzz::fuzzKernel(data, big.size());
            else if (t == "scene") rays::fuzz::fuzzScene(data, big.size());
            else if (t == "pov") rays::fuzz::fuzzPov(data, big.size());
            else if (t == "ini") rays::fuzz::fuzzIni(data, big.size());
            else ADD_FAILURE() << "no target " << t;
            ++seeds;
        }
    EXPECT_GE(seeds, 10u);
}

}}  // namespace RAYS_TEST_UNIT, namespace

// The second bad-input catalogue of docs/errors.md ("Outputs, messages, silent acceptance,
// streams"): runs exactly like tests/errors_test.cpp (the real binary in a fresh TempDir holding
// the row's files; exit status and stderr checked exactly, inputs unchanged, a failure adds no file
// and no temporary, a success adds exactly the files it names), for the rows numbered H1, H2, ...
// HardeningDoc checks that docs/errors.md lists the same rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::ProcessResult;
using rays::test::readFile;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

struct File {
    std::string name;
    std::string bytes;
};

struct Row {
    std::string id;                    ///< the row's name in docs/errors.md
    std::vector<File> files;           ///< created in the temporary folder first
    std::vector<std::string> args;     ///< rays arguments
    int exit = 2;                      ///< expected exit status
    std::string message;               ///< stderr, exactly ("" = nothing; "\n" between lines)
    std::vector<std::string> written;  ///< files a successful run adds (or replaces)

    Row(std::string i, std::vector<File> f, std::vector<std::string> a, int e, std::string m,
        std::vector<std::string> w = {})
        : id(std::move(i)), files(std::move(f)), args(std::move(a)), exit(e), message(std::move(m)), written(std::move(w)) {}
};

void PrintTo(const Row& r, std::ostream* os) { *os << r.id; }

const std::string kCamera = "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n";
const std::string kLight = "light_source { <10,10,10> color rgb <1,1,1> }\n";
const std::string kSphere = "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";
const std::string kScene = kCamera + kLight + kSphere;
const std::string kPov = "#version 3.7;\ncamera { location -5*z look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n";

std::string pngBytes(int w, int h) {
    rays::Image8 img(w, h, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 7);
    const std::vector<uint8_t> png = rays::encodeImage("png", img);
    return std::string(png.begin(), png.end());
}

// A PNG whose IDAT chunk's CRC is off by one bit (the data itself intact).
std::string pngWithBadCrc() {
    std::string png = pngBytes(16, 12);
    const size_t idat = png.find("IDAT");
    const uint32_t length = uint32_t(uint8_t(png[idat - 4])) << 24 | uint32_t(uint8_t(png[idat - 3])) << 16 |
                            uint32_t(uint8_t(png[idat - 2])) << 8 | uint8_t(png[idat - 1]);
    png[idat + 4 + length + 3] ^= 1;
    return png;
}

std::vector<std::string> render(std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"render", "scene.pov", "16", "12", "-o", "out.png", "-q"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

// finish { ITEM 1e31 } in a course scene: the message names the item, its range and the value.
Row finishOutOfRange(const std::string& item) {
    const std::string line = "sphere { <0,0,0>, 2 finish { " + item + " 1e31 } }\n";
    const std::string col = std::to_string(line.find("1e31") + 1);
    return {"finish-" + item + "-1e31", {{"scene.pov", kCamera + line}}, render(), 2,
            "scene.pov:2:" + col + ": error: " + item + " must be between -1e+30 and 1e+30, got 1e+31"};
}

// Mirrors the "Outputs, messages, silent acceptance, streams" table of docs/errors.md, row for row.
std::vector<Row> catalogue() {
    const std::string png = pngBytes(16, 12);
    const std::string oldMask = "old mask bytes";
    std::vector<Row> t;
    // ---- 5: several outputs ----
    t.push_back({"failed-render-keeps-old-mask", {{"scene.pov", kScene}, {"mask.png", oldMask}},
                 {"render", "scene.pov", "16", "12", "-q", "--edges", "all", "--edge-mask", "mask.png", "-o", "/proc/out.png"}, 2,
                 "/proc/out.png: error: cannot create file: No such file or directory"});
    t.push_back({"filter-onto-its-input", {{"f.png", png}}, {"filter", "f.png", "f.png", "box_blur_3", "-q"}, 2,
                 "f.png: error: output would overwrite the input file 'f.png'"});
    t.push_back({"filter-onto-its-input-other-name", {{"f.png", png}}, {"filter", "f.png", "./f.png", "box_blur_3", "-q"}, 2,
                 "./f.png: error: output would overwrite the input file 'f.png'"});
    t.push_back({"filter-onto-its-kernel-file", {{"f.png", png}, {"k.png", "0 0 0\n0 1 0\n0 0 0\n"}},
                 {"filter", "f.png", "k.png", "kernel:k.png", "-q"}, 2,
                 "k.png: error: output would overwrite the input file 'k.png'"});
    t.push_back({"edge-mask-is-the-output", {{"scene.pov", kScene}}, render({"--edges", "all", "--edge-mask", "out.png"}), 2,
                 "out.png: error: the edge mask would overwrite the output image 'out.png' of the same run"});
    t.push_back({"edge-mask-is-the-output-other-name", {{"scene.pov", kScene}, {"out.png", png}},
                 render({"--edges", "all", "--edge-mask", "./out.png"}), 2,
                 "./out.png: error: the edge mask would overwrite the output image 'out.png' of the same run"});
    t.push_back({"edge-mask-is-the-partial-image", {{"scene.pov", kScene}},
                 render({"--edges", "all", "--save-partial", "--edge-mask", "out.partial.png"}), 2,
                 "out.partial.png: error: the partial image would overwrite the edge mask 'out.partial.png' of the same run"});
    t.push_back({"post-kernel-file-is-the-output", {{"scene.pov", kScene}, {"k.png", "0 0 0\n0 1 0\n0 0 0\n"}},
                 {"render", "scene.pov", "16", "12", "-o", "k.png", "-q", "--post", "kernel:k.png"}, 2,
                 "k.png: error: output would overwrite the input file 'k.png'"});
    t.push_back({"animation-masks-numbered", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "16", "12", "+KFF2", "-o", "out.png", "-q", "--edges", "all", "--edge-mask", "mask.png"}, 0, "",
                 {"out1.png", "out2.png", "mask1.png", "mask2.png"}});
    t.push_back({"sdl-fopen-onto-the-scene", {{"scene.pov", kPov + "#fopen F \"scene.pov\" write\n"}}, render(), 2,
                 "scene.pov:4:1: error: #fopen would overwrite \"scene.pov\", a scene file this parse reads"});
    t.push_back({"sdl-fopen-onto-the-output", {{"scene.pov", kPov + "#fopen F \"out.png\" write\n"}}, render(), 2,
                 "scene.pov:4:1: error: #fopen would overwrite \"out.png\", an output of this run"});
    // ---- 6: messages ----
    for (const char* item : {"ambient", "diffuse", "specular", "roughness", "ior", "refraction"})
        t.push_back(finishOutOfRange(item));
    t.push_back({"control-bytes-in-a-file-name", {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"\x1b[2J.png\" } } }\n"}},
                 render(), 2, "scene.pov:2:47: error: cannot open image file '\\x1b[2J.png'"});
    t.push_back({"control-bytes-in-an-sdl-string", {{"scene.pov", kPov + "#error concat(\"a\", chr(27), \"[2J\", chr(7))\n"}},
                 render(), 2, "scene.pov:4:1: error: #error: a\\x1b[2J\\x07"});
    t.push_back({"control-bytes-in-an-sdl-warning", {{"scene.pov", kPov + "#warning concat(\"a\", chr(27), \"[2J\")\nsphere { 0, 1 }\n"}},
                 render(), 0, "scene.pov:4:1: warning: a\\x1b[2J", {"out.png"}});
    t.push_back({"control-bytes-in-an-obj-token", {{"scene.pov", kScene}, {"model.obj", "v 0 0 \x1b[2J\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}},
                 render({"--obj", "model.obj"}), 2, "model.obj:1:1: error: invalid number '\\x1b[2J' in 'v' line"});
    t.push_back({"invalid-utf8-in-a-message", {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"caf\xC3\xA9\xff.png\" } } }\n"}},
                 render(), 2, "scene.pov:2:47: error: cannot open image file 'caf\xC3\xA9\\xff.png'"});
    // ---- 7: silent acceptance ----
    t.push_back({"obj-mesh-not-an-obj", {{"scene.pov", kScene + "obj_mesh { \"scene.pov\" }\n"}}, render(), 2,
                 "scene.pov:4:12: error: OBJ file 'scene.pov' has no faces (is it an OBJ file?)"});
    t.push_back({"scale-overflows", {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 scale 1e300 scale 1e300 }\n"}}, render(), 2,
                 "scene.pov:2:21: error: the transformation overflows or becomes singular here"});
    t.push_back({"scale-underflows", {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 scale 1e-200 scale 1e-200 }\n"}}, render(), 2,
                 "scene.pov:2:21: error: the transformation overflows or becomes singular here"});
    t.push_back({"sdl-scale-overflows", {{"scene.pov", kPov + "sphere { 0, 1 scale 1e300 scale 1e300 }\n"}}, render(), 2,
                 "scene.pov:4:1: error: the object's transformation overflows or is singular"});
    t.push_back({"sdl-camera-scale-overflows", {{"scene.pov", "#version 3.7;\ncamera { location -5*z look_at 0 scale 1e300 scale 1e300 }\nsphere { 0, 1 }\n"}},
                 render(), 2, "scene.pov:2:46: error: the camera's transformation overflows (its vectors are no longer finite)"});
    t.push_back({"sdl-light-scale-overflows", {{"scene.pov", "#version 3.7;\ncamera { location -5*z look_at 0 }\nlight_source { <5, 5, -5> rgb 1 scale 1e300 scale 1e300 }\nsphere { 0, 1 }\n"}},
                 render(), 2, "scene.pov:3:1: error: the light's transformation overflows (its position is no longer finite)"});
    t.push_back({"edge-color-out-of-range", {{"scene.pov", kScene}}, render({"--edges", "all", "--edge-color", "5,-1,nan"}), 2,
                 "rays: error: --edge-color takes R,G,B (three numbers from 0 to 1), got '5,-1,nan'"});
    t.push_back({"crease-angle-negative", {{"scene.pov", kScene}}, render({"--edges", "all", "--crease-angle", "-500"}), 2,
                 "rays: error: crease angle must be between 0 and 180 degrees, got -500.000000"});
    t.push_back({"crease-angle-nan", {{"scene.pov", kScene}}, render({"--edges", "all", "--crease-angle", "nan"}), 2,
                 "rays: error: --crease-angle: expected a finite number, got 'nan'"});
    t.push_back({"edge-width-nan", {{"scene.pov", kScene}}, render({"--edges", "all", "--edge-width", "nan"}), 2,
                 "rays: error: --edge-width: expected a finite number, got 'nan'"});
    t.push_back({"seed-past-2^64", {{"scene.pov", kScene}}, render({"--seed", "18446744073709551616"}), 2,
                 "rays: error: --seed: must be a whole number from 0 to 18446744073709551615 (2^64 - 1), got "
                 "'18446744073709551616' (see rays --help)"});
    t.push_back({"compare-scale-nan", {{"a.png", png}}, {"compare", "a.png", "a.png", "--scale", "nan"}, 2,
                 "rays: error: compare: --scale: expected a finite number, got 'nan' (usage: rays compare A B [--diff DIFF] [--scale K] [--threshold N] [--fail-ssim S])"});
    t.push_back({"png-bad-crc", {{"f.png", pngWithBadCrc()}}, {"filter", "f.png", "out.png", "box_blur_3", "-q"}, 2,
                 "f.png: error: cannot read image: corrupt PNG (the CRC of a chunk 'IDAT' does not match its data)"});
    // ---- 8: streams and encodings ----
    t.push_back({"course-scene-with-bom", {{"scene.pov", "\xEF\xBB\xBF" + kScene}}, render(), 0, "", {"out.png"}});
    t.push_back({"sdl-scene-with-bom", {{"scene.pov", "\xEF\xBB\xBF" + kPov + "sphere { 0, 1 }\n"}}, render(), 0, "", {"out.png"}});
    t.push_back({"course-scene-cr-only", {{"scene.pov", "camera { location <0,0,14> look_at <0,0,0> }\r\rsphere { <0,0,0>, 0 }\r"}},
                 render(), 2, "scene.pov:3:19: error: sphere radius must be greater than 0"});
    t.push_back({"sdl-scene-cr-only", {{"scene.pov", "#version 3.7;\r#declare A = 1;\r\r#declare B = C;\r"}}, render(), 2,
                 "scene.pov:4:14: error: undeclared identifier 'C'"});
    t.push_back({"obj-with-bom", {{"scene.pov", kScene}, {"model.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}},
                 render({"--obj", "model.obj"}), 0, "", {"out.png"}});
    t.push_back({"ini-with-bom-cr-only", {{"scene.pov", kScene}, {"a.ini", "\xEF\xBB\xBFInput_File_Name=scene.pov\rWidth=16\rHeight=12\r"}},
                 {"render", "a.ini", "+Oout.png", "-q"}, 0, "", {"out.png"}});
    return t;
}

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class HardeningRows : public ::testing::TestWithParam<Row> {};

TEST_P(HardeningRows, ExitStatusMessageAndFilesAsDocumented) {
    const Row& row = GetParam();
    TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    std::map<std::string, std::string> before;
    for (const File& f : row.files) {
        std::ofstream(dir.path() / f.name, std::ios::binary) << f.bytes;
        before[f.name] = f.bytes;
    }
    const std::vector<std::string> inputs = entries(dir.path());
    const ProcessResult r = runProcess(RAYS_BINARY, row.args, dir.path().string(), std::chrono::seconds(60));
    std::string cmd = "rays";
    for (const std::string& a : row.args) cmd += " " + a;
    ASSERT_TRUE(r.startError.empty() && !r.timedOut && r.termSignal == 0) << cmd << ": " << r.summary() << "\n" << r.err;
    EXPECT_EQ(r.exitCode, row.exit) << cmd << "\nstderr: " << r.err;
    EXPECT_EQ(r.err, row.message.empty() ? "" : row.message + "\n") << cmd;

    for (const auto& [name, bytes] : before) {
        if (std::find(row.written.begin(), row.written.end(), name) == row.written.end()) {
            EXPECT_EQ(readFile(dir.path() / name), bytes) << name << " changed";
        }
    }
    std::vector<std::string> want = inputs;
    for (const std::string& w : row.written)
        if (std::find(want.begin(), want.end(), w) == want.end()) want.push_back(w);
    std::sort(want.begin(), want.end());
    EXPECT_EQ(entries(dir.path()), want) << cmd;
}

INSTANTIATE_TEST_SUITE_P(Hardening, HardeningRows, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Row>& info) {
                             std::string n = info.param.id;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

// docs/errors.md has a row "| HN | `id` | ... | exit | `message` | ... |" for every entry above.
TEST(HardeningDoc, ListsEveryRowWithItsExitStatusAndMessage) {
    const std::string doc = readFile(fs::path(RAYS_SOURCE_DIR) / "docs" / "errors.md");
    ASSERT_FALSE(doc.empty());
    std::map<std::string, std::string> lines;
    std::istringstream in(doc);
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (std::regex_search(line, m, std::regex("^\\| H[0-9]+ \\| `([^`]+)` \\|"))) lines[m[1]] = line;
    }
    const std::vector<Row> rows = catalogue();
    for (const Row& row : rows) {
        const auto it = lines.find(row.id);
        ASSERT_NE(it, lines.end()) << "docs/errors.md has no row `" << row.id << "`";
        EXPECT_NE(it->second.find("| " + std::to_string(row.exit) + " |"), std::string::npos) << it->second;
        if (!row.message.empty()) {
            EXPECT_NE(it->second.find("`" + row.message + "`"), std::string::npos) << "message of " << row.id << " in: " << it->second;
        }
    }
    EXPECT_EQ(lines.size(), rows.size()) << "docs/errors.md H rows vs tests/errors_hardening_test.cpp catalogue";
}

}}  // namespace RAYS_TEST_UNIT, namespace

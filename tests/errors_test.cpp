// The bad-input catalogue (docs/errors.md), row by row: each row runs the real `rays` binary
// (RAYS_BINARY) with runProcess in a fresh TempDir holding the row's files, and checks the exit
// status, that stderr is exactly the documented line ({DIR} stands for the temporary folder), that
// a failed run leaves no output and no temporary file, that a successful one writes its image, and
// that no input file changed. ErrorsDoc checks that docs/errors.md lists every row with its exit
// status and message, so the two stay in step.
#include <gtest/gtest.h>

#include <stdlib.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
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

// A file of the row: its bytes, or a function making them when the row runs (large contents, so
// that registering the tests, which every test process does, stays quick).
struct File {
    std::string name;
    std::string bytes;
    bool directory = false;
    std::function<std::string()> make;
    File(std::string n, std::string b, bool d = false) : name(std::move(n)), bytes(std::move(b)), directory(d) {}
    File(std::string n, std::function<std::string()> m) : name(std::move(n)), make(std::move(m)) {}
    std::string contents() const { return make ? make() : bytes; }
};

struct BadInput {
    std::string id;                 ///< the row's name in docs/errors.md
    std::vector<File> files;        ///< created in the temporary folder first
    std::vector<std::string> args;  ///< rays arguments
    int exit = 2;                   ///< expected exit status
    std::string message;            ///< stderr, exactly (one line; "" = nothing); {DIR} = the folder
    std::string output = "out.png"; ///< written on success, absent after a failure ("" = none)
    std::string env;                ///< "NAME=VALUE" set for the run, or ""

    BadInput(std::string i, std::vector<File> f, std::vector<std::string> a, int e, std::string m,
             std::string o = "out.png", std::string v = "")
        : id(std::move(i)), files(std::move(f)), args(std::move(a)), exit(e), message(std::move(m)),
          output(std::move(o)), env(std::move(v)) {}
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.id; }

const std::string kCamera = "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n";
const std::string kLight = "light_source { <10,10,10> color rgb <1,1,1> }\n";
const std::string kSphere = "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";
const std::string kScene = kCamera + kLight + kSphere;

std::string pngBytes(int w, int h) {
    rays::Image8 img(w, h, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 7);
    const std::vector<uint8_t> png = rays::encodeImage("png", img);
    return std::string(png.begin(), png.end());
}

// The header of a w×h RGB PNG followed by `dataBytes` of zeros as its image data: the declared size
// is all a reader sees before it decides to allocate.
std::string pngDeclaring(int w, int h, size_t dataBytes) {
    auto be32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    auto chunk = [&](const std::string& type, const std::string& data) {
        const std::string body = type + data;
        const uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size())));
        return be32(uint32_t(data.size())) + body + be32(crc);
    };
    const std::string ihdr = be32(uint32_t(w)) + be32(uint32_t(h)) + std::string("\x08\x02\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", std::string(dataBytes, '\0')) +
           chunk("IEND", "");
}

// Four 2048×2048 textures (12 MiB of texels each) on four spheres.
std::vector<File> fourTextures() {
    std::vector<File> files;
    std::string body;
    for (int i = 0; i < 4; ++i) {
        const std::string name = "tex" + std::to_string(i) + ".png";
        files.push_back({name, std::function<std::string()>([] {
                             const std::vector<uint8_t> png = rays::encodeImage("png", rays::Image8(2048, 2048, 3));
                             return std::string(png.begin(), png.end());
                         })});
        body += "sphere { <" + std::to_string(i) + ",0,0>, 1 pigment { image_map { png \"" + name + "\" } } }\n";
    }
    files.push_back({"scene.pov", kCamera + body});
    return files;
}

// An OBJ file of one star-shaped polygon of n corners (every second one concave), radius 3.
std::string starPolygonObj(int n) {
    std::string obj;
    char line[96];
    for (int i = 0; i < n; ++i) {
        const double angle = 2 * 3.14159265358979323846 * i / n, r = i % 2 ? 1.5 : 3.0;
        std::snprintf(line, sizeof line, "v %.9f %.9f 0\n", r * std::cos(angle), r * std::sin(angle));
        obj += line;
    }
    obj += "f";
    for (int i = 1; i <= n; ++i) obj += " " + std::to_string(i);
    return obj + "\n";
}

// Two facing mirrors seen between them.
const std::string kMirrors = kCamera + kLight +
                             "plane { <0,0,1>, -1 pigment { color rgb 1 } finish { reflection 1 } }\n"
                             "plane { <0,0,-1>, -20 pigment { color rgb 1 } finish { reflection 1 } }\n";

// A scene with `body` after the camera (and, with a light, after the light too).
std::vector<File> scene(const std::string& body, bool light = false) {
    return {{"scene.pov", kCamera + (light ? kLight : "") + body}};
}

std::vector<std::string> render(std::vector<std::string> extra = {}, const std::string& sceneFile = "scene.pov") {
    std::vector<std::string> a = {"render", sceneFile, "16", "12", "-o", "out.png", "-q"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

// Mirrors docs/errors.md, row for row (same ids, same order).
std::vector<BadInput> catalogue() {
    const std::string png = pngBytes(16, 9);
    const std::string garbage = std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) + std::string("\xff\x00\x13\x37 binary", 11);
    const std::string objTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::vector<BadInput> t;
    // ---- scene files: structure ----
    t.push_back({"empty-scene", {{"scene.pov", ""}}, render(), 2, "scene.pov: error: scene has no camera"});
    t.push_back({"comments-only", {{"scene.pov", "// nothing\n/* here */\n"}}, render(), 2,
                 "scene.pov: error: scene has no camera"});
    t.push_back({"camera-only", {{"scene.pov", kCamera}}, render(), 0, ""});
    t.push_back({"no-light", scene(kSphere), render(), 0, ""});
    t.push_back({"truncated-block", scene("sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> }"), render(), 2,
                 "scene.pov:2:8: error: '{' of 'sphere' is never closed (end of file reached)"});
    t.push_back({"truncated-vector", scene("sphere { <0,0,"), render(), 2,
                 "scene.pov:2:15: error: expected a number or vector, found end of file"});
    t.push_back({"unterminated-comment", scene("/* sphere { <0,0,0>, 2 }"), render(), 2,
                 "scene.pov:2:1: error: unterminated /* comment"});
    t.push_back({"unterminated-string", scene("#include \"colors.inc\n"), render(), 2,
                 "scene.pov:2:10: error: unterminated string"});
    t.push_back({"binary-garbage", {{"scene.pov", garbage}}, render(), 2,
                 "scene.pov:1:1: error: unexpected character '\\x89'"});
    t.push_back({"nul-byte", scene(std::string("sphere { <0,0,0>, 2 \0 }\n", 24)), render(), 2,
                 "scene.pov:2:21: error: unexpected character '\\x00'"});
    t.push_back({"stray-brace", scene("sphere { <0,0,0>, 2 }\n}\n"), render(), 2,
                 "scene.pov:3:1: error: unbalanced '}': no block is open"});
    t.push_back({"unknown-keyword", scene("spere { <0,0,0>, 2 }\n"), render(), 2,
                 "scene.pov:2:1: error: unknown keyword 'spere'"});
    t.push_back({"directory-as-scene", {{"scene.pov", "", true}}, render(), 2,
                 "scene.pov: error: is a directory, not a scene file"});
    t.push_back({"missing-scene", {}, render({}, "nosuch.pov"), 2, "nosuch.pov: error: cannot open scene file"});
    // ---- scene files: numbers ----
    t.push_back({"number-too-large", scene("sphere { <0,0,0>, 1e999 }\n"), render(), 2,
                 "scene.pov:2:19: error: number '1e999' is too large"});
    t.push_back({"number-underflow", scene("sphere { <0,0,0>, 1e-999 }\n"), render(), 2,
                 "scene.pov:2:19: error: sphere radius must be greater than 0"});
    t.push_back({"infinite-expression", scene("sphere { <0,0,0>, 1e308*10 }\n"), render(), 2,
                 "scene.pov:2:19: error: sphere radius is not a finite number"});
    t.push_back({"infinite-vector", scene("sphere { <1e308*10,0,0>, 1 }\n"), render(), 2,
                 "scene.pov:2:10: error: sphere centre has a non-finite component"});
    t.push_back({"nan-word", scene("sphere { <0,0,0>, nan }\n"), render(), 2,
                 "scene.pov:2:19: error: expected sphere radius, found 'nan'"});
    t.push_back({"division-by-zero", scene("sphere { <0,0,0>, 1/0 }\n"), render(), 2,
                 "scene.pov:2:20: error: division by zero"});
    t.push_back({"malformed-number", scene("sphere { <0,0,0>, 1.2.3 }\n"), render(), 2,
                 "scene.pov:2:19: error: malformed number '1.2.3'"});
    t.push_back({"deep-nesting", scene("sphere { <0,0,0>, " + std::string(300, '(') + "1 }\n"), render(), 2,
                 "scene.pov:2:275: error: expression nested too deeply (more than 256 levels)"});
    // ---- scene files: geometry and counts ----
    t.push_back({"zero-scale", scene("sphere { <0,0,0>, 1 scale <1,0,1> }\n"), render(), 2,
                 "scene.pov:2:21: error: scale has a zero component"});
    t.push_back({"singular-matrix", scene("box { <0,0,0>, <1,1,1> matrix <1,0,0, 0,0,0, 0,0,1, 0,0,0> }\n"), render(), 2,
                 "scene.pov:2:31: error: matrix is singular"});
    t.push_back({"degenerate-triangle", scene("triangle { <0,0,0>, <1,1,1>, <2,2,2> pigment { color rgb 1 } }\n", true),
                 render(), 0, "scene.pov:3:1: warning: degenerate triangle (zero area) can never be hit"});
    t.push_back({"zero-radius", scene("sphere { <0,0,0>, 0 }\n"), render(), 2,
                 "scene.pov:2:19: error: sphere radius must be greater than 0"});
    t.push_back({"zero-plane-normal", scene("plane { <0,0,0>, 1 }\n"), render(), 2,
                 "scene.pov:2:9: error: plane normal has zero length"});
    t.push_back({"camera-looks-at-itself", {{"scene.pov", "camera { location <0,0,0> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"}},
                 render(), 2, "scene.pov:1:1: error: camera 'look_at' equals its 'location'"});
    t.push_back({"area-light-0-samples", scene("light_source { <0,9,0> color rgb 1 area_light <1,0,0>, <0,0,1>, 0, 4 }\n"),
                 render(), 2, "scene.pov:2:65: error: area_light sample counts must be whole numbers from 1 to 1024"});
    t.push_back({"area-light-10^6-samples",
                 scene("light_source { <0,9,0> color rgb 1 area_light <1,0,0>, <0,0,1>, 1000000, 4 }\n"), render(), 2,
                 "scene.pov:2:65: error: area_light sample counts must be whole numbers from 1 to 1024"});
    t.push_back({"blur-samples-0",
                 {{"scene.pov", "camera { location <0,0,14> up <0,1,0> right <1,0,0> look_at <0,0,0> blur_samples 0 }\n"}},
                 render(), 2, "scene.pov:1:69: error: blur_samples must be a whole number from 1 to 65536"});
    t.push_back({"adaptive-10^47", scene("light_source { <0,9,0> color rgb 1 adaptive 1e47 }\n"), render(), 2,
                 "scene.pov:2:36: error: adaptive level must be a whole number from 0 to 1000"});
    t.push_back({"mesh2-index-out-of-range",
                 scene("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,7> } }\n"),
                 render(), 2, "scene.pov:2:1: error: mesh vertex index 7 is out of range (3 available)"});
    // ---- scene files: referenced files ----
    t.push_back({"missing-include", {{"scene.pov", "#include \"nosuch.inc\"\n" + kScene}}, render(), 2,
                 "scene.pov:1:1: error: cannot find include file \"nosuch.inc\" (searched the scene's folder, the library "
                 "paths and /usr/share/povray-3.7/include)"});
    t.push_back({"missing-texture", scene("sphere { <0,0,0>, 2 pigment { image_map { png \"nosuch.png\" } } }\n"),
                 render(), 2, "scene.pov:2:47: error: cannot open image file 'nosuch.png'"});
    t.push_back({"texture-not-an-image",
                 {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"tex.png\" } } }\n"},
                  {"tex.png", "not an image"}},
                 render(), 2,
                 "scene.pov:2:47: error: tex.png: cannot read image: not a PNG, JPEG, BMP, TGA or binary PPM/PGM "
                 "file, or corrupt"});
    t.push_back({"texture-truncated",
                 {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"tex.png\" } } }\n"},
                  {"tex.png", png.substr(0, 60)}},
                 render(), 2, "scene.pov:2:47: error: tex.png: cannot read image: corrupt PNG (a chunk runs past the end of the file)"});
    t.push_back({"texture-is-a-directory",
                 {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"tex.png\" } } }\n"},
                  {"tex.png", "", true}},
                 render(), 2, "scene.pov:2:47: error: cannot open image file 'tex.png'"});
    t.push_back({"missing-obj-mesh", scene("obj_mesh { \"nosuch.obj\" }\n"), render(), 2,
                 "scene.pov:2:12: error: cannot open OBJ file 'nosuch.obj'"});
    // ---- sizes, counts and limits ----
    t.push_back({"width-0", {{"scene.pov", kScene}}, {"render", "scene.pov", "0", "12", "-o", "out.png", "-q"}, 2,
                 "rays: error: image size must be positive, got 0x12"});
    t.push_back({"negative-width", {{"scene.pov", kScene}}, {"render", "scene.pov", "-W", "-5", "-H", "12", "-o", "out.png"}, 2,
                 "rays: error: image size must be positive, got -5x12"});
    t.push_back({"width-not-a-number", {{"scene.pov", kScene}}, {"render", "scene.pov", "abc", "12", "-o", "out.png"}, 2,
                 "rays: error: Could not convert: width = abc (see rays --help)"});
    t.push_back({"size-10^6x10^6", {{"scene.pov", kScene}}, {"render", "scene.pov", "1000000", "1000000", "-o", "out.png"}, 2,
                 "rays: error: image size 1000000x1000000 is too large (at most 65536 per side and 268435456 pixels)"});
    t.push_back({"size-65536x65536", {{"scene.pov", kScene}}, {"render", "scene.pov", "65536", "65536", "-o", "out.png"}, 2,
                 "rays: error: image size 65536x65536 is too large (at most 65536 per side and 268435456 pixels)"});
    t.push_back({"spp-0", {{"scene.pov", kScene}}, render({"--spp", "0"}), 2,
                 "rays: error: --spp: Value 0 not in range 1 to 65536 (see rays --help)"});
    t.push_back({"spp-10^9", {{"scene.pov", kScene}}, render({"--spp", "1000000000"}), 2,
                 "rays: error: --spp: Value 1000000000 not in range 1 to 65536 (see rays --help)"});
    t.push_back({"ss-0", {{"scene.pov", kScene}}, render({"-ss=0"}), 2,
                 "rays: error: --ss: Value 0 not in range 1 to 64 (see rays --help)"});
    t.push_back({"samples-over-2^40", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "65536", "4096", "--spp", "65536", "-o", "out.png"}, 2,
                 "rays: error: 65536x4096 at 65536 samples per pixel is 1.76e+13 samples, more than the limit of 2^40 "
                 "(1.1e12) per image"});
    t.push_back({"buffers-over-memory-limit", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "8192", "8192", "--edges", "all", "-o", "out.png"}, 2,
                 "rays: error: a 8192x8192 render with these options needs about 9.1 GiB of image buffers and 0.0 MiB "
                 "for the scene, more than the memory limit of 1.0 GiB (RAYS_MEMORY_LIMIT)",
                 "out.png", "RAYS_MEMORY_LIMIT=1G"});
    t.push_back({"depth-0", {{"scene.pov", kCamera + kLight +
                                               "sphere { <0,0,0>, 2 pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.6 reflection 0.5 } }\n"}},
                 render({"--depth", "0"}), 0, ""});
    t.push_back({"depth-10^6", {{"scene.pov", kScene}}, render({"--depth", "1000000"}), 2,
                 "rays: error: --depth: Value 1000000 not in range 0 to 1000 (see rays --help)"});
    t.push_back({"threads-10^5", {{"scene.pov", kScene}}, render({"--threads", "100000"}), 2,
                 "rays: error: --threads: Value 100000 not in range 0 to 1024 (see rays --help)"});
    t.push_back({"camera-index-missing", {{"scene.pov", kScene}}, render({"--camera", "5"}), 2,
                 "scene.pov: error: camera 5 does not exist (the scene has 1)"});
    t.push_back({"negative-aperture", {{"scene.pov", kScene}}, render({"--aperture", "-1"}), 2,
                 "rays: error: --aperture: must be at least 0, got -1 (see rays --help)"});
    t.push_back({"focal-distance-0", {{"scene.pov", kScene}}, render({"--focal-distance", "0"}), 2,
                 "rays: error: --focal-distance: must be greater than 0, got 0 (see rays --help)"});
    t.push_back({"area-samples-0", {{"scene.pov", kScene}}, render({"--area-samples", "0"}), 2,
                 "rays: error: --area-samples: Value 0 not in range 1 to 1024 (see rays --help)"});
    t.push_back({"gi-samples-0", {{"scene.pov", kScene}}, render({"-gi_samples=0"}), 2,
                 "rays: error: gi_samples must be a whole number from 1 to 65536, got '0'"});
    t.push_back({"edge-width-100", {{"scene.pov", kScene}}, render({"--edges", "all", "--edge-width", "100"}), 2,
                 "rays: error: edge width must be between 0.5 and 8 pixels, got 100.000000"});
    // ---- options ----
    t.push_back({"aa-edges-one-sample", {{"scene.pov", kScene}}, render({"--aa-edges"}), 2,
                 "rays: error: --aa-edges needs more than one sample per pixel (--spp N or -ss=N)"});
    t.push_back({"unknown-shading", {{"scene.pov", kScene}}, render({"--shading", "bogus"}), 2,
                 "rays: error: unknown shading model 'bogus' (use blinn-phong, cook-torrance, oren-nayar, lambert, flat or "
                 "normals)"});
    t.push_back({"unknown-edge-type", {{"scene.pov", kScene}}, render({"--edges", "bogus"}), 2,
                 "rays: error: unknown edge type 'bogus' (use silhouette, occlusion, intersection, crease, material, "
                 "shadow, reflection, all or none)"});
    t.push_back({"edge-mask-without-edges", {{"scene.pov", kScene}}, render({"--edge-mask", "mask.png"}), 2,
                 "rays: error: --edge-mask needs edge lines (--edges LIST or an edges { } block)"});
    t.push_back({"bad-post-kernel", {{"scene.pov", kScene}}, render({"--post", "box_blur_2"}), 2,
                 "rays: error: kernel 'box_blur_2': the size must be odd and positive, got 2"});
    t.push_back({"unknown-option", {{"scene.pov", kScene}}, render({"--frob"}), 2,
                 "rays: error: The following argument was not expected: --frob (see rays --help)"});
    t.push_back({"unknown-command", {{"scene.pov", kScene}}, {"frobnicate", "scene.pov"}, 2,
                 "rays: error: unknown command 'frobnicate' (commands: render, raycast, sceneinfo, pixelray, firsthit, "
                 "pixelcolor, printrays, scenes, assets, filter, compare; or the positional form WIDTH HEIGHT INPUT OUTPUT SHADING "
                 "RAYS_PER_PIXEL DEPTH [OBJ])"});
    t.push_back({"positional-shading-9", {{"scene.pov", kScene}}, {"16", "12", "scene.pov", "out.png", "9", "1", "6"}, 2,
                 "rays: error: SHADING_MODEL must be 0 (Blinn-Phong), 1 (Cook-Torrance), 2 (Oren-Nayar), 3 (Lambert), "
                 "4 (flat) or 5 (normals); got 9"});
    t.push_back({"positional-spp-0", {{"scene.pov", kScene}}, {"16", "12", "scene.pov", "out.png", "0", "0", "6"}, 2,
                 "rays: error: RAYS_PER_PIXEL must be at least 1"});
    // ---- OBJ files ----
    t.push_back({"obj-bad-index", {{"scene.pov", kScene}, {"model.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n"}},
                 render({"--obj", "model.obj"}), 2, "model.obj:4:1: error: vertex index 5 is out of range (3 vertices in the file)"});
    t.push_back({"obj-index-0", {{"scene.pov", kScene}, {"model.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"}},
                 render({"--obj", "model.obj"}), 2,
                 "model.obj:4:1: error: invalid face vertex '0' (indices start at 1, not 0)"});
    t.push_back({"obj-bad-number", {{"scene.pov", kScene}, {"model.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"}},
                 render({"--obj", "model.obj"}), 2, "model.obj:2:1: error: invalid number 'nan' in 'v' line"});
    t.push_back({"obj-empty", {{"scene.pov", kScene}, {"model.obj", ""}}, render({"--obj", "model.obj"}), 2,
                 "model.obj: error: OBJ file has no faces (is it an OBJ file?)"});
    t.push_back({"obj-binary-garbage", {{"scene.pov", kScene}, {"model.obj", garbage}}, render({"--obj", "model.obj"}), 2,
                 "model.obj: error: OBJ file has no faces (is it an OBJ file?)"});
    t.push_back({"obj-missing", {{"scene.pov", kScene}}, render({"--obj", "nosuch.obj"}), 2,
                 "nosuch.obj: error: cannot open OBJ file"});
    t.push_back({"obj-ok", {{"scene.pov", kScene}, {"model.obj", objTriangle}}, render({"--obj", "model.obj"}), 0, ""});
    // ---- outputs ----
    t.push_back({"output-dir-missing", {{"scene.pov", kScene}}, {"render", "scene.pov", "16", "12", "-o", "nodir/out.png"}, 2,
                 "nodir/out.png: error: cannot write the image: directory '{DIR}/nodir' does not exist", "nodir/out.png"});
    t.push_back({"output-is-a-directory", {{"scene.pov", kScene}, {"out.png", "", true}}, render(), 2,
                 "out.png: error: is a directory", ""});
    t.push_back({"output-parent-is-a-file", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "16", "12", "-o", "scene.pov/out.png"}, 2,
                 "scene.pov/out.png: error: cannot write the image: directory '{DIR}/scene.pov' does not exist", ""});
    t.push_back({"output-unknown-extension", {{"scene.pov", kScene}}, {"render", "scene.pov", "16", "12", "-o", "out.gif"}, 2,
                 "out.gif: error: unsupported output image format (use .png, .jpg, .jpeg, .ppm, .tga, .bmp, .exr or .pfm)", "out.gif"});
    t.push_back({"output-no-extension", {{"scene.pov", kScene}}, {"render", "scene.pov", "16", "12", "-o", "out"}, 2,
                 "out: error: unsupported output image format (use .png, .jpg, .jpeg, .ppm, .tga, .bmp, .exr or .pfm)", "out"});
    t.push_back({"output-dir-not-writable", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "16", "12", "-o", "/proc/self/out.png"}, 2,
                 "/proc/self/out.png: error: cannot write the image: directory '/proc/self' is not writable", ""});
    t.push_back({"output-cannot-be-created", {{"scene.pov", kScene}},
                 {"render", "scene.pov", "16", "12", "-q", "-o", "/proc/out.png"}, 2,
                 "/proc/out.png: error: cannot create file: No such file or directory", ""});
    t.push_back({"output-onto-the-scene", {{"scene.png", kScene}}, {"render", "scene.png", "16", "12", "-o", "scene.png"}, 2,
                 "scene.png: error: output would overwrite the input file 'scene.png'", ""});
    t.push_back({"output-onto-a-texture",
                 {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"tex.png\" } } }\n"},
                  {"tex.png", png}},
                 {"render", "scene.pov", "16", "12", "-o", "tex.png"}, 2,
                 "tex.png: error: output would overwrite the input file 'tex.png'", ""});
    t.push_back({"edge-mask-onto-the-scene", {{"scene.png", kScene}},
                 {"render", "scene.png", "16", "12", "--edges", "all", "--edge-mask", "scene.png", "-o", "out.png"}, 2,
                 "scene.png: error: output would overwrite the input file 'scene.png'"});
    // POV-Ray's form (docs/cli.md "POV-Ray switches and INI files").
    t.push_back({"pov-ini-bad-width", {{"scene.pov", kScene}, {"bad.ini", "Input_File_Name=scene.pov\nWidth=abc\n"}},
                 {"bad.ini", "+Oout.png"}, 2, "rays: error: bad.ini:2: Width must be a positive integer, got 'abc'"});
    t.push_back({"pov-ini-missing", {{"scene.pov", kScene}}, {"+Iscene.pov", "nosuch.ini", "+Oout.png"}, 2,
                 "rays: error: cannot open INI file 'nosuch.ini' (named on the command line)"});
    t.push_back({"pov-switch-bad-value", {{"scene.pov", kScene}}, {"+Iscene.pov", "+W16", "+H12", "+R10", "+Oout.png"}, 2,
                 "rays: error: +R10: Antialias_Depth must be a whole number from 1 to 9, got '10'"});
    t.push_back({"pov-unknown-switch", {{"scene.pov", kScene}}, {"+Iscene.pov", "+W16", "+H12", "+Zap", "+Oout.png", "-q"},
                 0, "rays: warning: +Zap: unknown option '+Zap'"});
    t.push_back({"pov-empty-part-of-image", {{"scene.pov", kScene}},
                 {"+Iscene.pov", "+W16", "+H12", "+SR0.9", "+ER0.5", "+Oout.png"}, 2,
                 "rays: error: the part of the image asked for (Start_Row, End_Row, Start_Column, End_Column; +SR +ER +SC +EC) "
                 "is empty: rows 11-6 and columns 1-16 of 16x12"});
    t.push_back({"pov-subset-no-frame", {{"scene.pov", kScene}},
                 {"+Iscene.pov", "+W16", "+H12", "+KFF3", "+SF5", "+Oout.png"}, 2,
                 "rays: error: Subset_Start_Frame selects frame 5, after the final frame 3"});
    // ---- POV-Ray scene language ----
    const std::string pov = "#version 3.7;\n";
    const std::string povScene = "camera { location -5*z look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n";
    t.push_back({"sdl-undeclared", {{"scene.pov", pov + "#declare A = B + 1;\n" + povScene}}, render(), 2,
                 "scene.pov:2:14: error: undeclared identifier 'B'"});
    t.push_back({"sdl-missing-semicolon", {{"scene.pov", pov + "#declare A = 1\n" + povScene}}, render(), 2,
                 "scene.pov:2:14: error: the declaration of 'A' must end with ';' (float, vector and colour "
                 "declarations need one since POV-Ray 3.5)"});
    t.push_back({"sdl-error-directive", {{"scene.pov", pov + "#error \"the scene says no\\n\"\n"}}, render(), 2,
                 "scene.pov:2:1: error: #error: the scene says no"});
    t.push_back({"sdl-never-closed", {{"scene.pov", pov + "#if (1)\n" + povScene}}, render(), 2,
                 "scene.pov:2:1: error: this directive is never closed by #end (end of file reached)"});
    t.push_back({"sdl-macro-error", {{"scene.pov", pov + "#macro M(A)\n  #local B = A + Nope;\n#end\nM(1)\n" + povScene}},
                 render(), 2, "scene.pov:3:18: error: undeclared identifier 'Nope' (in macro M called at scene.pov:5:1)"});
    t.push_back({"sdl-include-cycle", {{"scene.pov", pov + "#include \"a.inc\"\n"}, {"a.inc", "#include \"a.inc\"\n"}},
                 render(), 2,
                 "a.inc:1:1: error: include files nested deeper than 64 (does a file include itself?) (in a.inc included "
                 "from a.inc:1:1; in a.inc included from a.inc:1:1; in a.inc included from a.inc:1:1; in a.inc included from "
                 "a.inc:1:1; ... 58 more; in a.inc included from a.inc:1:1; in a.inc included from scene.pov:2:1)"});
    t.push_back({"sdl-macro-recursion", {{"scene.pov", pov + "#macro R() R() #end\nR()\n"}}, render(), 2,
                 "scene.pov:2:12: error: macro calls nested deeper than 10000 (runaway recursion?) (in macro R called at "
                 "scene.pov:2:12; in macro R called at scene.pov:2:12; in macro R called at scene.pov:2:12; in macro R called "
                 "at scene.pov:2:12; ... 9994 more; in macro R called at scene.pov:2:12; in macro R called at scene.pov:3:1)"});
    t.push_back({"pov-not-rendered", {{"scene.pov", pov + povScene + "julia_fractal { <0, 0, 0, 0> exp }\nsphere { 0, 1 }\n"}}, render(), 0,
                 "scene.pov:4:1: warning: not rendered yet: julia_fractal (left out)"});
    t.push_back({"pov-strict", {{"scene.pov", pov + povScene + "julia_fractal { <0, 0, 0, 0> exp }\nsphere { 0, 1 }\n"}},
                 {"render", "scene.pov", "16", "12", "-o", "out.png", "-q", "--strict"}, 2,
                 "scene.pov:4:1: error: not rendered yet: julia_fractal (--strict)"});
    // ---- issue 27: every form of the command line within the same limits ----
    t.push_back({"positional-depth-10^4", {{"scene.pov", kScene}}, {"16", "12", "scene.pov", "out.png", "0", "1", "10000"}, 2,
                 "rays: error: the recursion depth must be a whole number from 0 to 1000, got 10000"});
    t.push_back({"positional-spp-10^9", {{"scene.pov", kScene}}, {"16", "12", "scene.pov", "out.png", "0", "999999999", "6"}, 2,
                 "rays: error: the number of samples per pixel must be a whole number from 1 to 65536, got 999999999"});
    t.push_back({"mirrors-depth-1000", {{"scene.pov", kMirrors}}, render({"--depth", "1000"}), 0, ""});
    t.push_back({"gi-bounces-10^4", {{"scene.pov", kScene}}, render({"-gi_bounces=10000"}), 2,
                 "rays: error: gi_bounces must be a whole number from 1 to 1000, got '10000'"});
    t.push_back({"pov-frames-10^9", {{"scene.pov", kScene}}, {"+Iscene.pov", "+W16", "+H12", "+KFF999999999", "+Oout.png"}, 2,
                 "rays: error: the animation has 999999999 frames to render, more than the limit of 1000000 per run (render it in "
                 "parts with Subset_Start_Frame and Subset_End_Frame, +SF +EF)"});
    // ---- issue 27: every input within a ceiling ----
    t.push_back({"scene-endless", {}, {"render", "/dev/zero", "16", "12", "-o", "out.png", "-q"}, 2,
                 "/dev/zero: error: scene file is larger than 1 GiB (the limit for scene text)"});
    t.push_back({"kernel-endless", {{"in.png", pngBytes(16, 12)}}, {"filter", "in.png", "out.png", "kernel:/dev/zero"}, 2,
                 "/dev/zero: error: kernel file is larger than 64 MiB"});
    t.push_back({"filter-over-memory-limit", {{"in.png", pngBytes(256, 256)}}, {"filter", "in.png", "out.png", "box_blur_3"}, 2,
                 "rays: error: filtering a 256x256 image needs about 1.9 MiB, more than the memory limit of 1.0 MiB (RAYS_MEMORY_LIMIT)",
                 "out.png", "RAYS_MEMORY_LIMIT=1M"});
    t.push_back({"texture-over-memory-limit",
                 {{"scene.pov", kCamera + "sphere { <0,0,0>, 2 pigment { image_map { png \"tex.png\" } } }\n"},
                  {"tex.png", pngDeclaring(16384, 16384, 70000)}},
                 render(), 2,
                 "scene.pov:2:47: error: tex.png: cannot read image: a 16384x16384 image needs 1.5 GiB to decode, more than "
                 "the memory limit of 1.0 GiB (RAYS_MEMORY_LIMIT)",
                 "out.png", "RAYS_MEMORY_LIMIT=1G"});
    t.push_back({"textures-over-memory-limit", fourTextures(), render(), 2,
                 "rays: error: a 16x12 render with these options needs about 0.0 MiB of image buffers and 48.0 MiB for the "
                 "scene, more than the memory limit of 40.0 MiB (RAYS_MEMORY_LIMIT)",
                 "out.png", "RAYS_MEMORY_LIMIT=40M"});
    t.push_back({"obj-star-polygon-10^5", {{"scene.pov", kCamera + kLight}, {"model.obj", std::function<std::string()>([] { return starPolygonObj(100000); })}},
                 render({"--obj", "model.obj"}), 0, ""});
    std::string a, b;
    for (int i = 0; i < 40; ++i) a += "b\n", b += "c\n";
    t.push_back({"ini-read-over-and-over", {{"scene.pov", kScene}, {"a.ini", a}, {"b.ini", b}, {"c.ini", "Width=16\n"}},
                 {"a.ini", "+Iscene.pov", "+H12", "+Oout.png"}, 2,
                 "rays: error: reading INI file 'c.ini' makes more than 1000 INI files or 64 MiB of INI text read in all "
                 "(do INI files name each other over and over?) (named b.ini:15)"});
    return t;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size())) s.replace(i, from.size(), to);
    return s;
}

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return "[" + s + "]";
}

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, ExitStatusMessageAndFilesAsDocumented) {
    const BadInput& row = GetParam();
    TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    std::map<std::string, std::string> before;  // input files and their bytes
    for (const File& f : row.files) {
        if (f.directory) {
            fs::create_directories(dir.path() / f.name);
            continue;
        }
        const std::string bytes = f.contents();
        std::ofstream(dir.path() / f.name, std::ios::binary) << bytes;
        before[f.name] = bytes;
    }
    const std::vector<std::string> inputs = entries(dir.path());

    std::string envName;
    if (!row.env.empty()) {
        envName = row.env.substr(0, row.env.find('='));
        ::setenv(envName.c_str(), row.env.substr(envName.size() + 1).c_str(), 1);
    }
    const ProcessResult r = runProcess(RAYS_BINARY, row.args, dir.path().string(), std::chrono::seconds(60));
    if (!envName.empty()) ::unsetenv(envName.c_str());

    std::string cmd = "rays";
    for (const std::string& a : row.args) cmd += " " + a;
    ASSERT_TRUE(r.startError.empty() && !r.timedOut && r.termSignal == 0) << cmd << ": " << r.summary() << "\n" << r.err;
    EXPECT_EQ(r.exitCode, row.exit) << cmd << "\nstderr: " << r.err;
    const std::string expected = row.message.empty() ? "" : replaceAll(row.message, "{DIR}", dir.path().string()) + "\n";
    EXPECT_EQ(r.err, expected) << cmd;
    EXPECT_TRUE(r.out.empty()) << cmd << "\nstdout: " << r.out;

    // Inputs unchanged; a success adds exactly its output, a failure adds nothing (no temporary).
    for (const auto& [name, bytes] : before) EXPECT_EQ(readFile(dir.path() / name), bytes) << name << " changed";
    std::vector<std::string> want = inputs;
    if (row.exit == 0 && !row.output.empty()) {
        want.push_back(row.output);
        std::sort(want.begin(), want.end());
        const rays::Image8 img = rays::readImage((dir.path() / row.output).string());
        EXPECT_EQ(img.width, 16);
        EXPECT_EQ(img.height, 12);
    }
    EXPECT_EQ(entries(dir.path()), want) << cmd << " left " << join(entries(dir.path()));
}

INSTANTIATE_TEST_SUITE_P(Errors, BadInputs, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<BadInput>& info) {
                             std::string n = info.param.id;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

// docs/errors.md has a row for every catalogue entry: "| N | `id` | ... | exit | `message` | ... |".
TEST(ErrorsDoc, ListsEveryRowWithItsExitStatusAndMessage) {
    const std::string doc = readFile(fs::path(RAYS_SOURCE_DIR) / "docs" / "errors.md");
    ASSERT_FALSE(doc.empty());
    std::map<std::string, std::string> lines;  // id -> table line
    std::istringstream in(doc);
    for (std::string line; std::getline(in, line);) {
        std::smatch m;  // "| 12 | `id` | ..."
        if (std::regex_search(line, m, std::regex("^\\| [0-9]+ \\| `([^`]+)` \\|"))) lines[m[1]] = line;
    }
    const std::vector<BadInput> rows = catalogue();
    EXPECT_GE(rows.size(), 40u);
    for (const BadInput& row : rows) {
        const auto it = lines.find(row.id);
        ASSERT_NE(it, lines.end()) << "docs/errors.md has no row `" << row.id << "`";
        EXPECT_NE(it->second.find("| " + std::to_string(row.exit) + " |"), std::string::npos)
            << "exit status of " << row.id << " in: " << it->second;
        if (!row.message.empty()) {
            EXPECT_NE(it->second.find(row.message), std::string::npos) << "message of " << row.id << " in: " << it->second;
        }
    }
    EXPECT_EQ(lines.size(), rows.size()) << "docs/errors.md rows vs tests/errors_test.cpp catalogue";
}

}}  // namespace RAYS_TEST_UNIT, namespace

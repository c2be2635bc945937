// The fuzzing entry points of the library's readers (the INI reader's, in the program's code, is in
// entry_points_ini.h), shared by the libFuzzer targets in fuzz/ and by
// tests/regressions_test.cpp (which replays the saved crash inputs in tests/regressions/).
// Each takes arbitrary bytes, feeds them to one reader of the library and returns normally for any
// input: a rays::Error is the expected outcome of bad input; everything else (a crash, a sanitizer
// report, another exception type, a leak, a hang) is a finding.
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>

#include "rays/error.h"
#include "rays/image/filter.h"
#include "rays/image/kernels.h"
#include "rays/io/image_io.h"
#include "rays/io/obj_loader.h"
#include "rays/io/scene_parser.h"
#include "rays/io/ttf_font.h"
#include "rays/pov/load_pov.h"
#include "rays/sdl/interpreter.h"

namespace rays::fuzz {

/// A private directory for the files the OBJ and image targets need, created on first use under the
/// system temp dir (TMPDIR) and removed at exit.
inline const std::string& scratchDir() {
    static const std::string dir = [] {
        std::error_code ec;
        std::string tmpl = (std::filesystem::temp_directory_path(ec) / "rays-fuzz-XXXXXX").string();
        if (ec) tmpl = "/tmp/rays-fuzz-XXXXXX";
        if (!::mkdtemp(tmpl.data())) {
            std::perror("rays fuzz: mkdtemp");
            std::abort();
        }
        static std::string keep;
        keep = tmpl;
        std::atexit([] {
            std::error_code e;
            std::filesystem::remove_all(keep, e);
        });
        return tmpl;
    }();
    return dir;
}

/// A folder below scratchDir(), created on first use.
inline std::string scratchSubdir(const std::string& name) {
    const std::string d = scratchDir() + "/" + name;
    std::error_code ec;
    std::filesystem::create_directories(d, ec);
    if (ec) {
        std::perror(d.c_str());
        std::abort();
    }
    return d;
}

/// Writes bytes to path (truncating); aborts when that fails (a broken harness, not a finding).
inline void writeScratchFile(const std::string& path, std::string_view bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) {
        std::perror(path.c_str());
        std::abort();
    }
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            std::perror(path.c_str());
            std::abort();
        }
        done += size_t(n);
    }
    ::close(fd);
}

inline std::string_view asText(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// Scene lexer and parser: parseScene on the bytes as scene text. Warnings are discarded. Relative
/// texture paths resolve against the working directory (the fuzz script runs in a scratch folder).
inline void fuzzScene(const uint8_t* data, size_t size) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    opt.rotation = size % 2 ? RotationOrder::Povray : RotationOrder::Course;
    try {
        const Scene scene = parseScene(std::string(asText(data, size)), "fuzz.pov", opt);
        (void)scene;
    } catch (const Error&) {
    }
}

/// The separator between the OBJ text and an optional MTL file in an OBJ fuzz input.
inline constexpr std::string_view kMtlSeparator = "\n#--MTL--\n";

/// OBJ loader: the bytes up to kMtlSeparator go to in.obj, the rest (if any) to in.mtl next to it
/// (so `mtllib in.mtl` reaches tinyobjloader's MTL reader); then loadObj("…/in.obj").
inline void fuzzObj(const uint8_t* data, size_t size) {
    const std::string_view all = asText(data, size);
    const size_t sep = all.find(kMtlSeparator);
    const std::string obj = scratchDir() + "/in.obj", mtl = scratchDir() + "/in.mtl";
    writeScratchFile(obj, all.substr(0, sep));
    if (sep != std::string_view::npos) writeScratchFile(mtl, all.substr(sep + kMtlSeparator.size()));
    else ::unlink(mtl.c_str());
    // loadObj prints tinyobjloader's warnings on std::cerr: drop them while fuzzing.
    struct Silence {
        std::streambuf* saved = std::cerr.rdbuf(nullptr);
        ~Silence() {
            std::cerr.rdbuf(saved);
            std::cerr.clear();
        }
    } silence;
    try {
        const ObjMesh mesh = loadObj(obj);
        // What the renderer relies on: every index is in range.
        for (const ObjMesh::Face& f : mesh.faces)
            for (int c = 0; c < 3; ++c) {
                if (f.v[size_t(c)] < 0 || size_t(f.v[size_t(c)]) >= mesh.positions.size()) std::abort();
                if (f.n[size_t(c)] >= 0 && size_t(f.n[size_t(c)]) >= mesh.normals.size()) std::abort();
                if (f.t[size_t(c)] >= 0 && size_t(f.t[size_t(c)]) >= mesh.uvs.size()) std::abort();
            }
        if (mesh.faceMaterial.size() != mesh.faces.size()) std::abort();
    } catch (const Error&) {
    }
}

/// Filter kernels: the first line is a kernel spec for parseKernelSpec (`kernel:FILE` specs are
/// skipped: they would read arbitrary paths), the rest is the text of a custom kernel file for
/// parseKernelText. Every kernel that parses is applied to a small 7×5 RGBA image.
inline void fuzzKernel(const uint8_t* data, size_t size) {
    const std::string_view all = asText(data, size);
    const size_t nl = all.find('\n');
    const std::string spec(all.substr(0, nl));
    const std::string text(nl == std::string_view::npos ? std::string_view() : all.substr(nl + 1));
    Image8 img(7, 5, 4);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 37 + size);
    const BorderMode border = BorderMode(size % 4);
    auto apply = [&](const KernelSpec& k) {
        // Kernels far larger than the image cost width·height multiply-adds per pixel; keep the
        // fuzzer fast by skipping the very large ones (they are parsed all the same).
        if (double(k.width) * k.height > 4096) return;
        const Image8 out = applyFilters(img, {k}, border, 1);
        if (out.width != img.width || out.height != img.height || out.channels != img.channels) std::abort();
    };
    try {
        if (spec.rfind("kernel:", 0) != 0) apply(parseKernelSpec(spec));
    } catch (const Error&) {
    }
    try {
        apply(parseKernelText(text, "fuzz.kernel"));
    } catch (const Error&) {
    }
}

/// Image reader: the bytes go to a file (in.img) and readImage reads it back.
inline void fuzzImage(const uint8_t* data, size_t size) {
    const std::string path = scratchDir() + "/in.img";
    writeScratchFile(path, asText(data, size));
    try {
        const Image8 img = readImage(path);
        if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 ||
            img.pixels.size() != size_t(img.width) * size_t(img.height) * size_t(img.channels))
            std::abort();
    } catch (const Error&) {
    }
}

/// The include files fuzzPov's scenes find as POV-Ray's installed includes (tiny stand-ins written
/// for the harness, not POV-Ray's files): colours and textures, macros, and one including both.
inline constexpr std::string_view kPovColorsInc = R"(// fuzz harness: colours and textures
#declare White = rgb 1;
#declare Black = rgb 0;
#declare Red = rgb <1, 0, 0>;
#declare Green = rgb <0, 1, 0>;
#declare Blue = rgb <0, 0, 1>;
#declare Yellow = rgb <1, 1, 0>;
#declare Gray50 = rgb 0.5;
#declare Clear = rgbf 1;
#declare Shiny = finish { specular 0.6 roughness 0.01 reflection 0.2 }
#declare Plain = texture { pigment { color White } finish { ambient 0.1 diffuse 0.7 } }
#declare Checks = texture { pigment { checker color Red color Blue scale 0.5 } finish { Shiny } }
#declare Marble = pigment { marble turbulence 0.5 color_map { [0 Black] [0.5 Gray50] [1 White] } }
#declare Glass = material { texture { pigment { Clear } } interior { ior 1.5 } }
)";
inline constexpr std::string_view kPovMacrosInc = R"(// fuzz harness: macros
#macro Square(X) (X * X) #end
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#macro Swap(A, B) #local T = A; #declare A = B; #declare B = T; #end
#macro Ball(P, R, optional T) sphere { P, R #ifdef (T) texture { T } #end } #end
#macro Row(N) union { #for (I, 0, N - 1) Ball(<I, 0, 0>, 0.4,) #end } #end
)";
inline constexpr std::string_view kPovStdincInc = R"(// fuzz harness: includes the others
#ifndef (Stdinc_Inc_Temp)
#declare Stdinc_Inc_Temp = version;
#version 3.7;
#include "colors.inc"
#include "macros.inc"
#version Stdinc_Inc_Temp;
#end
)";

/// fuzzPov's include folder (colors.inc, macros.inc, stdinc.inc), written on first use.
inline const std::string& povIncludeDir() {
    static const std::string dir = [] {
        const std::string d = scratchSubdir("povinc");
        writeScratchFile(d + "/colors.inc", kPovColorsInc);
        writeScratchFile(d + "/macros.inc", kPovMacrosInc);
        writeScratchFile(d + "/stdinc.inc", kPovStdincInc);
        return d;
    }();
    return dir;
}

/// fuzzPov's scene folder: where #include looks first and the only place #fopen may write.
inline const std::string& povSceneDir() {
    static const std::string dir = scratchSubdir("povscene");
    return dir;
}

/// The limits fuzzPov parses with: the budgets of time and memory (loops, macro recursion, tokens,
/// array elements, string and #write bytes, items used again, objects the scene builder makes)
/// lowered from the defaults so that an input ends in well under a second and a few hundred MiB;
/// nesting and include depth stay as users get them (the C++ stack depth those allow is what should
/// be tested).
inline sdl::Limits povFuzzLimits() {
    sdl::Limits l;
    l.loopIterations = 20'000;
    l.macroDepth = 1'000;
    l.tokens = uint64_t(1) << 21;
    l.arrayElements = uint64_t(1) << 20;
    l.stringBytes = uint64_t(1) << 27;
    l.writeBytes = uint64_t(1) << 26;
    l.sceneObjects = uint64_t(1) << 16;
    l.itemCopies = uint64_t(1) << 16;
    return l;
}

/// POV-Ray scene language, items and scene builder: pov::parsePovText on the text, with the
/// harness's include folder as the installed includes, no library paths, povFuzzLimits(), and strict
/// mode on odd-sized inputs. Throws what the parse throws. Files #fopen wrote are removed after.
inline Scene parseFuzzPov(std::string_view text) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    opt.language.installedIncludeDir = povIncludeDir();
    opt.language.libraryPaths.clear();
    opt.language.strict = text.size() % 2 == 1;
    struct Tidy {  // every input starts with an empty scene folder
        ~Tidy() {
            std::error_code ec;
            for (std::filesystem::directory_iterator it(povSceneDir(), ec), end; !ec && it != end; it.increment(ec))
                std::filesystem::remove_all(it->path(), ec);
        }
    } tidy;
    return pov::parsePovText(text, "fuzz.pov", povSceneDir(), opt, povFuzzLimits());
}

/// POV-Ray scenes: parseFuzzPov on the bytes; a rays::Error is the expected answer to bad input.
inline void fuzzPov(const uint8_t* data, size_t size) {
    try {
        const Scene scene = parseFuzzPov(asText(data, size));
        (void)scene;
    } catch (const Error&) {
    }
}

/// TrueType fonts: the bytes go to a file (in.ttf), TtfFont opens it through FreeType and lays out a
/// text of letters, kerning pairs and non-ASCII code points (some the font will lack) into a
/// TextShape, extruded or flat.
inline void fuzzFont(const uint8_t* data, size_t size) {
    const std::string path = scratchDir() + "/in.ttf";
    writeScratchFile(path, asText(data, size));
    try {
        TtfFont font(path);
        const TextShape shape = font.layout("AVAWTo fi Rays \xc3\xa9\xd0\x96\xe2\x88\x91\xff 0.5!", size % 2 ? 0.25 : 0.0,
                                            Vec3(0.01 * double(size % 7), 0, 0));
        (void)shape;
    } catch (const Error&) {
    }
}

// ---- size-scaling mode ----------------------------------------------------------------------------

/// True when RAYS_FUZZ_SCALE is set (fuzz/run.sh --scaled): the targets then read their input
/// through scaledInput.
inline bool scaling() {
    static const bool on = std::getenv("RAYS_FUZZ_SCALE") != nullptr;
    return on;
}

/// Size-scaling mode (issue 27: the quadratic OBJ polygon was not found by fuzzing, whose inputs
/// stay small): the input's first byte k sets a count 2^(k mod 18) (1 to 131072), and each region
/// written between a pair of "@@" markers is repeated that many times (the whole result at most
/// 32 MiB). A few bytes such as "\x10f@@ 1@@\n" then make a face of 65536 corners, so work that
/// grows faster than its input shows up as a libFuzzer timeout (-timeout) or out-of-memory report.
inline std::string scaledInput(const uint8_t* data, size_t size) {
    if (size == 0) return {};
    const size_t count = size_t(1) << (data[0] % 18);
    constexpr size_t kMaxBytes = size_t(32) << 20;
    const std::string_view in(reinterpret_cast<const char*>(data + 1), size - 1);
    std::string out;
    size_t pos = 0;
    while (pos < in.size()) {
        const size_t open = in.find("@@", pos);
        const size_t close = open == std::string_view::npos ? open : in.find("@@", open + 2);
        if (close == std::string_view::npos) {
            out.append(in.substr(pos));
            break;
        }
        out.append(in.substr(pos, open - pos));
        const std::string_view body = in.substr(open + 2, close - open - 2);
        for (size_t i = 0; i < count && out.size() + body.size() <= kMaxBytes; ++i) out.append(body);
        pos = close + 2;
    }
    return out;
}

/// Runs target on the input as it is, or in size-scaling mode on its expansion.
template <class Target>
void run(Target target, const uint8_t* data, size_t size) {
    if (!scaling()) return target(data, size);
    const std::string big = scaledInput(data, size);
    target(reinterpret_cast<const uint8_t*>(big.data()), big.size());
}

}  // namespace rays::fuzz

// The four fuzzing entry points, shared by the libFuzzer targets in fuzz/ and by
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

}  // namespace rays::fuzz

// OBJ loading: a strict pre-scan of our own (tinyobjloader silently reads bad numbers as 0 and only warns,
// without a usable line number, about out-of-range indices), then tinyobjloader for the actual parse.
#include "rays/io/obj_loader.h"
#include "rays/io/polygon_triangulate.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string_view>

#include <tiny_obj_loader.h>
#include <zlib.h>

#include "rays/error.h"
#include "rays/io/file_text.h"

namespace rays {
namespace {

bool isGzipName(const std::string& path) { return path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0; }

/// The decompressed text of a gzip file (zlib's gzread).
std::string readGzipFile(const std::string& path) {
    gzFile f = gzopen(path.c_str(), "rb");
    if (!f) failFile(path, std::string("cannot open OBJ file: ") + std::strerror(errno ? errno : ENOENT));
    std::string text;
    char chunk[1 << 16];
    for (;;) {
        const int n = gzread(f, chunk, sizeof chunk);
        if (n < 0) {
            int code = 0;
            const std::string why = gzerror(f, &code);
            gzclose(f);
            failFile(path, "cannot read compressed OBJ file: " + why);
        }
        if (n == 0) break;
        if (text.size() + size_t(n) > kMaxTextFileBytes) {
            gzclose(f);
            failFile(path, "OBJ file is larger than " + FileText::describe(kMaxTextFileBytes) + " decompressed");
        }
        text.append(chunk, size_t(n));
    }
    gzclose(f);
    return text;
}

// The OBJ file's text as source text (byte-order mark skipped, lone CRs end lines), at most
// kMaxTextFileBytes (an endless source such as /dev/zero stops there); a .gz file decompressed.
std::string readWholeFile(const std::string& path) {
    if (isGzipName(path)) {
        std::string text = readGzipFile(path);
        const size_t start = makeSourceText(text.data(), text.size());
        return text.erase(0, start);
    }
    FileText text(path, TextForm::Source);
    if (text.status() == FileText::Status::CannotOpen) failFile(path, std::string("cannot open OBJ file: ") + std::strerror(errno));
    if (text.status() == FileText::Status::CannotRead) failFile(path, "cannot read OBJ file");
    if (text.status() == FileText::Status::TooLarge)
        failFile(path, "OBJ file is larger than " + FileText::describe(kMaxTextFileBytes));
    return std::string(text.text());
}

// MTL files as tinyobjloader's MaterialFileReader finds them (the OBJ's folder, or as named), read
// as source text: a UTF-8 byte-order mark at the start would otherwise hide the first statement
// (usually the first `newmtl`, losing that material). tinyobj ends lines at \n, \r\n and \r itself.
class SourceMtlReader : public tinyobj::MaterialReader {
public:
    explicit SourceMtlReader(std::string folder) : folder_(std::move(folder)) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* byName, std::string* warn, std::string* err) override {
        std::ifstream file(folder_ + name, std::ios::binary);
        if (!file) {
            if (warn) *warn += "Material file [ " + name + " ] not found in a path : " + folder_ + "\n";
            return false;
        }
        std::ostringstream bytes;
        bytes << file.rdbuf();
        std::string text = bytes.str();
        if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
        std::istringstream in(text);
        tinyobj::LoadMtl(byName, materials, &in, warn, err);
        return true;
    }

private:
    std::string folder_;  ///< "" or ending in '/'
};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string quoted(std::string_view s) {
    if (s.size() > 40) return "'" + std::string(s.substr(0, 40)) + "...'";
    return "'" + std::string(s) + "'";
}

/// Validates the v/vn/vt/f lines of an OBJ text; throws Error "PATH:LINE:1: error: ..." at the first problem.
/// Line numbering matches tinyobjloader's ("\n", "\r\n" and a lone "\r" each end a line).
class PreScanner {
public:
    PreScanner(const std::string& path, std::string_view text) : path_(path), text_(text) {}

    /// Validates the text; returns the corner count of each face, in file order.
    std::vector<uint32_t> run() {
        const char* p = text_.data();
        const char* const end = p + text_.size();
        while (p < end) {
            ++line_;
            const char* e = p;
            while (e < end && *e != '\n' && *e != '\r') ++e;
            scanLine(p, e);
            if (e == end) break;
            p = (*e == '\r' && e + 1 < end && e[1] == '\n') ? e + 2 : e + 1;
        }
        for (const Pending& f : forward_) {
            const int count = counts_[f.kind];
            if (f.index > count) fail(f.line, outOfRange(f.kind, f.index, count, false));
        }
        return std::move(faceCorners_);
    }

private:
    enum Kind { V = 0, VT = 1, VN = 2 };
    struct Pending {
        int line, kind, index;
    };

    [[noreturn]] void fail(int line, const std::string& msg) const { rays::fail(SourceLoc{path_, line, 1}, msg); }

    static std::string outOfRange(int kind, int index, int count, bool relative) {
        static const char* const names[3] = {"vertex", "texture coordinate", "normal"};
        static const char* const plurals[3] = {"vertices", "texture coordinates", "normals"};
        return std::string(names[kind]) + " index " + std::to_string(index) + " is out of range (" +
               std::to_string(count) + " " + (count == 1 ? names[kind] : plurals[kind]) +
               (relative ? " defined before this line)" : " in the file)");
    }

    /// Next whitespace-separated field in [p, e), advancing p; empty at the end of the line.
    static std::string_view nextField(const char*& p, const char* e) {
        while (p < e && isBlank(*p)) ++p;
        const char* b = p;
        while (p < e && !isBlank(*p)) ++p;
        return {b, size_t(p - b)};
    }

    void scanLine(const char* p, const char* e) {
        const std::string_view key = nextField(p, e);
        if (key == "v")
            scanNumbers(p, e, "v", 3, 7), ++counts_[V];
        else if (key == "vt")
            scanNumbers(p, e, "vt", 1, 3), ++counts_[VT];
        else if (key == "vn")
            scanNumbers(p, e, "vn", 3, 3), ++counts_[VN];
        else if (key == "f")
            scanFace(p, e);
        else if (key == "vw")
            scanSkinWeights(p, e);
    }

    // tinyobjloader's `vw VERTEX JOINT WEIGHT [JOINT WEIGHT ...]` extension (skin weights, unused by
    // Rays): it converts each joint id to int without a check (undefined behaviour for 1e39, found by
    // fuzzing), so joint ids must be numbers from 0 to 2^24.
    void scanSkinWeights(const char* p, const char* e) {
        nextField(p, e);  // the vertex
        for (int k = 0;; ++k) {
            std::string_view f = nextField(p, e);
            if (f.empty() || f[0] == '#') break;
            if (k % 2 != 0) continue;  // a weight
            const std::string_view orig = f;
            if (f.size() > 1 && f[0] == '+') f.remove_prefix(1);
            double value = 0;
            const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), value);
            if (ec != std::errc() || ptr != f.data() + f.size() || !(value >= 0 && value <= 16777216.0))
                fail(line_, "invalid joint id " + quoted(orig) + " in 'vw' line (a number from 0 to 16777216)");
        }
    }

    void scanNumbers(const char* p, const char* e, const char* key, int minCount, int maxCount) {
        int n = 0;
        for (;;) {
            std::string_view f = nextField(p, e);
            if (f.empty() || f[0] == '#') break;
            const std::string_view orig = f;
            if (f.size() > 1 && f[0] == '+') f.remove_prefix(1);
            double value = 0;
            const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), value);
            if (ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(value))
                fail(line_, std::string("invalid number ") + quoted(orig) + " in '" + key + "' line");
            ++n;
        }
        if (n < minCount || n > maxCount) {
            const std::string expected = minCount == maxCount ? std::to_string(minCount)
                                                              : std::to_string(minCount) + " to " +
                                                                    std::to_string(maxCount);
            fail(line_, std::string("'") + key + "' line needs " + expected + " numbers, got " +
                            std::to_string(n));
        }
    }

    void scanFace(const char* p, const char* e) {
        int corners = 0;
        for (;;) {
            const std::string_view f = nextField(p, e);
            if (f.empty()) break;
            if (f[0] == '#') fail(line_, "comment after a face is not supported (put it on its own line)");
            // i, i/j, i//k or i/j/k
            std::string_view parts[3];
            int nparts = 0;
            size_t start = 0;
            for (;;) {
                const size_t slash = f.find('/', start);
                if (nparts == 3) fail(line_, "invalid face vertex " + quoted(f) + " (too many '/')");
                parts[nparts++] = f.substr(start, slash == std::string_view::npos ? slash : slash - start);
                if (slash == std::string_view::npos) break;
                start = slash + 1;
            }
            static const int kinds[3] = {V, VT, VN};
            for (int i = 0; i < nparts; ++i) {
                if (parts[i].empty()) {
                    if (i == 1 && nparts == 3) continue;  // i//k
                    fail(line_, "invalid face vertex " + quoted(f) + " (missing index)");
                }
                checkIndex(parts[i], kinds[i], f);
            }
            ++corners;
        }
        if (corners < 3) fail(line_, "face needs at least 3 vertices, got " + std::to_string(corners));
        faceCorners_.push_back(uint32_t(corners));
    }

    void checkIndex(std::string_view s, int kind, std::string_view field) {
        if (s.size() > 1 && s[0] == '+') s.remove_prefix(1);
        int index = 0;
        const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
        if (ec != std::errc() || ptr != s.data() + s.size())
            fail(line_, "invalid face vertex " + quoted(field) + " (index " + quoted(s) + " is not an integer)");
        if (index == 0) fail(line_, "invalid face vertex " + quoted(field) + " (indices start at 1, not 0)");
        const int count = counts_[kind];
        if (index < 0) {
            if (-index > count) fail(line_, outOfRange(kind, index, count, true));
        } else if (index > count) {
            forward_.push_back({line_, kind, index});  // legal if defined further down; checked at the end
        }
    }

    const std::string& path_;
    std::string_view text_;
    int line_ = 0;
    int counts_[3] = {0, 0, 0};
    std::vector<Pending> forward_;
    std::vector<uint32_t> faceCorners_;  ///< tinyobjloader keeps only the low 8 bits of these
};

/// The line number in a tinyobjloader message ("... line 12.)", "line: 12"), or 0.
int lineFromMessage(const std::string& msg) {
    for (size_t pos = msg.find("line"); pos != std::string::npos; pos = msg.find("line", pos + 4)) {
        size_t i = pos + 4;
        while (i < msg.size() && (msg[i] == ' ' || msg[i] == ':')) ++i;
        int n = 0;
        bool digits = false;
        while (i < msg.size() && msg[i] >= '0' && msg[i] <= '9' && n < 100000000) {
            n = n * 10 + (msg[i++] - '0');
            digits = true;
        }
        if (digits && n > 0) return n;
    }
    return 0;
}

/// Non-empty lines of a tinyobjloader message, trimmed.
std::vector<std::string> messageLines(const std::string& msg) {
    std::vector<std::string> out;
    size_t b = 0;
    while (b < msg.size()) {
        size_t e = msg.find('\n', b);
        if (e == std::string::npos) e = msg.size();
        size_t s = b, t = e;
        while (s < t && isBlank(msg[s])) ++s;
        while (t > s && isBlank(msg[t - 1])) --t;
        if (t > s) out.emplace_back(msg, s, t - s);
        b = e + 1;
    }
    return out;
}

}  // namespace

ObjMesh loadObj(const std::string& path) {
    std::string text = readWholeFile(path);
    const std::vector<uint32_t> faceCorners = PreScanner(path, text).run();

    // The text read once is what tinyobjloader parses; MTL files are searched in the OBJ's folder.
    // Polygons are triangulated here, in linear time (polygon_triangulate.h), not by tinyobjloader.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    const size_t slash = path.find_last_of('/');
    SourceMtlReader mtlReader(slash == std::string::npos ? std::string() : path.substr(0, slash + 1));
    bool ok = false;
    {
        std::stringbuf buffer(std::move(text));
        std::istream in(&buffer);
        ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, &mtlReader, false, false);
    }
    for (const std::string& w : messageLines(warning)) std::cerr << formatWarning(SourceLoc{path, 0, 0}, w) << "\n";
    if (!ok) {
        const std::vector<std::string> lines = messageLines(error);
        std::string msg;
        for (const std::string& l : lines) msg += (msg.empty() ? "" : "; ") + l;
        if (msg.empty()) msg = "cannot parse OBJ file";
        const int line = lineFromMessage(error);
        fail(SourceLoc{path, line, line > 0 ? 1 : 0}, msg);
    }
    // A non-fatal error text (e.g. from the MTL parser) is still worth showing.
    for (const std::string& w : messageLines(error)) std::cerr << formatWarning(SourceLoc{path, 0, 0}, w) << "\n";

    ObjMesh mesh;
    mesh.positions.resize(attrib.vertices.size() / 3);
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        mesh.positions[i] = Vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    mesh.normals.resize(attrib.normals.size() / 3);
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        mesh.normals[i] = Vec3(attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]);
    mesh.uvs.resize(attrib.texcoords.size() / 2);
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        mesh.uvs[i] = {double(attrib.texcoords[2 * i]), double(attrib.texcoords[2 * i + 1])};

    const std::string dir = path.find('/') == std::string::npos ? "" : path.substr(0, path.rfind('/') + 1);
    for (const tinyobj::material_t& m : materials) {
        ObjMesh::Material mat;
        mat.name = m.name;
        mat.diffuse = Vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
        mat.diffuseTexture = m.diffuse_texname;
        if (!mat.diffuseTexture.empty() && mat.diffuseTexture[0] != '/')
            mat.diffuseTexture = dir + mat.diffuseTexture;
        mesh.materials.push_back(std::move(mat));
    }

    size_t total = 0;  // triangles: a polygon of n corners makes n - 2
    for (const uint32_t n : faceCorners) total += n - 2;
    mesh.faces.reserve(total);
    mesh.faceMaterial.reserve(total);
    const int nv = int(mesh.positions.size()), nn = int(mesh.normals.size()), nt = int(mesh.uvs.size());
    const int nm = int(mesh.materials.size());
    // tinyobjloader lists the faces in file order, shape after shape, and keeps each one's corner
    // count in a byte: the pre-scan's counts are the true ones.
    std::vector<Vec3> corners;
    size_t face = 0;
    for (const tinyobj::shape_t& s : shapes) {
        size_t k = 0;
        for (size_t f = 0; f < s.mesh.num_face_vertices.size(); ++f, ++face) {
            if (face >= faceCorners.size() || uint8_t(faceCorners[face]) != s.mesh.num_face_vertices[f] ||
                k + faceCorners[face] > s.mesh.indices.size())
                failFile(path, "faces read differently by the pre-scan and tinyobjloader");
            const size_t n = faceCorners[face];
            corners.clear();
            for (size_t c = 0; c < n; ++c) {
                const tinyobj::index_t& idx = s.mesh.indices[k + c];
                // The pre-scan guarantees these; check anyway rather than hand out bad indices.
                if (idx.vertex_index < 0 || idx.vertex_index >= nv || idx.normal_index >= nn || idx.texcoord_index >= nt)
                    failFile(path, "face index out of range");
                corners.push_back(mesh.positions[size_t(idx.vertex_index)]);
            }
            const int m = f < s.mesh.material_ids.size() ? s.mesh.material_ids[f] : -1;
            for (const std::array<int, 3>& tri : triangulatePolygon(corners)) {
                ObjMesh::Face out;
                for (size_t c = 0; c < 3; ++c) {
                    const tinyobj::index_t& idx = s.mesh.indices[k + size_t(tri[c])];
                    out.v[c] = idx.vertex_index;
                    out.n[c] = idx.normal_index < 0 ? -1 : idx.normal_index;
                    out.t[c] = idx.texcoord_index < 0 ? -1 : idx.texcoord_index;
                }
                mesh.faces.push_back(out);
                mesh.faceMaterial.push_back(m >= 0 && m < nm ? m : -1);
            }
            k += n;
        }
    }
    return mesh;
}

}  // namespace rays

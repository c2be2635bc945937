// #fopen, #fclose, #read and #write (POV-Ray 3.7 reference, "File I/O Directives"). Files are
// read whole when opened (at most 64 MiB) and parsed item by item; written files are plain
// text (or binary words). Written files must lie in the scene's folder or below it: a scene
// cannot write anywhere else.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "rays/error.h"
#include "rays/io/file_text.h"
#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"
#include "rays/sdl/pov_strings.h"

namespace rays::sdl {

namespace fs = std::filesystem;

struct FileHandle {
    std::string shownName;
    bool writing = false;
    std::string content;  ///< reading: the whole file
    size_t pos = 0;
    std::FILE* out = nullptr;
    ~FileHandle() {
        if (out) std::fclose(out);
    }
};

namespace {
constexpr size_t kMaxReadFile = size_t(64) << 20;

// Whether p lies in folder or below it (links and ".." resolved); ec tells why when a path cannot
// be resolved (a name too long for the system, a component that is not a folder), and the answer
// is then false.
bool insideFolder(const fs::path& folder, const fs::path& p, std::error_code& ec) {
    const fs::path a = fs::weakly_canonical(folder, ec);
    if (ec) return false;
    const fs::path b = fs::weakly_canonical(p, ec);
    if (ec) return false;
    auto ai = a.begin(), bi = b.begin();
    for (; ai != a.end(); ++ai, ++bi)
        if (bi == b.end() || *ai != *bi) return false;
    return true;
}
}  // namespace

void Interpreter::dirFopen(const Loc& at) {
    const uint32_t name = readNewName("file handle");
    const std::string file = parseString();
    const Kw mode = kw();
    if (mode != Kw::read && mode != Kw::write && mode != Kw::append)
        errorHere("expected read, write or append after the file name, found " + describe());
    next();
    auto h = std::make_shared<FileHandle>();
    h->shownName = file;
    if (mode == Kw::read) {
        const std::string path = findFile(file);
        if (path.empty()) error(at, "cannot find \"" + file + "\" to read");
        FileText text(path, TextForm::Source, kMaxReadFile);
        if (text.status() == FileText::Status::TooLarge) error(at, "\"" + file + "\" is larger than 64 MiB");
        if (text.status() != FileText::Status::Ok) error(at, "cannot read \"" + file + "\"");
        h->content.assign(text.text());
    } else {
        const fs::path p = fs::path(file).is_absolute() ? fs::path(file) : fs::path(sceneFolder_) / file;
        std::error_code ec;
        const bool inside = insideFolder(sceneFolder_, p, ec);
        if (ec) error(at, "cannot open \"" + file + "\" to write: " + ec.message());
        if (!inside)
            error(at, "#fopen may only write files in the scene's folder or below it (\"" + file + "\" is outside)");
        for (const auto& f : files_)  // a run never writes over its own input
            if (fs::exists(p, ec) && fs::equivalent(p, f->path, ec))
                error(at, "#fopen would overwrite \"" + f->shownName + "\", a scene file this parse reads");
        // Nor one of the run's own outputs (compared by name, links and ".." resolved).
        auto resolved = [](const fs::path& q) {
            std::error_code e;
            const fs::path r = fs::weakly_canonical(fs::absolute(q, e), e);
            return e ? fs::path() : r;
        };
        const fs::path target = resolved(p);
        for (const std::string& out : options_.outputFiles)
            if (!out.empty() && !target.empty() && resolved(out) == target)
                error(at, "#fopen would overwrite \"" + out + "\", an output of this run");
        h->writing = true;
        h->out = std::fopen(p.string().c_str(), mode == Kw::write ? "wb" : "ab");
        if (!h->out) error(at, "cannot open \"" + file + "\" for writing");
    }
    scopes_.declare(name, Value::file(std::move(h)));
}

void Interpreter::dirFclose() {
    const Loc at = loc();
    const uint32_t name = readNewName("file handle");
    Binding* b = scopes_.find(name);
    if (!b || b->value.type != VType::File) error(at, "'" + std::string(names_.name(name)) + "' is not an open file");
    scopes_.undef(name);
}

namespace {

// One data item of a #read file: a string literal, a float, or a vector literal; false at the end.
bool readDatum(FileHandle& h, Value& out, std::string& problem) {
    std::string& s = h.content;
    size_t& i = h.pos;
    auto skip = [&] {
        while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',')) ++i;
    };
    auto number = [&](double& v) {
        const char* b = s.c_str() + i;
        char* e = nullptr;
        v = std::strtod(b, &e);
        if (e == b) return false;
        i += size_t(e - b);
        return true;
    };
    skip();
    if (i >= s.size()) return false;
    if (s[i] == '"') {
        const size_t e = s.find('"', i + 1);
        if (e == std::string::npos) {
            problem = "unterminated string";
            return false;
        }
        out = Value::string(s.substr(i + 1, e - i - 1));
        i = e + 1;
        return true;
    }
    if (s[i] == '<') {
        ++i;
        double c[5];
        int n = 0;
        for (;;) {
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            if (n == 5 || !number(c[n])) {
                problem = "malformed vector";
                return false;
            }
            ++n;
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            if (i < s.size() && s[i] == ',') {
                ++i;
                continue;
            }
            if (i < s.size() && s[i] == '>') {
                ++i;
                break;
            }
            problem = "malformed vector";
            return false;
        }
        out = Value::vector(n, c);
        return true;
    }
    double v;
    if (!number(v)) {
        problem = "expected a string, number or vector";
        return false;
    }
    out = Value::number(v);
    return true;
}

}  // namespace

void Interpreter::dirRead(const Loc& at) {
    expectSym('(', "after #read");
    const uint32_t handle = readNewName("file handle");
    Binding* b = scopes_.find(handle);
    if (!b || b->value.type != VType::File || b->value.file().writing)
        error(at, "'" + std::string(names_.name(handle)) + "' is not a file opened for reading");
    const Value fileValue = b->value;
    std::vector<uint32_t> targets;
    while (acceptSym(',')) targets.push_back(readNewName("#read target"));
    expectSym(')', "to close #read");
    FileHandle& h = fileValue.file();
    for (uint32_t target : targets) {
        Value v;
        std::string problem;
        if (!readDatum(h, v, problem)) {
            if (!problem.empty()) error(at, "#read from \"" + h.shownName + "\": " + problem);
            scopes_.undef(handle);  // reading past the end closes the file (defined() turns false)
            return;
        }
        scopes_.declare(target, std::move(v));
    }
}

void Interpreter::dirWrite(const Loc& at) {
    expectSym('(', "after #write");
    const uint32_t handle = readNewName("file handle");
    Binding* b = scopes_.find(handle);
    if (!b || b->value.type != VType::File || !b->value.file().writing)
        error(at, "'" + std::string(names_.name(handle)) + "' is not a file opened for writing");
    const Value fileValue = b->value;
    std::FILE* out = fileValue.file().out;
    auto put = [&](const std::string& bytes) {
        spend(writeBytes_, bytes.size(), limits_.writeBytes, at, "bytes written by #write");
        std::fwrite(bytes.data(), 1, bytes.size(), out);
    };
    for (;;) {  // commas between the items are optional, as in POV-Ray
        acceptSym(',');
        if (isSym(')')) break;
        const Kw k = kw();
        int bytes = 0;
        bool isSigned = false, bigEndian = false;
        switch (k) {
            case Kw::uint8: bytes = 1; break;
            case Kw::sint8: bytes = 1; isSigned = true; break;
            case Kw::uint16be: bytes = 2; bigEndian = true; break;
            case Kw::uint16le: bytes = 2; break;
            case Kw::sint16be: bytes = 2; isSigned = true; bigEndian = true; break;
            case Kw::sint16le: bytes = 2; isSigned = true; break;
            case Kw::sint32be: bytes = 4; isSigned = true; bigEndian = true; break;
            case Kw::sint32le: bytes = 4; isSigned = true; break;
            default: break;
        }
        if (bytes) {
            next();
            // Values up to the next comma are written as binary words, rounded and clamped.
            const Value v = parseNumeric(false);
            const double lo = isSigned ? -std::ldexp(1.0, bytes * 8 - 1) : 0.0;
            const double hi = isSigned ? std::ldexp(1.0, bytes * 8 - 1) - 1 : std::ldexp(1.0, bytes * 8) - 1;
            const int n = v.type == VType::Float ? 1 : v.dim;
            spend(writeBytes_, uint64_t(n * bytes), limits_.writeBytes, at, "bytes written by #write");
            for (int c = 0; c < n; ++c) {
                const long long w = (long long)std::clamp(std::round(v.c[c]), lo, hi);
                for (int i = 0; i < bytes; ++i) {
                    const int shift = 8 * (bigEndian ? bytes - 1 - i : i);
                    std::fputc(int((unsigned long long)w >> shift) & 0xFF, out);
                }
            }
            continue;
        }
        if (atStringStart()) {
            put(parseString());
            continue;
        }
        const Value v = parseNumeric(false);
        if (v.type == VType::Float) {
            put(povWriteFloat(v.c[0]));
        } else if (v.isNumeric()) {
            put(povWriteVector(std::span<const double>(v.c.data(), v.dim)));
        } else {
            error(at, std::string("#write cannot write a ") + typeName(v.type));
        }
    }
    expectSym(')', "to close #write");
    std::fflush(out);
}

}  // namespace rays::sdl

#include "pov_options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "arg_text.h"
#include "paths.h"
#include "pov_option_table.h"
#include "rays/error.h"
#include "rays/io/file_text.h"
#include "rays/sdl/declare_value.h"

namespace rays::cli {
namespace {

namespace fs = std::filesystem;

/// Largest INI file read (16 MiB): POV-Ray's INI files are a few KiB; /dev/zero stops here.
constexpr size_t kMaxIniFileBytes = size_t(16) << 20;
// INI files read in one run, counting each time a file is read again, and their bytes: nesting
// stops at 10 levels, but files naming others many times each would otherwise multiply the reads.
constexpr size_t kMaxIniFilesRead = 1000;
constexpr size_t kMaxIniBytesRead = size_t(64) << 20;
using pov::Form;
using pov::Key;
using pov::Kind;

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    const size_t b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && lower(s.substr(s.size() - suffix.size())) == suffix;
}

// A value wrapped in matching single or double quotes loses them (+I"my file.pov").
std::string unquote(const std::string& v) {
    if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front()) return v.substr(1, v.size() - 2);
    return v;
}

std::string folderOf(const std::string& path) {
    return fs::path(path).parent_path().string();
}

// A relative name from an INI file: as POV-Ray 3.7 does, relative to the current folder; when no
// such file exists there but one does next to the INI file, that one (so `rays dir/scene.ini`
// works from anywhere).
std::string besideIni(const std::string& name, const std::vector<std::string>& iniStack) {
    if (name.empty() || name[0] == '/' || iniStack.empty() || fileExists(name)) return name;
    const std::string folder = folderOf(iniStack.back());
    if (folder.empty()) return name;
    const std::string beside = folder + "/" + name;
    return fileExists(beside) ? beside : name;
}

bool isIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

bool parseDouble(const std::string& text, double& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return *end == '\0' && errno == 0 && std::isfinite(out);
}

bool parseLong(const std::string& text, long& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(text.c_str(), &end, 10);
    return *end == '\0' && errno == 0;
}

// INI booleans (reference 3.2): true, yes, on, 1 and false, no, off, 0, any case.
bool parseBool(const std::string& text, bool& out) {
    const std::string l = lower(text);
    if (l == "on" || l == "true" || l == "yes" || l == "1") return out = true, true;
    if (l == "off" || l == "false" || l == "no" || l == "0") return out = false, true;
    return false;
}

// Splits an INI line of switches into words; quotes keep blanks inside a word, ';' outside quotes
// starts a comment.
std::vector<std::string> switchWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    char quote = 0;
    for (char c : line) {
        if (quote) {
            word += c;
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            word += c;
            quote = c;
        } else if (c == ';') {
            break;
        } else if (c == ' ' || c == '\t') {
            if (!word.empty()) words.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    if (!word.empty()) words.push_back(word);
    return words;
}

// The line without its comment: ';' starts a comment unless inside quotes that open at the start
// of the text, after '=' or after a blank (an apostrophe inside a word opens nothing).
std::string withoutComment(const std::string& line) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if ((c == '"' || c == '\'') && (i == 0 || line[i - 1] == '=' || line[i - 1] == ' ' || line[i - 1] == '\t')) {
            quote = c;
        } else if (c == ';') {
            return line.substr(0, i);
        }
    }
    return line;
}

// "name[Section]" → name and section (empty when there is none).
void splitSection(const std::string& arg, std::string& name, std::string& section) {
    const size_t open = arg.find('[');
    if (!arg.empty() && arg.back() == ']' && open != std::string::npos) {
        name = trim(arg.substr(0, open));
        section = trim(arg.substr(open + 1, arg.size() - open - 2));
    } else {
        name = arg;
        section.clear();
    }
}

[[noreturn]] void failAt(const PovOptionReader::Where& where, const std::string& message) {
    if (!where.file.empty()) throw Error("rays: error: " + where.file + ":" + std::to_string(where.line) + ": " + message);
    throw Error("rays: error: " + where.text + ": " + message);
}

}  // namespace

// A setting's value read as its key's kind; the checks name the key and the value.
struct PovOptionReader::Value {
    const pov::KeyInfo& info;
    const std::string& text;
    const Where& where;
    bool flag = false;
    long integer = 0;
    double number = 0;

    [[noreturn]] void fail(const std::string& rule) const {
        failAt(where, std::string(info.name) + " must be " + rule + ", got '" + text + "'");
    }
    int atLeast(long lo, const char* rule) const {
        if (integer < lo) fail(rule);
        return int(std::min(integer, 1L << 30));
    }
    int inRange(long lo, long hi) const {
        if (integer < lo || integer > hi) fail("a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
        return int(integer);
    }
    // Start_Row … End_Column and the subset frames: a fraction below 1, else a whole number.
    double bound(const char* unit) const {
        if (number < 0 || (number >= 1 && number != std::floor(number)))
            fail(std::string("a fraction below 1 or a ") + unit + " number");
        return std::min(number, 1e9);
    }
};

PovOptionReader::Value PovOptionReader::readValue(const pov::KeyInfo& info, const std::string& text, const Where& where) {
    Value v{info, text, where};
    switch (info.kind) {
        case Kind::Bool:
            if (!parseBool(text, v.flag)) v.fail("on or off (true/false, yes/no, 1/0)");
            break;
        case Kind::Int:
            if (!parseLong(text, v.integer))
                v.fail(info.key == Key::Width || info.key == Key::Height || info.key == Key::FrameStep ? "a positive integer"
                                                                                                        : "a whole number");
            break;
        case Kind::Float:
            if (!parseDouble(text, v.number)) v.fail("a number");
            break;
        case Kind::Text:
            if (text.empty()) failAt(where, std::string(info.name) + " needs a value");
            break;
    }
    return v;
}

bool isPovSwitch(const std::string& arg) {
    return arg.size() >= 2 && (arg[0] == '+' || arg[0] == '-') && std::isalpha(static_cast<unsigned char>(arg[1]));
}

bool isPovSetting(const std::string& arg) {
    const size_t eq = arg.find('=');
    return eq != std::string::npos && isIdentifier(trim(arg.substr(0, eq)));
}

bool isIniArgument(const std::string& arg) {
    if (arg.empty() || arg[0] == '+' || arg[0] == '-' || isPovSetting(arg)) return false;
    return endsWithNoCase(arg, ".ini") || (arg.back() == ']' && arg.find('[') != std::string::npos);
}

bool isSceneArgument(const std::string& arg) {
    return !arg.empty() && arg[0] != '+' && arg[0] != '-' && !isPovSetting(arg) && endsWithNoCase(arg, ".pov");
}

PovOptionReader::PovOptionReader(PovOptions& options, Warn warn) : o_(options), warn_(std::move(warn)) {}


void PovOptionReader::warnOnce(const std::string& key, const std::string& message, const Where& where) {
    if (!warned_.insert(lower(key)).second || !warn_) return;
    if (!where.file.empty())
        warn_(where.file + ":" + std::to_string(where.line) + ": warning: " + message);
    else
        warn_("rays: warning: " + where.text + ": " + message);
}

void PovOptionReader::readArgument(const std::string& arg) {
    const Where where{"", 0, arg};
    if (isPovSwitch(arg)) return readSwitch(arg, where);
    if (isPovSetting(arg)) return setKeyValue(arg, where);
    if (isSceneArgument(arg)) {
        o_.inputFile = resolveScene(arg, where);
        return;
    }
    std::string name, section;
    splitSection(arg, name, section);
    readIniFile(name, section, "on the command line");
}

void PovOptionReader::readSwitch(const std::string& sw, const Where& where) {
    const bool plus = sw[0] == '+';
    const std::string body = sw.substr(1);
    const pov::SwitchInfo* s = pov::findSwitch(body);
    if (!s) return warnOnce(sw, "unknown option '" + sw + "'", where);
    const std::string rest = unquote(body.substr(std::string(s->letters).size()));
    switch (s->form) {
        case Form::Value:
            if (rest.empty()) failAt(where, std::string("'") + sw[0] + s->letters + "' needs a value (" + s->key + ")");
            return set(s->key, rest, where);
        case Form::Toggle:
            if (!rest.empty()) return warnOnce(sw, "unknown option '" + sw + "'", where);
            return set(s->key, plus ? "on" : "off", where);
        case Form::OnValue:
            // The sign first, then the value: +J0 sets jitter on, then its amount 0 turns it off.
            set(s->key, plus ? "on" : "off", where);
            if (!rest.empty()) set(s->second, rest, where);
            return;
    }
}

std::string PovOptionReader::resolveScene(const std::string& name, const Where& where) const {
    if (name == "-") failAt(where, "reading the scene from standard input (+I-) is not supported");
    std::string path = extensionDot(name) != std::string::npos ? name : name + ".pov";  // ".pov is assumed" (reference 3.2.5.2)
    return where.file.empty() ? path : besideIni(path, iniStack_);
}

void PovOptionReader::setKeyValue(const std::string& text, const Where& where) {
    const size_t eq = text.find('=');
    set(trim(text.substr(0, eq)), unquote(trim(text.substr(eq + 1))), where);
}

void PovOptionReader::set(const std::string& keyName, const std::string& value, const Where& where) {
    const pov::KeyInfo* info = pov::findKey(keyName);
    if (!info) return warnOnce(keyName, "unknown option '" + keyName + "'", where);
    // POV-Ray reads `Key=` with nothing after it as "no value": the setting stays as it was
    // (advanced/benchmark/benchmark.ini has All_File=, Output_File_Name=, Include_Header=).
    if (info->kind == pov::Kind::Text && value.empty()) return;
    const Value v = readValue(*info, value, where);
    if (!setAnimation(v) && !setAntialias(v) && !setOutput(v)) setOther(v);
}

bool PovOptionReader::setAnimation(const Value& v) {
    AnimationOptions& a = o_.animation;
    switch (v.info.key) {
        case Key::Clock: a.clock = v.number, a.clockGiven = true; return true;
        case Key::InitialFrame: a.initialFrame = v.atLeast(0, "a whole number, 0 or more"); return true;
        case Key::FinalFrame: a.finalFrame = v.atLeast(-1, "a whole number, -1 or more"); return true;
        case Key::InitialClock: a.initialClock = v.number; return true;
        case Key::FinalClock: a.finalClock = v.number; return true;
        case Key::SubsetStartFrame: a.subsetStart = {true, v.bound("frame")}; return true;
        case Key::SubsetEndFrame: a.subsetEnd = {true, v.bound("frame")}; return true;
        case Key::FrameStep: a.frameStep = v.atLeast(1, "a positive integer"); return true;
        case Key::CyclicAnimation: a.cyclic = v.flag; return true;
        default: return false;
    }
}

bool PovOptionReader::setAntialias(const Value& v) {
    PovAntialias& aa = o_.antialias;
    switch (v.info.key) {
        case Key::Antialias: aa.on = v.flag; break;
        case Key::AntialiasThreshold:
            if (v.number < 0) v.fail("0 or more");
            aa.threshold = v.number;
            break;
        case Key::AntialiasDepth: aa.depth = v.inRange(1, 9); break;
        case Key::AntialiasGamma:  // how colours are compared; does not itself choose the sampling
            if (!(v.number > 0)) v.fail("more than 0");
            aa.gamma = v.number;
            return true;
        case Key::SamplingMethod: aa.method = v.inRange(1, 2); break;
        case Key::Jitter: aa.jitter = v.flag; break;
        case Key::JitterAmount:
            aa.jitterAmount = v.number;
            if (v.number <= 0) aa.jitter = false;  // "If n.n <= 0 aa-jitter is set off"
            break;
        default: return false;
    }
    aa.given = true;
    return true;
}

bool PovOptionReader::setOutput(const Value& v) {
    const std::string& name = v.info.name;
    switch (v.info.key) {
        case Key::OutputFileName:
            if (v.text == "-") failAt(v.where, "writing the image to standard output (-) is not supported");
            o_.outputFile = v.text;
            o_.outputExact = false;
            return true;
        case Key::Width: o_.width = v.atLeast(1, "a positive integer"); return true;
        case Key::Height: o_.height = v.atLeast(1, "a positive integer"); return true;
        case Key::StartRow: o_.startRow = {true, v.bound("row")}; return true;
        case Key::EndRow: o_.endRow = {true, v.bound("row")}; return true;
        case Key::StartColumn: o_.startColumn = {true, v.bound("column")}; return true;
        case Key::EndColumn: o_.endColumn = {true, v.bound("column")}; return true;
        case Key::OutputToFile: o_.outputToFile = v.flag; return true;
        case Key::OutputFileType: setFileType(v); return true;
        case Key::OutputAlpha:
            if (v.flag) warnOnce(name, "Output_Alpha is not supported: the image has no alpha channel", v.where);
            return true;
        case Key::BitsPerColor: o_.bitsPerColor = int(v.inRange(1, 16)); return true;
        case Key::FileGamma: setFileGamma(v); return true;
        case Key::Compression:
            // POV-Ray: 0 or 1 mean its default quality 85; values outside 0..100 are clipped.
            o_.jpegQuality = v.integer <= 1 ? 85 : int(std::min(v.integer, 100L));
            return true;
        default: return false;
    }
}

void PovOptionReader::setFileType(const Value& v) {
    const char type = char(std::toupper(static_cast<unsigned char>(v.text[0])));
    if (type == 'E' || type == 'H')
        failAt(v.where, std::string(type == 'E' ? "OpenEXR" : "Radiance HDR") +
                            " output is not supported (Output_File_Type N, J, P, T, C, B or S)");
    if (std::string("NPTCJBS").find(type) == std::string::npos)
        failAt(v.where, "unknown Output_File_Type '" + v.text + "' (use N PNG, J JPEG, P PPM, T or C Targa, B BMP, S system)");
    o_.fileType = type;
    if (v.text.size() > 1) set("Bits_Per_Color", v.text.substr(1), v.where);  // +FN16: PNG, 16 bits per colour
}

// File_Gamma: sRGB (POV-Ray's default, 0 here) or a positive number.
void PovOptionReader::setFileGamma(const Value& v) {
    if (lower(v.text) == "srgb") {
        o_.fileGamma = 0;
        return;
    }
    char* end = nullptr;
    const double g = std::strtod(v.text.c_str(), &end);
    if (end == v.text.c_str() || *end != '\0' || !(g > 0) || !std::isfinite(g))
        failAt(v.where, "File_Gamma must be sRGB or a positive number, got '" + v.text + "'");
    o_.fileGamma = g;
}

void PovOptionReader::setDeclare(const Value& v) {
    const size_t eq = v.text.find('=');
    const std::string id = eq == std::string::npos ? v.text : trim(v.text.substr(0, eq));
    const std::string value = eq == std::string::npos ? std::string() : trim(v.text.substr(eq + 1));
    if (!isIdentifier(id) || !sdl::parseDeclareValue(value))
        failAt(v.where, "Declare needs NAME=VALUE with VALUE a number or a string in double quotes, got '" + v.text + "'");
    auto same = std::find_if(o_.declares.begin(), o_.declares.end(), [&](const sdl::Declare& d) { return d.name == id; });
    if (same != o_.declares.end()) same->value = value;  // a later declaration of the name wins
    else o_.declares.push_back({id, value});
}

void PovOptionReader::setOther(const Value& v) {
    switch (v.info.key) {
        case Key::InputFileName:
            o_.inputFile = resolveScene(v.text, v.where);
            break;
        case Key::LibraryPath: addLibraryPath(v.text); break;
        case Key::IncludeHeader: o_.includeHeader = v.text; break;
        case Key::Declare: setDeclare(v); break;
        case Key::Version:
            o_.version = std::max(1.0, v.number);  // POV-Ray 3.7 takes any number and reads 1.0 below 1 (measured)
            break;
        case Key::WorkThreads: o_.threads = v.inRange(0, 1024); break;
        case Key::ContinueTrace: o_.continueTrace = v.flag; break;
        case Key::Warned: {
            // Asking for nothing (off, false, 0) needs no warning.
            bool off = false;
            if (v.info.kind == Kind::Bool ? !v.flag : (parseBool(v.text, off) && !off)) break;
            warnOnce(v.info.name, std::string(v.info.name) + " is not acted on: " + v.info.unsupported, v.where);
            break;
        }
        default: break;  // Key::Quiet: checked, nothing to do
    }
}

void PovOptionReader::readIniFile(const std::string& path, const std::string& section, const std::string& from) {
    std::string name = extensionDot(path) != std::string::npos ? path : path + ".ini";  // ".ini is assumed" (tutorial 2.2.8.2)
    name = besideIni(name, iniStack_);
    const std::string origin = from.empty() ? std::string() : " (named " + from + ")";
    if (iniStack_.size() >= 10)
        throw Error("rays: error: " + name + ": INI files nested more than 10 deep" + origin);
    std::error_code ec;
    const FileText text(name, TextForm::Bytes, kMaxIniFileBytes);
    if (text.status() == FileText::Status::CannotOpen || fs::is_directory(name, ec))
        throw Error("rays: error: cannot open INI file '" + name + "'" + origin);
    if (text.status() == FileText::Status::CannotRead) throw Error("rays: error: cannot read INI file '" + name + "'" + origin);
    if (text.status() == FileText::Status::TooLarge)
        throw Error("rays: error: INI file '" + name + "' is larger than " + FileText::describe(kMaxIniFileBytes) + origin);
    iniBytesRead_ += text.text().size();
    if (++iniFilesRead_ > kMaxIniFilesRead || iniBytesRead_ > kMaxIniBytesRead)
        throw Error("rays: error: reading INI file '" + name + "' makes more than " + std::to_string(kMaxIniFilesRead) +
                    " INI files or " + FileText::describe(kMaxIniBytesRead) +
                    " of INI text read in all (do INI files name each other over and over?)" + origin);
    iniStack_.push_back(name);
    readIniText(std::string(text.text()), name, section);
    iniStack_.pop_back();
}

void PovOptionReader::readIniText(const std::string& text, const std::string& path, const std::string& section) {
    // POV-Ray 3.7 (observed) reads the unlabelled top part, then the parts labelled [section]; its
    // manual says a named section replaces the top part, but the program reads both.
    bool reading = true, found = false;
    std::string source = text;  // as scene files: a byte-order mark skipped, lone CRs end lines
    source.erase(0, makeSourceText(source.data(), source.size()));
    std::istringstream lines(source);
    int lineNo = 0;
    for (std::string raw; std::getline(lines, raw);) {
        ++lineNo;
        const Where where{path, lineNo, ""};
        const std::string line = trim(withoutComment(raw));
        if (line.empty()) continue;
        if (line[0] == '[') {
            const size_t close = line.find(']');
            if (close == std::string::npos) failAt(where, "section label without ']': '" + line + "'");
            reading = !section.empty() && lower(trim(line.substr(1, close - 1))) == lower(section);
            found = found || reading;
            continue;
        }
        if (!reading) continue;
        if (line[0] == '+' || line[0] == '-') {
            for (const std::string& word : switchWords(line)) {
                const Where at{path, lineNo, word};
                if (isPovSwitch(word)) {
                    readSwitch(word, at);
                } else if (isPovSetting(word)) {  // `+kc declare=fp=0` (animations/splinefollow.ini)
                    setKeyValue(word, at);
                } else {
                    warnOnce(word, "unknown option '" + word + "'", at);
                }
            }
        } else if (line.find('=') != std::string::npos) {
            setKeyValue(line, where);
        } else {
            std::string name, sub;
            splitSection(line, name, sub);
            readIniFile(unquote(name), sub, path + ":" + std::to_string(lineNo));
        }
    }
    if (!section.empty() && !found && warn_)
        warn_(path + ": warning: no section [" + section + "]; only the top part was read");
}

void PovOptionReader::setOutputExact(const std::string& path) {
    o_.outputFile = path;
    o_.outputExact = true;
    o_.outputToFile = true;  // naming a file asks for it
}

void PovOptionReader::setWidth(int width) { o_.width = width; }
void PovOptionReader::setHeight(int height) { o_.height = height; }

void PovOptionReader::setScene(const std::string& path) {
    o_.inputFile = path;
}

void PovOptionReader::setThreads(int threads) { o_.threads = threads; }

void PovOptionReader::addLibraryPath(const std::string& path) {
    std::string p = path;
    while (p.size() > 1 && p.back() == '/') p.pop_back();  // "no final path separator"
    // "If you specify the exact same path twice it is only counted once" (reference 3.2.5.4).
    if (std::find(o_.libraryPaths.begin(), o_.libraryPaths.end(), p) == o_.libraryPaths.end()) o_.libraryPaths.push_back(p);
}

void PovOptionReader::setResume(bool on) { o_.continueTrace = on; }

void PovOptionReader::setJpegQuality(int quality) { o_.jpegQuality = quality; }

void PovOptionReader::renderChoseAntialias() { o_.antialias.given = false; }

PovOptions readPovArguments(const std::vector<std::string>& args, PovOptionReader::Warn warn) {
    PovOptions o;
    PovOptionReader reader(o, std::move(warn));
    for (const std::string& a : args) reader.readArgument(a);
    return o;
}

}  // namespace rays::cli

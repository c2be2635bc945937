// Course conformance: runs every text and image case listed in
// ../shared/conformance/course/pN/tests.json against the `rays` binary and compares the result
// with the course's expected output (tolerances in ../shared/README.md). Without ../shared a
// single test skips. The environment variable RAYS_SHARED_DIR, when set, overrides the
// compiled-in shared directory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/image_compare.h"
#include "support/process.h"
#include "support/text_compare.h"

namespace fs = std::filesystem;
using namespace rays::test;

namespace { namespace RAYS_TEST_UNIT {

constexpr auto kCaseTimeout = std::chrono::seconds(120);

fs::path sharedDir() {
    const char* env = std::getenv("RAYS_SHARED_DIR");
    const fs::path p = (env && *env) ? fs::path(env) : fs::path(RAYS_SHARED_DIR);
    return p.lexically_normal();
}

fs::path courseDir() { return sharedDir() / "conformance" / "course"; }

bool readFile(const fs::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    text = ss.str();
    return true;
}

// One entry of tests.json.
struct CourseCase {
    std::string part;      // "p1"
    std::string name;      // "test1"
    std::string type;      // "text" or "image"
    bool required = true;
    fs::path dir;          // .../conformance/course/p1
};

// How gtest prints a case parameter ("p1/test1 (text, required)") instead of raw bytes.
void PrintTo(const CourseCase& c, std::ostream* os) {
    *os << c.part << "/" << c.name << " (" << c.type << ", " << (c.required ? "required" : "optional") << ")";
}

// Name printed by gtest for a case ("p1_test1"); only [A-Za-z0-9_].
std::string caseId(const CourseCase& c) {
    std::string id = c.part + "_" + c.name;
    for (char& ch : id)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return id;
}

// One object of tests.json.
struct JsonEntry {
    std::string name, type;
    bool required = true;
};

size_t skipSpace(const std::string& s, size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

// Reads `"key": value` pairs in s[begin, end); string values unescaped only for \" and \\.
std::vector<std::pair<std::string, std::string>> scanPairs(const std::string& s, size_t begin, size_t end) {
    std::vector<std::pair<std::string, std::string>> pairs;
    auto readString = [&](size_t& i, std::string& out) {
        ++i;  // opening quote
        while (i < end && s[i] != '"') {
            if (s[i] == '\\' && i + 1 < end) ++i;
            out.push_back(s[i++]);
        }
        ++i;  // closing quote
    };
    size_t i = begin;
    while (true) {
        i = skipSpace(s, i);
        while (i < end && s[i] != '"') ++i;
        if (i >= end) break;
        std::string key, value;
        readString(i, key);
        i = skipSpace(s, i);
        if (i >= end || s[i] != ':') continue;
        i = skipSpace(s, i + 1);
        if (i < end && s[i] == '"') {
            readString(i, value);
        } else {
            while (i < end && s[i] != ',' && !std::isspace(static_cast<unsigned char>(s[i]))) value.push_back(s[i++]);
        }
        pairs.emplace_back(key, value);
    }
    return pairs;
}

// Minimal scanner for the regular tests.json files (no JSON library): a list of flat objects
// with string "name"/"type" and boolean "required" (default true). Objects without a name are
// ignored.
std::vector<JsonEntry> parseTestsJson(const std::string& text) {
    std::vector<JsonEntry> entries;
    size_t pos = 0;
    while ((pos = text.find('{', pos)) != std::string::npos) {
        const size_t close = text.find('}', pos);
        if (close == std::string::npos) break;
        JsonEntry e;
        for (const auto& [key, value] : scanPairs(text, pos + 1, close)) {
            if (key == "name") e.name = value;
            else if (key == "type") e.type = value;
            else if (key == "required") e.required = value != "false";
        }
        if (!e.name.empty()) entries.push_back(e);
        pos = close + 1;
    }
    return entries;
}

// Problems found while listing cases (reported by CourseConformanceSuite.Found).
std::vector<std::string>& listingProblems() {
    static std::vector<std::string> problems;
    return problems;
}

std::vector<std::string>& listingNotes() {
    static std::vector<std::string> notes;
    return notes;
}

// All text/image cases of every course/pN directory with a tests.json, sorted by part.
std::vector<CourseCase> loadCases() {
    std::vector<CourseCase> cases;
    std::error_code ec;
    const fs::path root = courseDir();
    if (!fs::is_directory(root, ec)) return cases;
    std::vector<fs::path> parts;
    for (const auto& entry : fs::directory_iterator(root, ec))
        if (entry.is_directory(ec) && fs::exists(entry.path() / "tests.json", ec)) parts.push_back(entry.path());
    std::sort(parts.begin(), parts.end());
    for (const fs::path& dir : parts) {
        const std::string part = dir.filename().string();
        std::string json;
        if (!readFile(dir / "tests.json", json)) {
            listingProblems().push_back("cannot read " + (dir / "tests.json").string());
            continue;
        }
        const auto entries = parseTestsJson(json);
        if (entries.empty()) listingProblems().push_back("no entries found in " + (dir / "tests.json").string());
        std::set<std::string> listed;
        for (const JsonEntry& e : entries) {
            listed.insert(e.name);
            if (e.type != "text" && e.type != "image") continue;  // e.g. "additional"
            cases.push_back({part, e.name, e.type, e.required, dir});
        }
        // Cases with an .args file and an expected .out or .png but no tests.json entry (p3/test7)
        // are run as optional cases of the matching type.
        for (const auto& f : fs::directory_iterator(dir, ec)) {
            const std::string stem = f.path().stem().string();
            if (f.path().extension() != ".args" || listed.count(stem)) continue;
            if (fs::exists(dir / (stem + ".out"), ec)) {
                cases.push_back({part, stem, "text", false, dir});
            } else if (fs::exists(dir / (stem + ".png"), ec)) {
                cases.push_back({part, stem, "image", false, dir});
            } else {
                listingNotes().push_back(part + "/" + f.path().filename().string() +
                                         " has no expected output; not run");
            }
        }
    }
    return cases;
}

const std::vector<CourseCase>& allCases() {
    static const std::vector<CourseCase> cases = loadCases();
    return cases;
}

// Splits an .args line on whitespace and replaces every "../resources/X" by the absolute path
// of the course scene X.
std::vector<std::string> caseArgs(const std::string& line) {
    const std::string from = "../resources/";
    const std::string to = (sharedDir() / "scenes" / "course").string() + "/";
    std::vector<std::string> args;
    std::istringstream in(line);
    std::string tok;
    while (in >> tok) {
        for (size_t p = tok.find(from); p != std::string::npos; p = tok.find(from, p + to.size()))
            tok.replace(p, from.size(), to);
        args.push_back(tok);
    }
    return args;
}

std::string joinArgs(const std::vector<std::string>& args) {
    std::string s = RAYS_BINARY;
    for (const auto& a : args) s += " " + a;
    return s;
}

std::string cut(const std::string& s, size_t maxChars = 4000) {
    if (s.size() <= maxChars) return s;
    return s.substr(0, maxChars) + "\n... (" + std::to_string(s.size() - maxChars) + " more bytes)";
}

std::string streamsReport(const ProcessResult& r) {
    std::string s = "--- stdout ---\n" + (r.out.empty() ? std::string("(empty)\n") : cut(r.out));
    if (!s.empty() && s.back() != '\n') s += '\n';
    s += "--- stderr ---\n" + (r.err.empty() ? std::string("(empty)\n") : cut(r.err));
    if (!s.empty() && s.back() != '\n') s += '\n';
    return s;
}

class CourseConformance : public ::testing::TestWithParam<CourseCase> {};

TEST_P(CourseConformance, MatchesExpectedOutput) {
    const CourseCase& c = GetParam();
    const std::string label = c.part + "/" + c.name + " (" + c.type + ", " +
                              (c.required ? "required" : "optional") + ")";

    std::string argsLine;
    ASSERT_TRUE(readFile(c.dir / (c.name + ".args"), argsLine))
        << label << ": cannot read " << (c.dir / (c.name + ".args")).string();
    const std::vector<std::string> args = caseArgs(argsLine);
    ASSERT_FALSE(args.empty()) << label << ": empty " << c.name << ".args";

    TempDir tmp("rays-conf-" + caseId(c) + "-");
    ASSERT_FALSE(tmp.path().empty()) << label << ": cannot create a temporary directory";
    // On failure, keep the working directory if rays left anything in it (e.g. output.png).
    struct KeepOnFailure {
        TempDir& dir;
        ~KeepOnFailure() {
            std::error_code ec;
            if (::testing::Test::HasFailure() && !fs::is_empty(dir.path(), ec)) dir.keep();
        }
    } keepOnFailure{tmp};

    const std::string header = label + "\n  command: " + joinArgs(args) + "\n  working dir: " +
                               tmp.path().string() + " (kept on failure if not empty)\n";
    const ProcessResult r = runProcess(RAYS_BINARY, args, tmp.path().string(), kCaseTimeout);
    if (!r.ok())
        FAIL() << header << "  rays failed: " << r.summary() << (r.timedOut ? " after 120 s" : "") << "\n"
               << streamsReport(r);

    if (c.type == "text") {
        const fs::path expectedPath = c.dir / (c.name + ".out");
        std::string expected;
        ASSERT_TRUE(readFile(expectedPath, expected)) << header << "  cannot read " << expectedPath.string();
        const std::string mismatch = compareText(expected, r.out);
        if (!mismatch.empty())
            ADD_FAILURE() << header << "  stdout does not match " << expectedPath.string() << "\n"
                          << mismatch << "\n"
                          << "--- expected (" << c.name << ".out) ---\n"
                          << numberedText(expected) << "--- actual stdout ---\n"
                          << numberedText(cut(r.out, 20000))
                          << (r.err.empty() ? "" : "--- stderr ---\n" + cut(r.err));
        return;
    }

    // Image case.
    const fs::path expectedPath = c.dir / (c.name + ".png");
    const fs::path producedPath = tmp.path() / "output.png";
    std::error_code ec;
    if (!fs::exists(producedPath, ec))
        FAIL() << header << "  rays exited with status 0 but wrote no output.png in the working dir\n"
               << streamsReport(r);
    const RgbImage expected = loadPngRgb(expectedPath.string());
    if (!expected.ok()) FAIL() << header << "  " << expected.error;
    const RgbImage produced = loadPngRgb(producedPath.string());
    if (!produced.ok()) FAIL() << header << "  " << produced.error << " (working dir kept)";
    if (produced.width != expected.width || produced.height != expected.height)
        FAIL() << header << "  output.png is " << produced.width << "x" << produced.height << ", expected "
               << expected.width << "x" << expected.height << "\n  produced image: " << producedPath.string()
               << "\n  expected image: " << expectedPath.string();

    const ImageDiff diff = compareImages(expected, produced);
    std::cout << "[  figures ] " << c.part << "/" << c.name << ": " << diff.describe() << "\n";
    RecordProperty("fraction_over", std::to_string(diff.fractionOver));
    RecordProperty("mean_abs_255", std::to_string(diff.meanAbs * 255.0));
    if (diff.matches()) return;
    fs::copy_file(expectedPath, tmp.path() / "expected.png", fs::copy_options::overwrite_existing, ec);
    ADD_FAILURE() << header << "  image does not match: " << diff.describe() << "\n  produced image: "
                  << producedPath.string() << "\n  expected image: " << expectedPath.string()
                  << " (copied to " << (tmp.path() / "expected.png").string() << ")";
}

std::string caseName(const ::testing::TestParamInfo<CourseCase>& info) { return caseId(info.param); }

INSTANTIATE_TEST_SUITE_P(Course, CourseConformance, ::testing::ValuesIn(allCases()), caseName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CourseConformance);

// Always present: skips without ../shared, otherwise checks that the listing found cases.
TEST(CourseConformanceSuite, Found) {
    std::error_code ec;
    if (!fs::is_directory(courseDir(), ec)) GTEST_SKIP() << "../shared not found: course conformance skipped";
    for (const std::string& note : listingNotes()) std::cout << "[   note   ] " << note << "\n";
    for (const std::string& problem : listingProblems()) ADD_FAILURE() << problem;
    EXPECT_FALSE(allCases().empty()) << "no text/image cases found under " << courseDir().string();
}

}}  // namespace RAYS_TEST_UNIT, namespace

// POV-Ray's string functions, number formatting and datetime, checked against POV-Ray 3.7's own
// answers: tests/data/povray/pov_strings.pov wrote pov_strings.txt, pov_string_errors.sh wrote
// pov_string_errors.txt (cases that stop POV-Ray). Lines are FUNCTION|ARGUMENTS...|RESULT; numbers
// are texts POV-Ray turned into floats with val(), vectors are components joined by ';', and a
// result "!MESSAGE" is an error ("!abort": POV-Ray itself aborts, Rays reports an error).
#include "rays/sdl/pov_strings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "rays/sdl/pov_datetime.h"
#include "rays/sdl/pov_int.h"

using namespace rays::sdl;

namespace { namespace RAYS_TEST_UNIT {

const std::string kDir = std::string(RAYS_SOURCE_DIR) + "/tests/data/povray/";

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out(1);
    for (char c : s) {
        if (c == sep)
            out.emplace_back();
        else
            out.back() += c;
    }
    return out;
}

using Fields = std::vector<std::string>;

/// Every line of the measured files, grouped by function name.
std::map<std::string, std::vector<Fields>> measured() {
    std::map<std::string, std::vector<Fields>> out;
    for (const char* file : {"pov_strings.txt", "pov_string_errors.txt"}) {
        std::ifstream in(kDir + file);
        EXPECT_TRUE(in.good()) << kDir << file;
        std::string line;
        while (std::getline(in, line)) {
            Fields f = split(line, '|');
            const std::string fn = f.front();
            f.erase(f.begin());
            out[fn].push_back(f);
        }
    }
    return out;
}

const std::map<std::string, std::vector<Fields>>& cases() {
    static const auto all = measured();
    return all;
}

/// The cases of one function, each with its field count checked.
std::vector<Fields> casesOf(const std::string& fn, size_t fields) {
    const auto it = cases().find(fn);
    EXPECT_NE(it, cases().end()) << "no measured cases for " << fn;
    if (it == cases().end()) return {};
    for (const Fields& f : it->second) EXPECT_EQ(f.size(), fields) << fn << " " << f.front();
    return it->second;
}

std::string text(const Fields& f) {
    std::string s;
    for (const std::string& x : f) s += x + "|";
    return s;
}

double num(const std::string& s) { return povVal(povString(s)); }
int integer(const std::string& s) { return povInt(num(s)); }

std::vector<double> components(const std::string& s) {
    std::vector<double> out;
    for (const std::string& c : split(s, ';')) out.push_back(num(c));
    return out;
}

PovString codes(const std::string& s) {
    PovString out;
    for (const std::string& c : split(s, ';'))
        if (!c.empty()) out.push_back(char16_t(std::stoi(c)));
    return out;
}

std::string narrowOrError(const Outcome<PovString>& r) {
    return r.ok() ? povNarrow(r.value) : "!" + r.error;
}

/// Compares a Rays outcome with a measured result, "!abort" accepting any error.
void expectOutcome(const Outcome<PovString>& got, const Fields& f) {
    const std::string& want = f.back();
    if (want == "!abort")
        EXPECT_FALSE(got.ok()) << text(f);
    else
        EXPECT_EQ(narrowOrError(got), want) << text(f);
}

TEST(PovStrings, StrMatchesPovRay) {
    const auto all = casesOf("str", 4);
    EXPECT_GT(all.size(), 100u);
    for (const Fields& f : all) EXPECT_EQ(povStr(num(f[0]), integer(f[1]), integer(f[2])), f[3]) << text(f);
}

TEST(PovStrings, VstrMatchesPovRay) {
    const auto all = casesOf("vstr", 6);
    EXPECT_GT(all.size(), 35u);
    for (const Fields& f : all) {
        const std::vector<double> v = components(f[1]);
        expectOutcome(povVstr(integer(f[0]), v, povString(f[2]), integer(f[3]), integer(f[4])), f);
    }
}

TEST(PovStrings, ValMatchesPovRay) {
    const auto all = casesOf("val", 2);
    EXPECT_GT(all.size(), 50u);
    for (const Fields& f : all) EXPECT_EQ(povStr(povVal(povString(f[0])), 0, 20), f[1]) << text(f);
    for (const Fields& f : casesOf("valcodes", 2))
        EXPECT_EQ(povStr(povVal(codes(f[0])), 0, 3), f[1]) << text(f);
}

TEST(PovStrings, WriteOfFloatsAndVectorsMatchesPovRay) {
    for (const Fields& f : casesOf("write", 2)) EXPECT_EQ(povWriteFloat(num(f[0])), f[1]) << text(f);
    for (const Fields& f : casesOf("writevec", 2)) EXPECT_EQ(povWriteVector(components(f[0])), f[1]) << text(f);
}

TEST(PovStrings, ChrAscStrlenMatchPovRay) {
    for (const Fields& f : casesOf("chr", 2)) {
        const auto r = povChr(integer(f[0]));
        const std::string got =
            r.ok() ? std::to_string(povStrlen(r.value)) + ";" + std::to_string(povAsc(r.value)) : "!" + r.error;
        EXPECT_EQ(got, f[1]) << text(f);
    }
    for (const Fields& f : casesOf("asc", 2)) EXPECT_EQ(std::to_string(povAsc(povString(f[0]))), f[1]) << text(f);
    for (const Fields& f : casesOf("strlen", 2))
        EXPECT_EQ(std::to_string(povStrlen(povString(f[0]))), f[1]) << text(f);
}

TEST(PovStrings, CaseChangesAreAsciiOnly) {
    for (const Fields& f : casesOf("strupr", 2)) EXPECT_EQ(povNarrow(povStrupr(povString(f[0]))), f[1]) << text(f);
    for (const Fields& f : casesOf("strlwr", 2)) EXPECT_EQ(povNarrow(povStrlwr(povString(f[0]))), f[1]) << text(f);
    for (const Fields& f : casesOf("struprcode", 2))
        EXPECT_EQ(std::to_string(povAsc(povStrupr(codes(f[0])))), f[1]) << text(f);
    for (const Fields& f : casesOf("strlwrcode", 2))
        EXPECT_EQ(std::to_string(povAsc(povStrlwr(codes(f[0])))), f[1]) << text(f);
}

TEST(PovStrings, SubstrMatchesPovRayIncludingItsErrors) {
    const auto all = casesOf("substr", 4);
    EXPECT_GT(all.size(), 25u);
    for (const Fields& f : all) expectOutcome(povSubstr(povString(f[0]), integer(f[1]), integer(f[2])), f);
}

TEST(PovStrings, StrcmpAndConcatMatchPovRay) {
    for (const Fields& f : casesOf("strcmp", 3))
        EXPECT_EQ(std::to_string(povStrcmp(povString(f[0]), povString(f[1]))), f[2]) << text(f);
    for (const Fields& f : casesOf("strcmpcodes", 3))
        EXPECT_EQ(std::to_string(povStrcmp(codes(f[0]), codes(f[1]))), f[2]) << text(f);
    for (const Fields& f : casesOf("concat", 2)) {
        std::vector<PovString> parts;
        for (const std::string& p : split(f[0], ';')) parts.push_back(povString(p));
        EXPECT_EQ(povNarrow(povConcat(parts)), f[1]) << text(f);
    }
    // concat("a", chr(0), "b") has length 2: chr(0) is the empty string.
    const std::vector<PovString> withNul = {u"a", povChr(0).value, u"b"};
    EXPECT_EQ(std::to_string(povStrlen(povConcat(withNul))), casesOf("concatlen", 2).at(0)[1]);
}

TEST(PovStrings, DatetimeMatchesPovRay) {
    const auto all = casesOf("datetime", 3);
    EXPECT_GT(all.size(), 35u);
    for (const Fields& f : all) {
        const std::string fmt = f[1] == "(default)" ? std::string(kDatetimeDefaultFormat) : f[1];
        expectOutcome(povDatetime(num(f[0]), povString(fmt)), f);
    }
}

TEST(PovStrings, NonAsciiBytesAndCodesBecomeSpaces) {
    EXPECT_EQ(povString("a\xc3\xa9z"), u"a  z");  // é in UTF-8 is two bytes
    EXPECT_EQ(povString(std::string_view("ab\0c", 4)), u"ab");
    EXPECT_EQ(povNarrow(u"x\u00e9\u03c0\u007f"), "x  \x7f");
}

TEST(PovStrings, FloatToIntegerParameter) {
    EXPECT_EQ(povInt(2.9), 2);
    EXPECT_EQ(povInt(-2.9), -2);
    EXPECT_EQ(povInt(2147483647.9), 2147483647);
    EXPECT_EQ(povInt(-2147483648.9), -2147483647 - 1);
    EXPECT_EQ(povInt(2147483648.0), -2147483647 - 1);
    EXPECT_EQ(povInt(-1e300), -2147483647 - 1);
    EXPECT_EQ(povInt(std::nan("")), -2147483647 - 1);
}

TEST(PovStrings, NowCountsDaysFrom2000Utc) {
    const double unixSeconds = povNow() * 86400.0 + 946684800.0;
    EXPECT_NEAR(unixSeconds, double(std::time(nullptr)), 60.0);
}

}}  // namespace RAYS_TEST_UNIT, namespace

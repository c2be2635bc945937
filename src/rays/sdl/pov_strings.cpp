#include "rays/sdl/pov_strings.h"

#include <locale.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace rays::sdl {
namespace {

// printf's own rules give POV-Ray's digits (glibc: the exact binary value rounded half to even,
// "inf", "-nan", no zero padding for inf and nan). width ≥ 0; precision < 0 means C's default.
std::string printfNumber(char conversion, bool zeroPad, int width, int precision, double v) {
    const char* fmt = conversion == 'f' ? (zeroPad ? "%0*.*f" : "%*.*f") : (zeroPad ? "%0*.*g" : "%*.*g");
    const int n = std::snprintf(nullptr, 0, fmt, width, precision, v);
    if (n < 0) return {};
    std::string out(size_t(n) + 1, '\0');
    std::snprintf(out.data(), out.size(), fmt, width, precision, v);
    out.pop_back();
    return out;
}

// %g output stops changing once the precision exceeds the longest exact decimal expansion of a
// double (767 significant digits): trailing zeros are removed. Capping it keeps printf's work small.
constexpr int kGPrecisionCap = 1100;

PovString widen(const std::string& ascii) { return PovString(ascii.begin(), ascii.end()); }

locale_t cLocale() {
    static const locale_t c = newlocale(LC_NUMERIC_MASK, "C", locale_t(0));
    return c;
}

}  // namespace

PovString povString(std::string_view ascii) {
    PovString out;
    out.reserve(ascii.size());
    for (char c : ascii) {
        if (c == '\0') break;
        out.push_back(static_cast<unsigned char>(c) < 128 ? char16_t(c) : u' ');
    }
    return out;
}

std::string povNarrow(const PovString& s) {
    std::string out;
    out.reserve(s.size());
    for (char16_t c : s) out.push_back(c < 128 ? char(c) : ' ');
    return out;
}

// ---- numbers → text --------------------------------------------------------------------------

std::string povStr(double a, int minLen, int precision) {
    // Measured: a result of 255 characters or more is replaced, first by %g, then by "<invalid>";
    // any |L| over 254 (INT_MIN included) can only give "<invalid>".
    if (minLen < -kStrMaxLength || minLen > kStrMaxLength) return "<invalid>";
    const bool zeroPad = minLen < 0;
    const int width = zeroPad ? -minLen : minLen;
    if (precision <= kStrMaxLength) {  // a larger precision alone makes %f too long
        std::string f = printfNumber('f', zeroPad, width, precision, a);
        if (f.size() <= size_t(kStrMaxLength)) return f;
    }
    std::string g = printfNumber('g', zeroPad, width, std::min(precision, kGPrecisionCap), a);
    return g.size() <= size_t(kStrMaxLength) ? g : "<invalid>";
}

Outcome<PovString> povVstr(int dims, std::span<const double> given, const PovString& separator,
                           int minLen, int precision) {
    const int n = std::clamp(dims, 2, 5);
    std::array<double, 5> c{};
    std::copy_n(given.begin(), std::min<size_t>(given.size(), size_t(n)), c.begin());
    const auto tooLong = [] {
        return Outcome<PovString>::failure(
            "vstr: a formatted component would be longer than 767 characters (POV-Ray 3.7 aborts)");
    };
    PovString out;
    for (int i = 0; i < n; ++i) {
        if (i > 0) out += separator;
        if (minLen == INT_MIN) continue;  // measured: printf refuses the width, components are empty
        const int width = minLen < 0 ? -minLen : minLen;
        // A width or precision this large can only give too long a component.
        if (width > kVstrMaxComponentLength || precision > kVstrMaxComponentLength - 2) return tooLong();
        const std::string s = printfNumber('f', minLen < 0, width, precision, c[size_t(i)]);
        if (s.size() > size_t(kVstrMaxComponentLength)) return tooLong();
        out += widen(s);
    }
    return {out, {}};
}

std::string povWriteFloat(double v) { return printfNumber('g', false, 0, -1, v); }

std::string povWriteVector(std::span<const double> components) {
    std::string out = "<";
    for (size_t i = 0; i < components.size(); ++i) {
        if (i > 0) out += ',';
        out += povWriteFloat(components[i]);
    }
    return out + "> ";
}

// ---- text → numbers --------------------------------------------------------------------------

double povVal(const PovString& s) {
    const std::string text = povNarrow(s);
    return strtod_l(text.c_str(), nullptr, cLocale());
}

int povAsc(const PovString& s) { return s.empty() ? 0 : int(s[0]); }

int povStrlen(const PovString& s) { return int(s.size()); }

int povStrcmp(const PovString& a, const PovString& b) {
    const size_t n = std::max(a.size(), b.size());
    for (size_t i = 0; i < n; ++i) {
        const int ca = i < a.size() ? int(a[i]) : 0;
        const int cb = i < b.size() ? int(b[i]) : 0;
        if (ca != cb) return ca - cb;
    }
    return 0;
}

// ---- strings → strings -----------------------------------------------------------------------

Outcome<PovString> povChr(int code) {
    if (code < 0 || code > 65535)
        return Outcome<PovString>::failure("Value " + std::to_string(code) + " cannot be used in chr(...).");
    if (code == 0) return {};
    return {PovString(1, char16_t(code)), {}};
}

Outcome<PovString> povSubstr(const PovString& s, int pos, int len) {
    if (pos < 0 || len < 0 || int64_t(pos) + len - 1 > int64_t(s.size()))
        return Outcome<PovString>::failure("Illegal parameters in substr.");
    if (pos == 0) return {};  // measured: substr("ABC", 0, L) is "" for every valid L
    return {s.substr(size_t(pos) - 1, size_t(len)), {}};
}

PovString povStrupr(PovString s) {
    for (char16_t& c : s)
        if (c >= u'a' && c <= u'z') c = char16_t(c - u'a' + u'A');
    return s;
}

PovString povStrlwr(PovString s) {
    for (char16_t& c : s)
        if (c >= u'A' && c <= u'Z') c = char16_t(c - u'A' + u'a');
    return s;
}

PovString povConcat(std::span<const PovString> parts) {
    PovString out;
    for (const PovString& p : parts) out += p;
    return out;
}

}  // namespace rays::sdl

#include "rays/sdl/pov_strings.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace rays::sdl {

Outcome<std::string> povStr(double v, int minLen, int precision) {
    char fmt[32];
    const int width = minLen < 0 ? -minLen : minLen;
    if (width > 1000) return Outcome<std::string>::failure("str: length out of range");
    if (precision < 0) std::snprintf(fmt, sizeof fmt, minLen < 0 ? "%%0%df" : "%%%df", width);
    else std::snprintf(fmt, sizeof fmt, minLen < 0 ? "%%0%d.%df" : "%%%d.%df", width, precision > 60 ? 60 : precision);
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, v);
    return {buf, {}};
}

Outcome<std::string> povVstr(int n, const double* comps, int dim, const std::string& sep, int minLen, int precision) {
    n = n < 2 ? 2 : n > 5 ? 5 : n;
    if (dim > n && dim > 1) return Outcome<std::string>::failure("Vector dimension is larger than the number of components to print.");
    std::string out;
    for (int i = 0; i < n; ++i) {
        const double c = dim == 1 ? comps[0] : (i < dim ? comps[i] : 0.0);
        Outcome<std::string> s = povStr(c, minLen, precision);
        if (!s.ok()) return s;
        if (i) out += sep;
        out += s.value;
    }
    return {out, {}};
}

Outcome<std::string> povChr(int code) {
    if (code < 0 || code > 127) return Outcome<std::string>::failure("chr: value " + std::to_string(code) + " cannot be used");
    return {std::string(1, char(code)), {}};
}

Outcome<std::string> povSubstr(const std::string& s, int pos, int len) {
    if (pos < 1 || len < 0 || size_t(pos - 1) + size_t(len) > s.size())
        return Outcome<std::string>::failure("Illegal parameters in substr.");
    return {s.substr(size_t(pos - 1), size_t(len)), {}};
}

Outcome<std::string> povDatetime(double days, const std::string& format) {
    const std::time_t t = std::time_t(946684800.0 + days * 86400.0);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[256];
    const size_t n = std::strftime(buf, sizeof buf, format.c_str(), &tm);
    return {std::string(buf, n), {}};
}

double povVal(std::string_view s) {
    const std::string copy(s);
    return std::strtod(copy.c_str(), nullptr);
}

}  // namespace rays::sdl

#include "flag_values.h"

#include <charconv>
#include <cmath>

#include "rays/error.h"

namespace rays::cli {

std::optional<double> finiteNumber(const std::string& text) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    if (begin != end && *begin == '+') ++begin;  // "+2" as strtod reads it; from_chars takes no '+'
    if (begin == end || (text[0] == '+' && (*begin == '+' || *begin == '-'))) return std::nullopt;
    double v = 0;
    const auto [p, ec] = std::from_chars(begin, end, v, std::chars_format::general);
    if (ec != std::errc() || p != end || !std::isfinite(v)) return std::nullopt;
    return v;
}

double flagNumber(const std::string& text, const char* flag) {
    if (const std::optional<double> v = finiteNumber(text)) return *v;
    throw Error(std::string("rays: error: ") + flag + ": expected a finite number, got '" + text + "'");
}

CLI::Validator finiteNumberCheck() {
    return CLI::Validator(
        [](std::string& in) -> std::string {
            return finiteNumber(in) ? std::string() : "expected a finite number, got '" + in + "'";
        },
        "NUMBER");
}

CLI::Validator unsigned64Check() {
    return CLI::Validator(
        [](std::string& in) -> std::string {
            const bool digits = !in.empty() && in.find_first_not_of("0123456789") == std::string::npos;
            uint64_t v = 0;
            const auto [p, ec] = std::from_chars(in.data(), in.data() + in.size(), v);
            if (!digits || ec != std::errc() || p != in.data() + in.size())
                return "must be a whole number from 0 to 18446744073709551615 (2^64 - 1), got '" + in + "'";
            return {};
        },
        "UINT64");
}

Vec3 flagColour(const std::string& text, const char* flag) {
    double c[3] = {0, 0, 0};
    size_t start = 0;
    int n = 0;
    for (; n < 3 && start <= text.size(); ++n) {
        const size_t comma = text.find(',', start);
        const std::optional<double> v = finiteNumber(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (!v || *v < 0 || *v > 1) break;
        c[n] = *v;
        if (comma == std::string::npos) {
            ++n;
            start = std::string::npos;
            break;
        }
        start = comma + 1;
    }
    if (n != 3 || start != std::string::npos)
        throw Error(std::string("rays: error: ") + flag + " takes R,G,B (three numbers from 0 to 1), got '" + text + "'");
    return {c[0], c[1], c[2]};
}

}  // namespace rays::cli

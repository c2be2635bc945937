#include "rays/sdl/pov_datetime.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <string>

namespace rays::sdl {
namespace {

constexpr int64_t kSecondsPerDay = 86400;
constexpr int64_t kEpoch2000 = 10957;  // days from 1970-01-01 to 2000-01-01
// The range POV-Ray accepts (measured: datetime(-219145) is 1400-01-01, datetime(2921940) fails).
constexpr int64_t kFirstDay = -219145, kEndDay = 2921940;  // days from 2000-01-01
constexpr size_t kBufferSize = 200;                        // measured: 199 characters fit

struct Civil {
    int64_t year;
    int month, day;  // 1-based
};

// Proleptic Gregorian date of a day number counted from 1970-01-01 (Howard Hinnant,
// "chrono-Compatible Low-Level Date Algorithms", civil_from_days).
Civil civilFromDays(int64_t z) {
    z += 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t doe = z - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    const int d = int(doy - (153 * mp + 2) / 5 + 1);
    const int m = int(mp < 10 ? mp + 3 : mp - 9);
    return {yoe + era * 400 + (m <= 2), m, d};
}

// Day number from 1970-01-01 of a proleptic Gregorian date (same source, days_from_civil).
int64_t daysFromCivil(int64_t y, int m, int d) {
    y -= m <= 2;
    const int64_t era = (y >= 0 ? y : y - 399) / 400;
    const int64_t yoe = y - era * 400;
    const int64_t doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
    const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

int64_t floorDiv(int64_t a, int64_t b) { return a / b - (a % b != 0 && (a < 0) != (b < 0)); }
int64_t floorMod(int64_t a, int64_t b) { return a - floorDiv(a, b) * b; }

// The broken-down UTC time of a second counted from 1970-01-01; tm_isdst = −1 as POV-Ray's
// (measured: %Z and %z print nothing, which is what strftime does for an unknown DST state).
std::tm brokenDown(int64_t second) {
    const int64_t day = floorDiv(second, kSecondsPerDay);
    const int64_t inDay = second - day * kSecondsPerDay;
    const Civil c = civilFromDays(day);
    std::tm t{};
    t.tm_year = int(c.year - 1900);
    t.tm_mon = c.month - 1;
    t.tm_mday = c.day;
    t.tm_hour = int(inDay / 3600);
    t.tm_min = int(inDay / 60 % 60);
    t.tm_sec = int(inDay % 60);
    t.tm_wday = int(floorMod(day + 4, 7));  // 1970-01-01 was a Thursday
    t.tm_yday = int(day - daysFromCivil(c.year, 1, 1));
    t.tm_isdst = -1;
    return t;
}

}  // namespace

double povNow() {
    using namespace std::chrono;
    const double sinceUnix = duration<double>(system_clock::now().time_since_epoch()).count();
    return sinceUnix / double(kSecondsPerDay) - double(kEpoch2000);
}

Outcome<PovString> povDatetime(double days, const PovString& format) {
    if (format.empty()) return Outcome<PovString>::failure("Empty format string.");
    // Nearest second. POV-Ray's own arithmetic decides exact half seconds within about 1e-7 s
    // either way (measured: 2.5 s gives 2, 3.5 s gives 4); floor(x + 0.5) is the documented
    // "nearest" and agrees everywhere else.
    const double second = std::floor(days * double(kSecondsPerDay) + 0.5);
    if (!(second >= double(kFirstDay * kSecondsPerDay) && second < double(kEndDay * kSecondsPerDay)))
        return Outcome<PovString>::failure("Year is out of valid range: 1400..9999");
    const std::tm t = brokenDown(int64_t(second) + kEpoch2000 * kSecondsPerDay);
    std::array<char, kBufferSize> buf{};
    const std::string fmt = povNarrow(format);
    const size_t n = std::strftime(buf.data(), buf.size(), fmt.c_str(), &t);
    if (n == 0)
        return Outcome<PovString>::failure(
            "Invalid formatting code in format string, or resulting string too long.");
    return {povString(std::string_view(buf.data(), n)), {}};
}

}  // namespace rays::sdl

#include "rays/pattern/tiles.h"

#include <cmath>

namespace rays::pattern {
namespace {

// a mod 3 in {0, 1, 2} for any integer-valued a.
int mod3(double a) { return int(a - 3 * std::floor(a / 3)); }

bool isOdd(double a) { return std::fmod(std::fabs(a), 2.0) == 1.0; }

constexpr double kRowDepth = 0.86602540378443865;  // √3/2

}  // namespace

int squareIndex(Vec3 p) {
    const bool oddX = isOdd(std::floor(p.x)), oddZ = isOdd(std::floor(p.z));
    return oddX ? (oddZ ? 2 : 3) : (oddZ ? 1 : 0);
}

int triangularIndex(Vec3 p) {
    // Measured: in an even row the upward triangle with base [k, k + 1] takes entry {0, 4, 2}[k mod 3]
    // and the downward one whose apex is at x = k (on the row's lower edge) {1, 3, 5}[k mod 3]; odd
    // rows are shifted half a unit and one triangle along.
    static constexpr int kUp[3] = {0, 4, 2}, kDown[3] = {1, 3, 5};
    const double row = std::floor(p.z / kRowDepth);
    const double t = p.z / kRowDepth - row;  // height within the row, 0 at its lower edge
    const bool odd = isOdd(row);
    const double x = odd ? p.x - 0.5 : p.x;
    const double k = std::floor(x);
    const double f = x - k;
    const double slot = odd ? k - 1 : k;
    if (f < t / 2) return kDown[mod3(slot)];
    if (f > 1 - t / 2) return kDown[mod3(slot + 1)];
    return kUp[mod3(slot)];
}

int cubicIndex(Vec3 p) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (ax >= ay && ax >= az) return p.x >= 0 ? 0 : 3;
    if (ay >= az) return p.y >= 0 ? 1 : 4;
    return p.z >= 0 ? 2 : 5;
}

}  // namespace rays::pattern

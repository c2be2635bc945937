#include "rays/pattern/density_file.h"

#include <cmath>

namespace rays::pattern {

namespace {

uint32_t bigEndian(const std::string& b, size_t at, int bytes) {
    uint32_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | uint8_t(b[at + size_t(i)]);
    return v;
}

// Catmull-Rom's weights of the four samples around t ∈ [0, 1).
void catmullRom(double t, double w[4]) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2 * t2 - t);
    w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
    w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
}

int wrapIndex(int i, int n) {
    i %= n;
    return i < 0 ? i + n : i;
}

}  // namespace

bool readDf3(const std::string& bytes, DensityGrid& grid, std::string& why) {
    if (bytes.size() < 6) {
        why = "a DF3 file starts with three 16-bit sizes, this one has " + std::to_string(bytes.size()) + " bytes";
        return false;
    }
    const int nx = int(bigEndian(bytes, 0, 2)), ny = int(bigEndian(bytes, 2, 2)), nz = int(bigEndian(bytes, 4, 2));
    const uint64_t count = uint64_t(nx) * uint64_t(ny) * uint64_t(nz);
    if (count == 0) {
        why = "a DF3 size is 0 (" + std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz) + ")";
        return false;
    }
    if (count > kMaxDensityValues) {
        why = "the DF3 grid has " + std::to_string(count) + " values, more than the limit of " +
              std::to_string(kMaxDensityValues);
        return false;
    }
    const uint64_t data = bytes.size() - 6;
    int size = 0;
    for (int s : {1, 2, 4})
        if (data >= count * uint64_t(s)) size = s;
    if (size == 0) {
        why = "the DF3 file holds " + std::to_string(data) + " bytes of values for a " + std::to_string(nx) + "x" +
              std::to_string(ny) + "x" + std::to_string(nz) + " grid";
        return false;
    }
    const double scale = 1.0 / double(size == 1 ? 255u : size == 2 ? 65535u : 4294967295u);
    grid.nx = nx, grid.ny = ny, grid.nz = nz;
    grid.values.resize(size_t(count));
    for (size_t i = 0; i < size_t(count); ++i) grid.values[i] = float(bigEndian(bytes, 6 + i * size_t(size), size) * scale);
    return true;
}

double DensityGrid::at(Vec3 p, int interpolate) const {
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1) || values.empty()) return 0;
    const double f[3] = {p.x * nx, p.y * ny, p.z * nz};
    const int n[3] = {nx, ny, nz};
    int i[3];
    double t[3];
    for (int a = 0; a < 3; ++a) {
        i[a] = std::min(int(std::floor(f[a])), n[a] - 1);
        t[a] = f[a] - i[a];
    }
    auto voxel = [&](int x, int y, int z) {
        return double(values[(size_t(wrapIndex(z, nz)) * size_t(ny) + size_t(wrapIndex(y, ny))) * size_t(nx) +
                             size_t(wrapIndex(x, nx))]);
    };
    if (interpolate == 1) {
        double sum = 0;
        for (int c = 0; c < 8; ++c) {
            const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
            const double w = (dx ? t[0] : 1 - t[0]) * (dy ? t[1] : 1 - t[1]) * (dz ? t[2] : 1 - t[2]);
            if (w != 0) sum += w * voxel(i[0] + dx, i[1] + dy, i[2] + dz);
        }
        return sum;
    }
    if (interpolate == 2) {
        double w[3][4];
        for (int a = 0; a < 3; ++a) catmullRom(t[a], w[a]);
        double sum = 0;
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                    sum += w[0][a] * w[1][b] * w[2][c] * voxel(i[0] + a - 1, i[1] + b - 1, i[2] + c - 1);
        return sum;
    }
    return voxel(i[0], i[1], i[2]);
}

}  // namespace rays::pattern

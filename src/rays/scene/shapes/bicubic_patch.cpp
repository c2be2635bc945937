#include "rays/scene/shapes/bicubic_patch.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rays {

namespace {

using PatchNet = std::array<Vec3, 16>;  // [t row][s column], row-major

void bernstein3(double x, double b[4], double d[4]) {
    const double y = 1 - x;
    b[0] = y * y * y, b[1] = 3 * x * y * y, b[2] = 3 * x * x * y, b[3] = x * x * x;
    d[0] = -3 * y * y, d[1] = 3 * y * y - 6 * x * y, d[2] = 6 * x * y - 3 * x * x, d[3] = 3 * x * x;
}

// Point and partial derivatives of the patch at (s, t).
void patchFrame(const Vec3* q, double s, double t, Vec3& p, Vec3& ds, Vec3& dt) {
    double bs[4], dbs[4], bt[4], dbt[4];
    bernstein3(s, bs, dbs);
    bernstein3(t, bt, dbt);
    p = ds = dt = Vec3{};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const Vec3 c = q[j * 4 + i];
            p += bs[i] * bt[j] * c;
            ds += dbs[i] * bt[j] * c;
            dt += bs[i] * dbt[j] * c;
        }
}

Vec3 patchNormal(const Vec3* q, double s, double t) {
    Vec3 p, ds, dt;
    patchFrame(q, s, t, p, ds, dt);
    Vec3 n = cross(ds, dt);
    if (length(n) < 1e-12 * (1 + dot(ds, ds) + dot(dt, dt))) {  // a collapsed edge: look just inside
        patchFrame(q, s + (0.5 - s) * 1e-4, t + (0.5 - t) * 1e-4, p, ds, dt);
        n = cross(ds, dt);
    }
    return n;
}

// The control net of the part [a, b] of a cubic Bézier (blossoming: P(a,a,a), P(a,a,b), P(a,b,b), P(b,b,b)).
void bezierPart(const Vec3 c[4], double a, double b, Vec3 out[4]) {
    auto blossom = [&](double x, double y, double z) {
        Vec3 l[3] = {(1 - x) * c[0] + x * c[1], (1 - x) * c[1] + x * c[2], (1 - x) * c[2] + x * c[3]};
        Vec3 m[2] = {(1 - y) * l[0] + y * l[1], (1 - y) * l[1] + y * l[2]};
        return (1 - z) * m[0] + z * m[1];
    };
    out[0] = blossom(a, a, a), out[1] = blossom(a, a, b), out[2] = blossom(a, b, b), out[3] = blossom(b, b, b);
}

PatchNet subNet(const Vec3* q, double s0, double s1, double t0, double t1) {
    PatchNet rows, out;
    for (int j = 0; j < 4; ++j) bezierPart(q + j * 4, s0, s1, &rows[size_t(j * 4)]);
    for (int i = 0; i < 4; ++i) {
        const Vec3 col[4] = {rows[size_t(i)], rows[size_t(4 + i)], rows[size_t(8 + i)], rows[size_t(12 + i)]};
        Vec3 part[4];
        bezierPart(col, t0, t1, part);
        for (int j = 0; j < 4; ++j) out[size_t(j * 4 + i)] = part[j];
    }
    return out;
}

// The largest distance of the net's points from the bilinear surface of its corners.
double netBend(const PatchNet& n) {
    double worst = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const double a = i / 3.0, b = j / 3.0;
            const Vec3 bl = (1 - a) * (1 - b) * n[0] + a * (1 - b) * n[3] + (1 - a) * b * n[12] + a * b * n[15];
            worst = std::max(worst, length(n[size_t(j * 4 + i)] - bl));
        }
    return worst;
}

struct PatchOut {
    const BicubicPatch& patch;
    Mesh& mesh;
    void corner(double s, double t) {
        const Vec3 p = bicubicPoint(patch, s, t);
        Vec3 n = patchNormal(patch.points, s, t);  // unit: the mesh interpolates them as they are
        if (length(n) > 0) n = normalize(n);
        mesh.positions.insert(mesh.positions.end(), {float(p.x), float(p.y), float(p.z)});
        mesh.normals.insert(mesh.normals.end(), {float(n.x), float(n.y), float(n.z)});
        const double* c = patch.uv;  // bilinear between the corners' uv
        const double u = (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[2] + s * t * c[4] + (1 - s) * t * c[6];
        const double v = (1 - s) * (1 - t) * c[1] + s * (1 - t) * c[3] + s * t * c[5] + (1 - s) * t * c[7];
        mesh.uvs.insert(mesh.uvs.end(), {float(u), float(v)});
    }
    // All pieces of the s × t grid 2^sLevel × 2^tLevel, sharing their corners.
    void grid(int sLevel, int tLevel) {
        const uint32_t ns = 1u << sLevel, nt = 1u << tLevel;
        for (uint32_t j = 0; j <= nt; ++j)
            for (uint32_t i = 0; i <= ns; ++i) corner(double(i) / ns, double(j) / nt);
        for (uint32_t j = 0; j < nt; ++j)
            for (uint32_t i = 0; i < ns; ++i) {
                const uint32_t k = j * (ns + 1) + i, up = k + ns + 1;  // (s0, t0), its (s0, t1)
                for (uint32_t v : {k, k + 1, up + 1, k, up + 1, up}) {
                    mesh.indices.push_back(v);
                    mesh.normalIndices.push_back(v);
                    mesh.uvIndices.push_back(v);
                }
            }
    }
    // Whether every piece of that grid is flat within `flatness`.
    bool flatAt(int sLevel, int tLevel) const {
        const int ns = 1 << sLevel, nt = 1 << tLevel;
        for (int j = 0; j < nt; ++j)
            for (int i = 0; i < ns; ++i)
                if (netBend(subNet(patch.points, double(i) / ns, double(i + 1) / ns, double(j) / nt, double(j + 1) / nt)) >
                    patch.flatness)
                    return false;
        return true;
    }
};

}  // namespace

Vec3 bicubicPoint(const BicubicPatch& p, double s, double t) {
    Vec3 q, ds, dt;
    patchFrame(p.points, s, t, q, ds, dt);
    return q;
}

void tessellateBicubicPatch(const BicubicPatch& p, Mesh& mesh) {
    // The whole patch is cut evenly, one level more in each direction (up to its steps) until every
    // piece is flat: flatness 0.1 stops objects/bezier.pov's patch at 8 × 8 pieces and 0.01 at its
    // 16 × 16 steps, as POV-Ray does; a piece-by-piece test stopped its middle pieces a level early.
    PatchOut out{p, mesh};
    const int sMax = std::clamp(p.vSteps, 0, 10), tMax = std::clamp(p.uSteps, 0, 10);
    int level = 0;
    while ((level < sMax || level < tMax) && !(p.flatness > 0 && out.flatAt(std::min(level, sMax), std::min(level, tMax))))
        ++level;
    out.grid(std::min(level, sMax), std::min(level, tMax));
}

}  // namespace rays

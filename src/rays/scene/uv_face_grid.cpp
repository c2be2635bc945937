#include "rays/scene/uv_face_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rays {

namespace {

constexpr int kMaxSide = 1024;            // cells across at most
constexpr size_t kEntriesPerFace = 16;    // listed faces per face at most (else a coarser grid)
constexpr size_t kEntriesSlack = 1 << 16;

// Twice the signed uv area of face t (u0 v0 u1 v1 u2 v2).
double area2(const double* t) { return (t[2] - t[0]) * (t[5] - t[1]) - (t[3] - t[1]) * (t[4] - t[0]); }

// Where x lies against the edge p → q (its doubled signed area with them), computed from the edge's
// lexicographically smaller end so that two faces sharing an edge get the same number for it,
// negated: a point on or near a shared edge is inside one of them whatever the rounding, and a
// grid of faces has no holes along its edges. (POV-Ray 3.7.0.10 has none either; and it leaves
// out a point that rounding puts a hair outside an edge no other face shares, measured: the uv
// (1/3, 2/3) is outside the face (0,0), (0,1), (1,0) on a 3×3 image, as here.)
double edgeSide(double pu, double pv, double qu, double qv, double xu, double xv) {
    if (pu > qu || (pu == qu && pv > qv)) return -((pu - qu) * (xv - qv) - (pv - qv) * (xu - qu));
    return (qu - pu) * (xv - pv) - (qv - pv) * (xu - pu);
}

bool usable(const double* t) {
    for (int k = 0; k < 6; ++k)
        if (!std::isfinite(t[k])) return false;
    const double a = area2(t);
    return a != 0 && std::isfinite(a);
}

}  // namespace

UvFaceGrid::UvFaceGrid(std::vector<double> uvs) : uv_(std::move(uvs)) {
    const size_t n = faceCount();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
    for (size_t f = 0; f < n; ++f) {
        const double* t = &uv_[6 * f];
        if (!usable(t)) continue;
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 2; ++a) {
                lo[a] = std::min(lo[a], t[2 * k + a]);
                hi[a] = std::max(hi[a], t[2 * k + a]);
            }
    }
    if (!(lo[0] < hi[0] && lo[1] < hi[1])) return;  // no face with uv area: nothing is ever found
    u0_ = lo[0];
    v0_ = lo[1];
    int side = std::clamp(int(std::ceil(std::sqrt(double(n)))), 1, kMaxSide);
    // A few faces spanning many cells could list far more entries than there are faces: coarser then.
    for (;;) {
        nu_ = nv_ = side;
        scaleU_ = nu_ / (hi[0] - lo[0]);
        scaleV_ = nv_ / (hi[1] - lo[1]);
        size_t entries = 0;
        for (size_t f = 0; f < n; ++f) {
            int i0, i1, j0, j1;
            if (cellRange(f, i0, i1, j0, j1)) entries += size_t(i1 - i0 + 1) * size_t(j1 - j0 + 1);
        }
        if (side == 1 || entries <= kEntriesPerFace * n + kEntriesSlack) break;
        side /= 2;
    }
    cellStart_.assign(size_t(nu_) * size_t(nv_) + 1, 0);
    for (size_t f = 0; f < n; ++f) {
        int i0, i1, j0, j1;
        if (!cellRange(f, i0, i1, j0, j1)) continue;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) ++cellStart_[size_t(j) * size_t(nu_) + size_t(i) + 1];
    }
    for (size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    cellFaces_.resize(cellStart_.back());
    std::vector<uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (size_t f = 0; f < n; ++f) {  // in face order: each cell's list ascends
        int i0, i1, j0, j1;
        if (!cellRange(f, i0, i1, j0, j1)) continue;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) cellFaces_[fill[size_t(j) * size_t(nu_) + size_t(i)]++] = uint32_t(f);
    }
}

int UvFaceGrid::cellU(double u) const {
    return int(std::clamp(std::floor((u - u0_) * scaleU_), 0.0, double(nu_ - 1)));
}

int UvFaceGrid::cellV(double v) const {
    return int(std::clamp(std::floor((v - v0_) * scaleV_), 0.0, double(nv_ - 1)));
}

bool UvFaceGrid::cellRange(size_t face, int& i0, int& i1, int& j0, int& j1) const {
    const double* t = &uv_[6 * face];
    if (!usable(t)) return false;
    i0 = cellU(std::min({t[0], t[2], t[4]}));
    i1 = cellU(std::max({t[0], t[2], t[4]}));
    j0 = cellV(std::min({t[1], t[3], t[5]}));
    j1 = cellV(std::max({t[1], t[3], t[5]}));
    return true;
}

int64_t UvFaceGrid::find(double u, double v, double w[3]) const {
    if (nu_ == 0 || !std::isfinite(u) || !std::isfinite(v)) return -1;
    const size_t cell = size_t(cellV(v)) * size_t(nu_) + size_t(cellU(u));
    for (uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
        const uint32_t f = cellFaces_[k];
        const double* t = &uv_[6 * size_t(f)];
        // Each corner's weight is the side of the opposite edge; all of the face's sign: inside.
        const double e0 = edgeSide(t[2], t[3], t[4], t[5], u, v), e1 = edgeSide(t[4], t[5], t[0], t[1], u, v),
                     e2 = edgeSide(t[0], t[1], t[2], t[3], u, v);
        const bool inside = area2(t) > 0 ? e0 >= 0 && e1 >= 0 && e2 >= 0 : e0 <= 0 && e1 <= 0 && e2 <= 0;
        if (!inside) continue;
        const double sum = e0 + e1 + e2;  // the face's doubled area, up to rounding
        w[0] = e0 / sum;
        w[1] = e1 / sum;
        w[2] = e2 / sum;
        return f;
    }
    return -1;
}

size_t UvFaceGrid::memoryBytes() const {
    return uv_.capacity() * sizeof(double) + (cellStart_.capacity() + cellFaces_.capacity()) * sizeof(uint32_t);
}

}  // namespace rays

#include "rays/render/irradiance_cache.h"

#include <algorithm>
#include <cmath>

#include "rays/render/sampler.h"

namespace rays {

IrradianceBlend::IrradianceBlend(Vec3 P, Vec3 N, int level, double errorBound, int nearestCount)
    : P_(P), N_(N), level_(level), a_(errorBound), invA_(1.0 / errorBound),
      nearest_(std::clamp(nearestCount, 1, kMaxNearest)) {}

void IrradianceBlend::consider(const IrradianceRecord& r) {
    if (r.level != level_) return;
    const Vec3 d = P_ - r.P;
    const double reach = a_ * r.R;  // ε ≥ |d|/R: no square root for records out of reach
    if (dot(d, d) >= reach * reach) return;
    // A record in front of the point sees other surroundings (Ward et al. 1988: d·(N + Nᵢ)/2 < 0).
    if (dot(d, N_ + r.N) < -0.1 * r.R) return;
    const double eps = length(d) / r.R + std::sqrt(std::max(0.0, 1.0 - dot(N_, r.N)));
    if (!(eps < a_)) return;
    const double w = 1.0 / std::max(eps, 1e-6) - invA_;
    // Keep the nearest_ largest weights (insertion into a short sorted array).
    int i = count_;
    if (count_ == nearest_) {
        if (weight_[nearest_ - 1] >= w) return;
        i = nearest_ - 1;  // replaces the smallest
    } else {
        ++count_;
    }
    while (i > 0 && weight_[i - 1] < w) {
        weight_[i] = weight_[i - 1];
        E_[i] = E_[i - 1];
        --i;
    }
    weight_[i] = w;
    E_[i] = r.E;
}

bool IrradianceBlend::result(Vec3& E) const {
    if (count_ == 0) return false;
    Vec3 sum;
    double wsum = 0;
    for (int i = 0; i < count_; ++i) {
        sum += weight_[i] * E_[i];
        wsum += weight_[i];
    }
    E = sum / wsum;
    return true;
}

size_t IrradianceCache::KeyHash::operator()(const Key& k) const {
    return size_t(mix64((uint64_t(uint32_t(k.x)) << 32 | uint32_t(k.y)) ^ mix64(uint64_t(uint32_t(k.z)) << 8 ^ uint64_t(k.exp + 512))));
}

namespace {
int32_t cellOf(double v, double size) { return int32_t(std::clamp(std::floor(v / size), -2.0e9, 2.0e9)); }
}  // namespace

void IrradianceCache::build(double maxErrorBound) {
    exps_.clear();
    listed_.clear();
    cells_.clear();
    struct Entry {
        Key key;
        uint32_t record;
    };
    std::vector<Entry> entries;
    entries.reserve(records_.size() * 8);
    for (size_t i = 0; i < records_.size(); ++i) {
        const IrradianceRecord& r = records_[i];
        const double reach = maxErrorBound * levelErrorScale(r.level) * r.R;
        const int32_t e = int32_t(std::ceil(std::log2(std::max(2 * reach, 1e-9))));
        const double size = std::ldexp(1.0, e);
        int32_t lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = cellOf(r.P[k] - reach, size);
            hi[k] = cellOf(r.P[k] + reach, size);
        }
        for (int32_t x = lo[0]; x <= hi[0]; ++x)
            for (int32_t y = lo[1]; y <= hi[1]; ++y)
                for (int32_t z = lo[2]; z <= hi[2]; ++z) entries.push_back({Key{e, x, y, z}, uint32_t(i)});
        if (std::find(exps_.begin(), exps_.end(), e) == exps_.end()) exps_.push_back(e);
    }
    // Group by cell, records in order within a cell (a stable order: the blend's ties stay fixed).
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        if (a.key.exp != b.key.exp) return a.key.exp < b.key.exp;
        if (a.key.x != b.key.x) return a.key.x < b.key.x;
        if (a.key.y != b.key.y) return a.key.y < b.key.y;
        return a.key.z < b.key.z;
    });
    listed_.reserve(entries.size());
    cells_.reserve(entries.size());
    for (size_t i = 0; i < entries.size();) {
        size_t j = i;
        while (j < entries.size() && entries[j].key == entries[i].key) listed_.push_back(entries[j++].record);
        cells_.emplace(entries[i].key, Range{uint32_t(listed_.size() - (j - i)), uint32_t(listed_.size())});
        i = j;
    }
    std::sort(exps_.begin(), exps_.end());
}

void IrradianceCache::gather(Vec3 P, IrradianceBlend& blend) const {
    for (const int32_t e : exps_) {
        const double size = std::ldexp(1.0, e);
        const auto it = cells_.find(Key{e, cellOf(P.x, size), cellOf(P.y, size), cellOf(P.z, size)});
        if (it == cells_.end()) continue;
        for (uint32_t k = it->second.begin; k < it->second.end; ++k) blend.consider(records_[listed_[k]]);
    }
}

}  // namespace rays

// Ward's irradiance cache (G. J. Ward, F. M. Rubinstein, R. D. Clear, "A Ray Tracing Solution for
// Diffuse Interreflection", SIGGRAPH 1988): irradiance records (position, normal, irradiance, harmonic
// mean distance R) reused at nearby points whose error estimate ε = |P − Pᵢ|/Rᵢ + √(1 − N·Nᵢ) stays
// below the error bound a, blended with the weights 1/ε − 1/a. POV-Ray's radiosity is this cache
// (docs/povray-lighting.md, "Radiosity"); the records are made by the tracer (tracer_radiosity.cpp).
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

struct IrradianceRecord {
    Vec3 P, N;     ///< where, and the unit normal (facing the side the light was gathered on)
    Vec3 E;        ///< the gathered light: the cosine-weighted mean radiance over the hemisphere
    double R = 0;  ///< harmonic mean distance of the gathering rays' hits, clamped
    int level = 0; ///< radiosity bounces before the point (records serve points of their own level)
};

/// Records at radiosity level k (made for points k bounces from the camera) serve with the error
/// bound a·2^k: deeper levels are seen only averaged over many gathering rays, so their error
/// matters less (Rays' choice; without it a closed room takes several times as many records).
inline double levelErrorScale(int level) { return double(1 << (level < 8 ? level : 8)); }

/// Blends the records valid at a point, keeping the nearestCount with the largest weights.
class IrradianceBlend {
public:
    static constexpr int kMaxNearest = 20;
    IrradianceBlend(Vec3 P, Vec3 N, int level, double errorBound, int nearestCount);
    /// Considers one record (ignored unless of the same level, within the error bound and not in
    /// front of the point: Ward et al. 1988, section 3.3).
    void consider(const IrradianceRecord& r);
    /// True when some record was valid; E then receives the blend.
    bool result(Vec3& E) const;

private:
    Vec3 P_, N_;
    int level_;
    double a_, invA_;
    int nearest_, count_ = 0;
    double weight_[kMaxNearest];
    Vec3 E_[kMaxNearest];
};

/// The records of a render with a lookup structure built once (build) and read-only afterwards:
/// a hash grid per power-of-two cell size, each record listed in the cells its reach a·R overlaps
/// at the smallest size no less than twice that reach (so a point looks at one cell per size).
class IrradianceCache {
public:
    void add(const IrradianceRecord& r) { records_.push_back(r); }
    size_t size() const { return records_.size(); }
    const IrradianceRecord& record(size_t i) const { return records_[i]; }
    /// Indexes the records for lookups with error bounds up to maxErrorBound·levelErrorScale(level).
    void build(double maxErrorBound);
    /// Feeds every record that may be valid at P (error bound ≤ the build's) to blend.
    void gather(Vec3 P, IrradianceBlend& blend) const;

private:
    struct Key {
        int32_t exp, x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const;
    };
    struct Range {
        uint32_t begin, end;
    };
    std::vector<IrradianceRecord> records_;
    std::vector<int32_t> exps_;        ///< the cell sizes in use, 2^exp
    std::vector<uint32_t> listed_;     ///< record indices, cell after cell
    std::unordered_map<Key, Range, KeyHash> cells_;
};

}  // namespace rays

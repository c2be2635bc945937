// The photon map of POV-Ray scenes with photons (POV-Ray 3.7 reference, "Photons"): the photons
// the lights' shooting left on surfaces (render/tracer_photons.cpp), in a balanced kd-tree, and
// the light they bring to a point: the k nearest photons' power over the disc holding them
// (Jensen, "Realistic Image Synthesis Using Photon Mapping", 2001, §7.2). Built before the
// render, read-only during it.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

/// A photon left on a surface: where, the light it carries (its power as irradiance times area)
/// and the direction it travelled in. Floats: a map holds millions.
struct Photon {
    float position[3];
    float power[3];
    float dir[3];
    uint8_t axis = 0;  ///< the kd-tree's split axis at this photon (set by PhotonMap)
};

struct PhotonGather {
    int max = 100;               ///< at most this many photons per estimate
    double radius = 0;           ///< searched within this distance
    double expandPercent = 0.2;  ///< searched again this much farther ...
    int expandMin = 40;          ///< ... when fewer than this many lie within radius
};

class PhotonMap {
public:
    PhotonMap() = default;
    /// Builds the tree over the photons (reordered).
    explicit PhotonMap(std::vector<Photon> photons);

    size_t size() const { return photons_.size(); }
    bool empty() const { return photons_.empty(); }

    /// Irradiance at P on the side N faces: the power of the photons among the nearest g.max
    /// within g.radius (expanded as g says) that arrive on that side, over π·r², r the distance
    /// of the farthest one taken when g.max were found, else the search radius.
    Vec3 irradiance(Vec3 P, Vec3 N, const PhotonGather& g) const;

    /// The light photons left in a medium bring to P, for the medium's in-scattering: Σ w(dir)·power
    /// over the photons among the nearest g.max within g.radius, over the sphere's volume
    /// (4/3)π·r³, r the distance of the farthest one taken when g.max were found, else the radius
    /// (Jensen 2001, §10.4: the volume radiance estimate). w(dir) weighs a photon by the direction
    /// it travelled in (the medium's phase function and scattering colour).
    template <class Weigh>
    Vec3 inScattered(Vec3 P, const PhotonGather& g, Weigh&& w) const {
        if (photons_.empty() || !(g.radius > 0)) return {};
        Found found[kMaxVolumeGather];
        const int k = g.max < 1 ? 1 : (g.max > kMaxVolumeGather ? kMaxVolumeGather : g.max);
        const int n = nearest(P, g.radius * g.radius, k, found);
        if (n == 0) return {};
        const double r2 = n == k ? double(found[0].d2) : g.radius * g.radius;
        const double volume = 4.0 / 3.0 * 3.14159265358979323846 * r2 * std::sqrt(r2);
        if (!(volume > 0)) return {};
        Vec3 sum;
        for (int i = 0; i < n; ++i) {
            const Photon& ph = photons_[found[i].index];
            sum += w(at(ph.dir)) * at(ph.power);
        }
        return sum / volume;
    }

    /// A gather radius for these photons: twice the median distance, over up to 256 photons
    /// spread through the map, to their k-th nearest neighbour (0 for an empty map).
    double typicalRadius(int k) const;

private:
    static constexpr int kMaxVolumeGather = 200;  ///< photons per volume estimate, at most
    static Vec3 at(const float* v) { return {v[0], v[1], v[2]}; }
    struct Found {
        float d2;
        uint32_t index;
    };
    /// The nearest photons to P within √maxD2 (at most k, k ≤ kMaxPhotonGather) into found (a
    /// max-heap on d2 when k were found, else in no order); returns their number.
    int nearest(Vec3 P, double maxD2, int k, Found* found) const;
    void build(size_t lo, size_t hi);

    std::vector<Photon> photons_;
};

}  // namespace rays

// The photon map of POV-Ray scenes with photons (POV-Ray 3.7 reference, "Photons"): the photons
// the lights' shooting left on surfaces (render/tracer_photons.cpp), in a balanced kd-tree, and
// the light they bring to a point: the k nearest photons' power over the disc holding them
// (Jensen, "Realistic Image Synthesis Using Photon Mapping", 2001, §7.2). Built before the
// render, read-only during it.
#pragma once
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

    /// A gather radius for these photons: twice the median distance, over up to 256 photons
    /// spread through the map, to their k-th nearest neighbour (0 for an empty map).
    double typicalRadius(int k) const;

private:
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

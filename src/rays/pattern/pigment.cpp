#include "rays/pattern/pigment.h"

#include <algorithm>

namespace rays::pattern {

Vec3 PigmentTable::inNodeSpace(const PigmentNode& node, Vec3 p) const {
    if (node.warpCount > 0) {
        for (int i = 0; i < node.warpCount; ++i) p = applyWarp(warps[size_t(node.warpBegin + i)], p);
    } else if (node.transformed) {
        p = node.toPattern.point(p);
    }
    return p;
}

double PigmentTable::rawValue(const PigmentNode& node, Vec3 q, Vec3 N, Vec3 D) const {
    if (node.kind == PatternKind::ImagePattern) {
        if (node.params.turbulence.on()) q = turbulent(q, node.params.turbulence);
        return node.image >= 0 ? images[size_t(node.image)].value(q) : 0;
    }
    if (node.kind == PatternKind::MaterialMap) return node.image >= 0 ? images[size_t(node.image)].materialIndex(q) : 0;
    if (node.kind != PatternKind::PigmentPattern) return patternValue(node.kind, node.params, q, N, D);
    if (node.params.source < 0) return 0;
    if (node.params.turbulence.on()) q = turbulent(q, node.params.turbulence);
    const Rgbft c = evaluate(node.params.source, q, N, D);
    return 0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z;
}

MapPlace PigmentTable::place(int n, Vec3 p, Vec3 N, Vec3 D) const {
    const PigmentNode& node = nodes[size_t(n)];
    if (node.mapCount == 0) return {};
    p = inNodeSpace(node, p);
    if (node.kind == PatternKind::MaterialMap) {
        const int i = materialEntry(node, p);
        return {i, i, 0};
    }
    if (isBlockPattern(node.kind)) {
        const int i = std::min(blockIndex(node.kind, node.params, p), node.mapCount - 1);
        return {i, i, 0};
    }
    const double v = applyWave(node.wave, rawValue(node, p, N, D));
    return placeInMap({entries.data() + node.mapBegin, size_t(node.mapCount)}, v);
}

Rgbft PigmentTable::evaluate(int n, Vec3 p, Vec3 N, Vec3 D) const {
    const PigmentNode& node = nodes[size_t(n)];
    if (node.kind == PatternKind::Solid) return node.color;
    p = inNodeSpace(node, p);
    if (node.kind == PatternKind::ImageMap) return images[size_t(node.image)].color(p);
    const MapEntry* map = entries.data() + node.mapBegin;
    // Entries that are pigments are evaluated at the point in this pigment's space (the outer
    // pigment's transformations move its map's pigments too).
    auto entry = [&](int i) { return map[i].pigment >= 0 ? evaluate(map[i].pigment, p, N, D) : map[i].color; };
    if (node.mapCount == 0) return node.color;
    if (node.kind == PatternKind::MaterialMap) return entry(materialEntry(node, p));
    if (isBlockPattern(node.kind)) {
        const int i = blockIndex(node.kind, node.params, p);
        return entry(i < node.mapCount ? i : node.mapCount - 1);
    }
    if (node.kind == PatternKind::Layered) {
        // The upper layer lets the lower through where it filters (tinted by its colour) or
        // transmits (POV-Ray 3.7 reference, "Layered Textures").
        const Rgbft below = entry(0), top = entry(1);
        const double f = std::clamp(top.filter, 0.0, 1.0), t = std::clamp(top.transmit, 0.0, 1.0);
        const double through = std::min(1.0, f + t);
        return {top.rgb * (1 - through) + below.rgb * (Vec3(t) + f * top.rgb), below.filter * through,
                below.transmit * through};
    }
    if (node.kind == PatternKind::Average) {
        Rgbft sum;
        double weights = 0;
        for (int i = 0; i < node.mapCount; ++i) {
            const Rgbft c = entry(i);
            const double w = map[i].value;
            sum.rgb += c.rgb * w;
            sum.filter += c.filter * w;
            sum.transmit += c.transmit * w;
            weights += w;
        }
        if (weights == 0) return sum;
        return {sum.rgb / weights, sum.filter / weights, sum.transmit / weights};
    }
    const double v = applyWave(node.wave, rawValue(node, p, N, D));
    const MapPlace at = placeInMap({map, size_t(node.mapCount)}, v);
    if (at.lo == at.hi || at.t == 0) return entry(at.lo);
    if (at.t == 1) return entry(at.hi);
    return mix(entry(at.lo), entry(at.hi), at.t);
}

double PigmentTable::value(int n, Vec3 p, Vec3 N, Vec3 D) const {
    const PigmentNode& node = nodes[size_t(n)];
    switch (node.kind) {
        case PatternKind::Solid: case PatternKind::Average: case PatternKind::Layered: case PatternKind::ImageMap:
            return 0;
        default: break;
    }
    p = inNodeSpace(node, p);
    if (isBlockPattern(node.kind)) return blockIndex(node.kind, node.params, p);
    return applyWave(node.wave, rawValue(node, p, N, D));
}

int PigmentTable::materialEntry(const PigmentNode& node, Vec3 q) const {
    // POV-Ray 3.7 reference, "Material Maps": the index modulo the number of textures.
    return node.image >= 0 && node.mapCount > 0 ? images[size_t(node.image)].materialIndex(q) % node.mapCount : 0;
}

bool PigmentTable::mayLetLightThrough(int n) const {
    const PigmentNode& node = nodes[size_t(n)];
    if (node.color.filter != 0 || node.color.transmit != 0) return true;
    if (node.kind == PatternKind::ImageMap) {
        const ImageMap& m = images[size_t(node.image)];
        return m.filterAll != 0 || m.transmitAll != 0 || !m.palette.empty() || m.once || m.image->channels % 2 == 0;
    }
    for (int i = 0; i < node.mapCount; ++i) {
        const MapEntry& e = entries[size_t(node.mapBegin + i)];
        if (e.pigment >= 0 ? mayLetLightThrough(e.pigment) : (e.color.filter != 0 || e.color.transmit != 0))
            return true;
    }
    return false;
}

}  // namespace rays::pattern

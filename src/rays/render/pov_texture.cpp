#include "rays/render/pov_texture.h"

#include <algorithm>

#include "rays/render/pov_lighting.h"

namespace rays {
namespace {

constexpr int kMaxDepth = 16;

struct Choices {
    PovTextureChoice (&out)[kMaxTextureChoices];
    int count = 0;
};

void collect(const Scene& scene, int n, Vec3 P, Vec3 N, Vec3 D, const Vec3* uv, double weight, Choices& c, int depth) {
    const PovTextures& tx = scene.povTextures;
    const PovTextureNode& node = tx.nodes[size_t(n)];
    if (node.pattern < 0) {
        if (c.count < kMaxTextureChoices && node.count > 0) c.out[c.count++] = {weight, node.begin, node.count};
        return;
    }
    if (depth > kMaxDepth || node.count == 0) return;
    auto child = [&](int i) { return tx.children[size_t(node.begin + std::clamp(i, 0, node.count - 1))]; };
    const pattern::PigmentTable& pigments = scene.pigments;
    const pattern::PigmentNode& pn = pigments.nodes[size_t(pigments.roots[size_t(node.pattern)].node)];
    if (pn.kind == pattern::PatternKind::Average) {
        // The map's values weigh the textures.
        double total = 0;
        const int m = std::min(pn.mapCount, node.count);
        for (int i = 0; i < m; ++i) total += pigments.entries[size_t(pn.mapBegin + i)].value;
        if (total == 0) return;
        for (int i = 0; i < m; ++i)
            if (const double w = pigments.entries[size_t(pn.mapBegin + i)].value; w != 0)
                collect(scene, child(i), P, N, D, uv, weight * w / total, c, depth + 1);
        return;
    }
    const pattern::MapPlace at = pigments.placeAtRoot(node.pattern, P, N, uv, D);
    if (at.lo == at.hi || at.t <= 0) return collect(scene, child(at.lo), P, N, D, uv, weight, c, depth + 1);
    if (at.t >= 1) return collect(scene, child(at.hi), P, N, D, uv, weight, c, depth + 1);
    collect(scene, child(at.lo), P, N, D, uv, weight * (1 - at.t), c, depth + 1);
    collect(scene, child(at.hi), P, N, D, uv, weight * at.t, c, depth + 1);
}

}  // namespace

int povTextureChoices(const Scene& scene, int node, Vec3 P, Vec3 N, PovTextureChoice (&out)[kMaxTextureChoices],
                      const Vec3* uv, Vec3 D) {
    Choices c{out};
    collect(scene, node, P, N, D, uv, 1.0, c, 0);
    return c.count;
}

Vec3 povTextureTint(const Scene& scene, int node, Vec3 P, Vec3 N, const Vec3* uv, Vec3 D) {
    PovTextureChoice choices[kMaxTextureChoices];
    const int n = povTextureChoices(scene, node, P, N, choices, uv, D);
    Vec3 tint;
    for (int i = 0; i < n; ++i) {
        Vec3 through(1.0);
        for (int k = 0; k < choices[i].count && through != Vec3{}; ++k) {
            const PovLayer& l = scene.povTextures.layers[size_t(choices[i].begin + k)];
            const PovPigmentSample c = povLayerPigment(scene, l, P, N, uv, D);
            through *= povFilterTint(c.color, c.filter, c.transmit);
        }
        tint += choices[i].weight * through;
    }
    return tint;
}

}  // namespace rays

// SceneBuilder's media: interior media placed in Scene::povMedia, atmospheric media in
// PovGlobals::media, their densities as roots of Scene::pigments (POV-Ray 3.7 reference, "Media",
// "Density"; docs/povray-lighting.md, "Media").
#include "rays/pov/scene_builder.h"

#include <algorithm>

namespace rays::pov {

namespace {

// True for densities that cost noise to evaluate (noise-based patterns, turbulence, warps, maps
// of other densities).
bool costly(const pattern::PigmentTable& t, int node) {
    using pattern::PatternKind;
    const pattern::PigmentNode& n = t.nodes[size_t(node)];
    switch (n.kind) {
        case PatternKind::Solid: case PatternKind::Checker: case PatternKind::Hexagon: case PatternKind::Brick:
        case PatternKind::Gradient: case PatternKind::Radial: case PatternKind::Onion: case PatternKind::Spherical:
        case PatternKind::Cylindrical: case PatternKind::Planar: case PatternKind::Boxed:
            break;
        default: return true;
    }
    if (n.params.turbulence.on() || n.warpCount > 0) return true;
    for (int i = 0; i < n.mapCount; ++i)
        if (t.entries[size_t(n.mapBegin + i)].pigment >= 0) return true;
    return false;
}

}  // namespace

PovMedia SceneBuilder::placeMedia(const MediaLook& m) {
    PovMedia out = m.media;
    out.densityFirst = int(scene_.pigments.roots.size());
    out.densityCount = 0;
    // The densities multiply: the cheap ones go first, so that a point where one is 0 costs no
    // noise (micro.pov's spherical densities around its crackle).
    std::vector<DensityLook> densities = m.densities;
    std::stable_partition(densities.begin(), densities.end(), [&](const DensityLook& d) {
        return d.node >= 0 && !costly(scene_.pigments, d.node);
    });
    for (const DensityLook& d : densities) {
        if (d.node < 0 || d.toObject.determinant() == 0) continue;
        scene_.pigments.roots.push_back(pattern::PigmentRoot{d.toObject.inverse(), d.node});
        ++out.densityCount;
    }
    return out;
}

void SceneBuilder::placeInteriorMedia(const InteriorLook& look, PovInterior& in) {
    in.mediaFirst = 0;
    in.mediaCount = 0;
    if (look.media.empty()) return;
    std::vector<PovMedia> placed;
    for (const MediaLook& m : look.media) placed.push_back(placeMedia(m));
    std::vector<PovMedia>& all = scene_.povMedia;
    in.mediaCount = int(placed.size());
    // Copies of one object (a loop, a CSG's leaves) give the same media again: shared then. Their
    // densities' roots were made anew, so equal media are those with equal roots.
    const size_t n = placed.size();
    if (all.size() >= n) {
        bool same = true;
        for (size_t i = 0; i < n && same; ++i) {
            PovMedia a = all[all.size() - n + i], b = placed[i];
            same = a.densityCount == b.densityCount;
            for (int k = 0; k < a.densityCount && same; ++k) {
                const pattern::PigmentRoot& ra = scene_.pigments.roots[size_t(a.densityFirst + k)];
                const pattern::PigmentRoot& rb = scene_.pigments.roots[size_t(b.densityFirst + k)];
                same = ra.node == rb.node && std::equal(&ra.worldToTexture.m[0][0], &ra.worldToTexture.m[0][0] + 12,
                                                        &rb.worldToTexture.m[0][0]);
            }
            a.densityFirst = b.densityFirst = 0;
            same = same && a == b;
        }
        if (same) {
            in.mediaFirst = int(all.size() - n);
            return;
        }
    }
    in.mediaFirst = int(all.size());
    all.insert(all.end(), placed.begin(), placed.end());
}

void SceneBuilder::addAtmosphericMedia(const Item& media) {
    MediaLook m;
    readMedia(media, m, &pigments_, notes_);
    scene_.pov.media.push_back(placeMedia(m));
}

}  // namespace rays::pov

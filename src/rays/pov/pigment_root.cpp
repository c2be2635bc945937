// SceneBuilder's pigment pieces (kept apart from scene_builder.cpp, which is about objects): a
// look's compiled pattern and normal placed in the world, layered and patterned textures as nodes
// of Scene::povTextures, and the sky_sphere's pigments.
#include "rays/pov/scene_builder.h"

#include <algorithm>

namespace rays::pov {

using sdl::VType;

int SceneBuilder::pigmentRoot(const Appearance& look) {
    if (look.pigmentNode < 0 || look.pigmentToObject.determinant() == 0) return -1;
    scene_.pigments.roots.push_back(pattern::PigmentRoot{look.pigmentToObject.inverse(), look.pigmentNode, look.pigmentUV});
    return int(scene_.pigments.roots.size()) - 1;
}

int SceneBuilder::normalRoot(const Appearance& look) {
    if (look.normalNode < 0 || look.normalToObject.determinant() == 0) return -1;
    const Transform toTexture = look.normalToObject.inverse();
    scene_.normals.roots.push_back(pattern::NormalRoot{toTexture, look.normalToObject, look.normalNode});
    return int(scene_.normals.roots.size()) - 1;
}

PovLayer SceneBuilder::layerOf(const Appearance& look, const PovSurface& object) {
    PovLayer l;
    l.surface = object;
    l.surface.texture = -1;
    l.surface.finish = look.finish;
    l.surface.transmit = look.pigment.transmit;
    l.surface.pigment = pigmentRoot(look);
    l.surface.pigmentTransparent =
        l.surface.pigment >= 0 && scene_.pigments.mayLetLightThrough(look.pigmentNode);
    l.surface.normal = normalRoot(look);
    l.color = look.pigment.rgb;
    l.filter = std::clamp(look.pigment.filter, 0.0, 1.0);
    return l;
}

// Layers go to the table top first; a pattern's textures become nodes of their own first, so
// that its children are contiguous.
int SceneBuilder::textureNode(const Appearance& look, const PovSurface& object, int depth) {
    PovTextures& tx = scene_.povTextures;
    PovTextureNode node;
    if (!look.choices.empty() && depth < 64 && look.patternNode >= 0 && look.patternToObject.determinant() != 0) {
        std::vector<int> kids;
        for (const Appearance& c : look.choices) kids.push_back(textureNode(c, object, depth + 1));
        scene_.pigments.roots.push_back(pattern::PigmentRoot{look.patternToObject.inverse(), look.patternNode, look.patternUV});
        node.pattern = int(scene_.pigments.roots.size()) - 1;
        node.begin = int(tx.children.size());
        node.count = int(kids.size());
        tx.children.insert(tx.children.end(), kids.begin(), kids.end());
    } else {
        node.begin = int(tx.layers.size());
        if (look.layers.empty()) {
            tx.layers.push_back(layerOf(look, object));
        } else {
            for (auto it = look.layers.rbegin(); it != look.layers.rend(); ++it) tx.layers.push_back(layerOf(*it, object));
        }
        node.count = int(tx.layers.size()) - node.begin;
    }
    tx.nodes.push_back(node);
    return int(tx.nodes.size()) - 1;
}

bool SceneBuilder::textureMayLetLightThrough(int n) const {
    const PovTextures& tx = scene_.povTextures;
    const PovTextureNode& node = tx.nodes[size_t(n)];
    if (node.pattern >= 0) {
        for (int i = 0; i < node.count; ++i)
            if (textureMayLetLightThrough(tx.children[size_t(node.begin + i)])) return true;
        return false;
    }
    for (int i = 0; i < node.count; ++i) {
        const PovLayer& l = tx.layers[size_t(node.begin + i)];
        if (l.filter == 0 && l.surface.transmit == 0 && !l.surface.pigmentTransparent) return false;
    }
    return true;
}

namespace {

// A sky_sphere's entries with `sky_sphere { Base ... }` unrolled: the base's first.
void skyEntries(const Item& sky, std::vector<const Entry*>& out, int depth) {
    for (const Entry& e : sky.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::sky_sphere && depth < 64)
                    skyEntries(v.item(), out, depth + 1);
            continue;
        }
        out.push_back(&e);
    }
}

}  // namespace

// POV-Ray 3.7 reference, "Sky Sphere": the pigments are looked up at the ray's direction (a point
// of the unit sphere), the last pigment on top; the transformations turn the sky; emission scales it.
void SceneBuilder::addSkySphere(const Item& sky) {
    std::vector<const Entry*> entries;
    skyEntries(sky, entries, 0);
    std::vector<int> nodes;
    Transform turn;
    Vec3 emission{1, 1, 1};
    for (const Entry* e : entries) {
        if (isTransformEntry(*e)) {
            applyTransform(*e, turn);
            continue;
        }
        if (e->kw() == Kw::emission) emission = toColor(e->args[0]).rgb;
        if (e->kw() != Kw::pigment) continue;
        const Item& p = e->args[0].item();
        int node = pigments_.compile(p);
        if (node < 0) {  // a flat colour (or a pattern drawn in its mean colour)
            Rgbft c{Vec3(0.5), 0, 0};
            applyPigment(p, c, notes_, false);
            pattern::PigmentNode flat;
            flat.color = {c.rgb, c.filter, c.transmit};
            scene_.pigments.nodes.push_back(flat);
            node = int(scene_.pigments.nodes.size()) - 1;
        }
        nodes.push_back(node);
    }
    if (nodes.empty() || turn.determinant() == 0) return;
    scene_.pov.skyFirst = int(scene_.pigments.roots.size());
    scene_.pov.skyCount = int(nodes.size());
    scene_.pov.skyEmission = emission;
    scene_.pov.skyLayersAsTexture = version_ >= 3.7;
    for (int n : nodes) scene_.pigments.roots.push_back(pattern::PigmentRoot{turn.inverse(), n});
}

}  // namespace rays::pov

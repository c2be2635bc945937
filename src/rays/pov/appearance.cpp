#include "rays/pov/appearance.h"

#include <algorithm>
#include <string>

#include "rays/pov/specs.h"

namespace rays::pov {

using sdl::VType;

namespace {

// A pattern keyword of a pigment or texture: a pattern type, or a pigment's image_map.
bool isPatternKeyword(Kw k) { return isPatternType(k) || k == Kw::image_map; }

// The mean of colours, filter and transmit included.
struct ColorMean {
    Rgbft sum;
    int n = 0;
    void add(const Rgbft& c) {
        sum.rgb += c.rgb;
        sum.filter += c.filter;
        sum.transmit += c.transmit;
        ++n;
    }
    Rgbft mean() const { return {sum.rgb / double(n), sum.filter / n, sum.transmit / n}; }
};

// The mean colour of a colour map (each entry's colours), for patterns drawn as a flat colour.
bool mapAverage(const Item& map, Rgbft& out) {
    ColorMean m;
    for (const Entry& e : map.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && mapAverage(v.item(), out)) return true;
            continue;
        }
        if (e.key != kMapEntry) continue;
        for (size_t i = 1; i < e.args.size(); ++i) {
            if (e.args[i].type == VType::Color) m.add(toColor(e.args[i]));
        }
    }
    if (m.n == 0) return false;
    out = m.mean();
    return true;
}

}  // namespace

namespace {

// The look's pigment becomes p: its flat (mean) colour, and its compiled pattern when there is one.
// A block with no colour, pigment, map-less pattern or other base of its own (`pigment { scale 0.25 }`,
// `pigment { octaves 3 rotate 90*z }`) modifies the pigment the look has (measured with POV-Ray
// 3.7: `texture { T pigment { scale 0.25 } }` scales T's checker; of a layered T, its top layer's).
bool modifiesPigment(const Item& block) {
    return std::none_of(block.entries.begin(), block.entries.end(), [](const Entry& x) {
        return x.positional() ? !x.args.empty() : isPatternKeyword(x.kw());
    });
}

// `matrix <...>` standing for t (POV-Ray's row-vector order, as applyTransform reads it).
Entry matrixEntry(const Transform& t, const sdl::Loc& loc) {
    Entry m;
    m.key = uint16_t(Kw::matrix);
    m.loc = loc;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m.args.push_back(Value::number(t.m[r][c]));
    for (int r = 0; r < 3; ++r) m.args.push_back(Value::number(t.m[r][3]));
    return m;
}

void setPigment(const Entry& e, Appearance& a, NotRendered& notes, PigmentCompiler* pigments) {
    const Item& block = e.args[0].item();
    std::shared_ptr<const Item> source = e.args[0].itemRef();
    bool made = false;
    if (a.pigmentSource && modifiesPigment(block)) {
        // The texture's transformations since (`texture { T scale 2 pigment { ... } }`, a layer
        // `texture { T_Grnt7 scale <2, 3, 2> }`) come before the block's modifiers.
        auto merged = std::make_shared<Item>(*a.pigmentSource);
        if (!a.pigmentToObject.isIdentity()) merged->entries.push_back(matrixEntry(a.pigmentToObject, e.loc));
        merged->entries.insert(merged->entries.end(), block.entries.begin(), block.entries.end());
        source = std::move(merged);
        made = true;
    }
    applyPigment(*source, a.pigment, notes, pigments == nullptr);
    a.pigmentNode = !pigments ? -1 : made ? pigments->compile(source) : pigments->compile(*source);
    a.pigmentSource = std::move(source);
    a.pigmentToObject = Transform{};
    a.pigmentUV = hasEntry(*a.pigmentSource, Kw::uv_mapping);
}

// The look's normal becomes the normal item of entry e (compiled when the compiler makes normals).
void setNormal(const Entry& e, Appearance& a, NotRendered& notes, PigmentCompiler* pigments) {
    if (!pigments || !pigments->compilesNormals()) {
        notes.note("normal", e.loc, "(surfaces drawn smooth)");
        return;
    }
    const Item& block = e.args[0].item();
    std::shared_ptr<const Item> source = e.args[0].itemRef();
    // A block without a pattern or a normal of its own (`normal { slope_map {...} }`, `normal
    // { scale 2 }`) modifies the normal the look has (measured with POV-Ray 3.7: under `#default
    // { normal { onion } }`, an object's `normal { slope_map {...} }` shows the onion rings).
    const bool ownBase = std::any_of(block.entries.begin(), block.entries.end(), [](const Entry& x) {
        return x.positional() ? std::any_of(x.args.begin(), x.args.end(), [](const Value& v) { return v.type == VType::Item; })
                              : isPatternKeyword(x.kw());
    });
    if (!ownBase && a.normalSource && a.normalToObject.isIdentity()) {
        auto merged = std::make_shared<Item>(*a.normalSource);
        merged->entries.insert(merged->entries.end(), block.entries.begin(), block.entries.end());
        source = std::move(merged);
    }
    // A new pattern without an amount of its own, and the normals of its normal_map, keep the
    // amount of the normal it replaces (measured with POV-Ray 3.7: under `#default { normal {
    // bump_size 1.5 } }`, `normal { gradient x }` tilts as `gradient x 1.5`, and so do the entries
    // of `normal { gradient x normal_map { [0.3 gradient y] [0.7 gradient x] } }`; the map's own
    // amount does not scale its entries).
    double inherited = 0.5;
    if (ownBase && a.normalSource) {
        const auto [amount, given] = pigments->normalAmount(*a.normalSource);
        if (given) inherited = amount;
    }
    a.normalNode = pigments->compileNormal(source, inherited);
    a.normalSource = std::move(source);
    a.normalToObject = Transform{};
}

}  // namespace

void applyPigment(const Item& p, Rgbft& c, NotRendered& notes, bool noteUnrendered) {
    const char* pattern = nullptr;
    sdl::Loc patternAt;
    ColorMean list;  // a colour list of checker, hexagon, brick, object, ...
    bool fromMap = false;
    Rgbft mapColor;
    for (const Entry& e : p.entries) {
        if (e.positional()) {
            for (const Value& v : e.args) {
                if (v.type == VType::Item && v.item().kind == Kw::pigment) {
                    applyPigment(v.item(), c, notes, noteUnrendered);
                } else if (v.type == VType::Item && (v.item().kind == Kw::color_map || v.item().kind == Kw::colour_map)) {
                    fromMap = mapAverage(v.item(), mapColor) || fromMap;
                } else if (v.isNumeric()) {
                    if (pattern) list.add(toColor(v));
                    else c = toColor(v);
                }
            }
            continue;
        }
        if (e.key == kMapEntry) continue;
        const Kw k = e.kw();
        if (isPatternKeyword(k)) {
            pattern = sdl::keywordName(k).data();
            patternAt = e.loc;
        } else if (k == Kw::color_map || k == Kw::colour_map) {
            fromMap = mapAverage(e.args[0].item(), mapColor) || fromMap;
        } else if (k == Kw::pigment_map && noteUnrendered) {
            notes.note("pigment_map", e.loc, "(drawn in one colour)");
        }
    }
    if (!pattern) return;
    if (noteUnrendered) notes.note(std::string("pigment pattern ") + pattern, patternAt, "(drawn in its mean colour)");
    if (fromMap) {
        c = mapColor;
    } else if (list.n > 0) {
        c = list.mean();
    } else {
        c = Rgbft{Vec3(0.5), 0, 0};
    }
}

void applyFinish(const Item& f, PovFinish& fin, NotRendered& notes) {
    for (const Entry& e : f.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::finish) applyFinish(v.item(), fin, notes);
            continue;
        }
        const auto arg = [&](size_t i) { return i < e.args.size() ? toFloat(e.args[i]) : 0.0; };
        switch (e.kw()) {
            case Kw::ambient: fin.ambient = toColor(e.args[0]).rgb; break;
            case Kw::emission: fin.emission = toColor(e.args[0]).rgb; break;
            case Kw::diffuse:
                fin.diffuse = arg(1);
                if (e.args.size() > 2) fin.diffuseBack = arg(2);
                if (arg(0) != 0) notes.note("diffuse albedo", e.loc, "(taken as the plain amount)");
                break;
            case Kw::brilliance: fin.brilliance = arg(0); break;
            case Kw::phong:
                fin.phong = arg(1);
                if (arg(0) != 0) notes.note("phong albedo", e.loc, "(taken as the plain amount)");
                break;
            case Kw::phong_size: fin.phongSize = arg(0); break;
            case Kw::specular:
                fin.specular = arg(1);
                if (arg(0) != 0) notes.note("specular albedo", e.loc, "(taken as the plain amount)");
                break;
            case Kw::roughness: fin.roughness = arg(0); break;
            case Kw::metallic: fin.metallic = e.args.empty() ? 1.0 : arg(0); break;
            case Kw::reflection: {
                const Value& r = e.args[0];
                if (r.type != VType::Item) {
                    fin.reflectionMin = fin.reflectionMax = toColor(r).rgb;
                    break;
                }
                std::vector<const Value*> pos = positionals(r.item());
                for (const Entry& re : r.item().entries) {
                    if (re.positional()) continue;
                    const double v = re.args.empty() ? 1.0 : toFloat(re.args[0]);
                    if (re.kw() == Kw::fresnel) fin.reflectionFresnel = v != 0;
                    if (re.kw() == Kw::falloff) fin.reflectionFalloff = v;
                    if (re.kw() == Kw::exponent) fin.reflectionExponent = v;
                    if (re.kw() == Kw::metallic) fin.reflectionMetallic = v;
                }
                // One value is the maximum; the minimum is that value too, except with fresnel,
                // where it is 0 (POV-Ray reflects max·Fresnel: measured, docs/povray-lighting.md).
                if (pos.size() == 1) {
                    fin.reflectionMax = toColor(*pos[0]).rgb;
                    fin.reflectionMin = fin.reflectionFresnel ? Vec3{} : fin.reflectionMax;
                }
                if (pos.size() >= 2) {
                    fin.reflectionMin = toColor(*pos[0]).rgb;
                    fin.reflectionMax = toColor(*pos[1]).rgb;
                }
                break;
            }
            case Kw::reflection_exponent: fin.reflectionExponent = arg(0); break;
            case Kw::conserve_energy: fin.conserveEnergy = true; break;
            case Kw::irid: {  // irid { amount [thickness T] [turbulence U] }
                const Value& v = e.args[0];
                if (v.type != VType::Item) {
                    fin.irid = toFloat(v);
                    break;
                }
                std::vector<const Value*> pos = positionals(v.item());
                if (!pos.empty()) fin.irid = toFloat(*pos[0]);
                for (const Entry& ie : v.item().entries) {
                    if (ie.positional() || ie.args.empty()) continue;
                    if (ie.kw() == Kw::thickness) fin.iridThickness = toFloat(ie.args[0]);
                    if (ie.kw() == Kw::turbulence) fin.iridTurbulence = toVec3(ie.args[0]).x;
                }
                break;
            }
            case Kw::crand: fin.crand = std::max(0.0, arg(0)); break;
            case Kw::subsurface:  // subsurface { translucency C }
                if (!e.args.empty() && e.args[0].type == VType::Item)
                    for (const Entry& se : e.args[0].item().entries)
                        if (!se.positional() && se.kw() == Kw::translucency && !se.args.empty()) {
                            fin.subsurface = true;
                            fin.translucency = toColor(se.args[0]).rgb;
                        }
                break;
            case Kw::fresnel: fin.reflectionFresnel = arg(0) != 0; break;
            case Kw::refraction: case Kw::ior: case Kw::caustics: case Kw::fade_distance: case Kw::fade_power:
                notes.note(std::string("finish ") + std::string(sdl::keywordName(e.kw())) + " (POV-Ray 3.0 syntax)", e.loc);
                break;
            default: break;
        }
    }
}

void applyInterior(const Item& i, InteriorLook& in, NotRendered& notes, PigmentCompiler* pigments) {
    for (const Entry& e : i.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::interior) applyInterior(v.item(), in, notes, pigments);
            continue;
        }
        switch (e.kw()) {
            case Kw::ior: in.ior = toFloat(e.args[0]); break;
            case Kw::fade_distance: in.fadeDistance = toFloat(e.args[0]); break;
            case Kw::fade_power: in.fadePower = toFloat(e.args[0]); break;
            case Kw::fade_color: case Kw::fade_colour: in.fadeColor = toColor(e.args[0]).rgb; break;
            case Kw::media:  // media add up: each interior media block is one more medium
                if (!e.args.empty() && e.args[0].type == VType::Item) {
                    MediaLook m;
                    readMedia(e.args[0].item(), m, pigments, notes);
                    in.media.push_back(std::move(m));
                }
                break;
            case Kw::caustics: in.caustics = toFloat(e.args[0]); break;
            case Kw::dispersion: in.dispersion = toFloat(e.args[0]); break;
            // At least 2, as POV-Ray 3.7 takes them (its reference's minimum); at most 1024.
            case Kw::dispersion_samples: in.dispersionSamples = int(std::clamp(toFloat(e.args[0]), 2.0, 1024.0)); break;
            default: break;
        }
    }
}

namespace {

// moveLook (keepUV false) and placeLook (true: uv-mapped pigments and patterns stay in uv space).
void moveParts(Appearance& a, const Transform& outer, bool keepUV) {
    if (!(keepUV && a.pigmentUV)) a.pigmentToObject = outer * a.pigmentToObject;
    a.normalToObject = outer * a.normalToObject;
    if (!(keepUV && a.patternUV)) a.patternToObject = outer * a.patternToObject;
    for (Appearance& l : a.layers) moveParts(l, outer, keepUV);
    for (Appearance& c : a.choices) moveParts(c, outer, keepUV);
    for (Appearance& i : a.inside) moveParts(i, outer, keepUV);
    for (MediaLook& m : a.interior.media) moveMedia(m, outer);
}

}  // namespace

void moveLook(Appearance& a, const Transform& outer) { moveParts(a, outer, false); }

void moveLook(Appearance& a, const Entry& transformation) {
    Transform t;
    applyTransform(transformation, t);
    moveLook(a, t);
}

void placeLook(Appearance& a, const Transform& outer) { moveParts(a, outer, true); }

void placeLook(Appearance& a, const Entry& transformation) {
    Transform t;
    applyTransform(transformation, t);
    placeLook(a, t);
}

void mapLookByUV(Appearance& a) {
    a.pigmentUV = a.pigmentNode >= 0;
    a.patternUV = a.patternNode >= 0;
    for (Appearance& l : a.layers) mapLookByUV(l);
    for (Appearance& c : a.choices) mapLookByUV(c);
    for (Appearance& i : a.inside) mapLookByUV(i);
}

namespace {

// The look as one plain texture (a layered or patterned look: the mix of its parts).
Appearance plainLook(const Appearance& a) {
    Appearance p = a;
    p.layers.clear();
    p.choices.clear();
    p.patternNode = -1;
    p.parts = 1;
    p.inside.clear();
    return p;
}

// Looks kept apart in one object's texture at most: textures nested in patterns double at every
// level, so a deeper tree is drawn as its mix (noted).
constexpr int kMaxParts = 4096;

int partsOf(const std::vector<Appearance>& looks) {
    int n = 0;
    for (const Appearance& l : looks) n = std::min(kMaxParts + 1, n + l.parts);
    return n;
}

// A layer over the texture below it (POV-Ray 3.7 reference, "Layered Textures"). Each layer keeps
// its own pigment, normal and finish (a.layers; the tracer lights them one by one); a layer starts
// from the default texture, not from the layer below (measured). The fields of a become their mix
// for paths that draw one look: the pigments mixed point by point (a Layered pigment node; the flat
// colour is the mix of the mean colours), the finish the layer's where it is mostly opaque.
void applyLayer(const Item& layer, Appearance& a, NotRendered& notes, PigmentCompiler* pigments,
                const Appearance* base) {
    const Appearance below = a;
    Appearance top = base ? plainLook(*base) : Appearance{};
    top.interior = a.interior;
    top.interiorSet = a.interiorSet;
    applyTexture(layer, top, notes, pigments, base);
    std::vector<Appearance> layers = below.layers;
    if (layers.empty()) layers.push_back(plainLook(below));
    if (top.layers.empty()) layers.push_back(plainLook(top));
    else layers.insert(layers.end(), top.layers.begin(), top.layers.end());

    a = plainLook(top);
    if (a.normalNode < 0) {  // the mix keeps the last normal given
        a.normalNode = below.normalNode;
        a.normalToObject = below.normalToObject;
    }
    const double f = std::clamp(a.pigment.filter, 0.0, 1.0);
    const double t = std::clamp(a.pigment.transmit, 0.0, 1.0);
    const double through = std::min(1.0, f + t);
    a.pigment.rgb = a.pigment.rgb * (1 - through) + below.pigment.rgb * (Vec3{t, t, t} + f * a.pigment.rgb);
    a.pigment.filter = below.pigment.filter * through;
    a.pigment.transmit = below.pigment.transmit * through;
    if (through >= 0.5) a.finish = below.finish;
    // Patterns: the layers are mixed point by point.
    if (pigments && (top.pigmentNode >= 0 || below.pigmentNode >= 0)) {
        a.pigmentNode = pigments->layered({below.pigmentNode, below.pigment, below.pigmentToObject},
                                          {top.pigmentNode, top.pigment, top.pigmentToObject});
        a.pigmentToObject = Transform{};
        a.pigmentUV = false;  // the mix is placed by the point (uv-mapped layers keep their uv in a.layers)
    }
    a.parts = partsOf(layers);
    if (a.parts <= kMaxParts) a.layers = std::move(layers);
    else notes.note("layered texture", layer.loc, "(more than 4096 textures in one: the layers' pigments mixed, lit with one finish)");
}

// A patterned texture (POV-Ray 3.7 reference, "Patterned Textures", "Texture Maps"): the pattern
// chooses among whole textures (a.choices, each lit with its own finish and normal by the tracer;
// the fields of a become the first texture with the textures' pigments following the pattern).
// False when the texture is not one (or its pattern is not rendered).
bool applyPatternedTexture(const Item& t, Appearance& a, NotRendered& notes, PigmentCompiler& pigments,
                           const Appearance* base) {
    const Entry* patternAt = nullptr;
    const Item* tiles = nullptr;  // tiles { texture {A} tile2 texture {B} }: POV-Ray's old checker of textures
    const Item* materialMap = nullptr;  // material_map { png "file" texture {A} texture {B} ... }
    for (const Entry& e : t.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::texture) return false;  // a base texture
            continue;
        }
        if (e.key != kMapEntry && isPatternKeyword(e.kw())) patternAt = &e;
        if (e.key != kMapEntry && e.kw() == Kw::tiles && !e.args.empty() && e.args[0].type == VType::Item) {
            patternAt = &e;
            tiles = &e.args[0].item();
        }
        if (e.key != kMapEntry && e.kw() == Kw::material_map && !e.args.empty() && e.args[0].type == VType::Item) {
            patternAt = &e;
            materialMap = &e.args[0].item();
        }
    }
    if (!patternAt) return false;
    std::vector<PigmentCompiler::Placed> entries;
    std::vector<double> values;
    std::vector<Appearance> looks;
    auto addTexture = [&](const Item& sub, double value) {
        Appearance look = plainLook(a);
        look.pigmentNode = -1;
        look.pigmentToObject = Transform{};
        look.normalToObject = Transform{};
        applyTexture(sub, look, notes, &pigments, base);
        entries.push_back({look.pigmentNode, look.pigment, look.pigmentToObject});
        values.push_back(value);
        looks.push_back(look);
    };
    // Textures written in a row arrive as one layered item (grammar.cpp); in a pattern's list
    // they are its entries.
    auto addTextures = [&](const Item& row) {
        const bool isRow = row.entries.size() > 1 && std::all_of(row.entries.begin(), row.entries.end(), [](const Entry& r) {
            return r.positional() && r.args.size() == 1 && r.args[0].type == VType::Item &&
                   r.args[0].item().kind == Kw::texture;
        });
        if (!isRow) addTexture(row, 0);
        else
            for (const Entry& r : row.entries) addTexture(r.args[0].item(), 0);
    };
    for (const Entry& e : t.entries) {
        if (e.positional() || e.key == kMapEntry) continue;
        // object { OBJECT texture { A }, texture { B } }: its list is inside its braces.
        if (e.kw() == Kw::object && !e.args.empty() && e.args[0].type == VType::Item)
            for (const Entry& le : e.args[0].item().entries)
                if (!le.positional() && le.kw() == Kw::texture && !le.args.empty() && le.args[0].type == VType::Item)
                    addTextures(le.args[0].item());
        if (e.kw() == Kw::texture) addTextures(e.args[0].item());
        if (e.kw() == Kw::material_map && materialMap)
            for (const Entry& me : materialMap->entries)
                if (!me.positional() && me.key != kMapEntry && me.kw() == Kw::texture) addTextures(me.args[0].item());
        if (e.kw() == Kw::tiles && tiles) {
            // The textures before tile2 make the first tile (layered when several), those after
            // the second; the block's transformations move them with the checker. The tile2
            // textures lie where a checker puts its first entry, the first ones where it puts its
            // second (measured with POV-Ray 3.7 on planes y = −1.5 … 1.5: the two patterns
            // disagree on every square), so the checker's entries are the tile2 ones, then the first.
            std::vector<const Item*> parts[2];
            int part = 1;
            for (const Entry& te : tiles->entries) {
                if (te.positional() || te.key == kMapEntry) continue;
                if (te.kw() == Kw::tile2) part = 0;
                if (te.kw() == Kw::texture) parts[part].push_back(&te.args[0].item());
            }
            for (const auto& textures : parts) {
                if (textures.empty()) continue;
                addTexture(*textures[0], 0);
                for (size_t i = 1; i < textures.size(); ++i) applyLayer(*textures[i], looks.back(), notes, &pigments, base);
                for (const Entry& te : tiles->entries)
                    if (!te.positional() && te.key != kMapEntry && isTransformEntry(te)) moveLook(looks.back(), te);
                entries.back() = {looks.back().pigmentNode, looks.back().pigment, looks.back().pigmentToObject};
            }
        }
        if (e.kw() == Kw::texture_map)
            for (const Entry& me : e.args[0].item().entries)
                if (me.key == kMapEntry && me.args.size() > 1 && me.args[1].type == VType::Item)
                    // An average's entries may leave their weight out: 1 (as in pigment maps).
                    addTexture(me.args[1].item(), me.args[0].type == VType::Undefined ? 1 : toFloat(me.args[0]));
    }
    const int node = tiles         ? pigments.tilesTexture(t, *tiles, entries)
                     : materialMap ? pigments.materialMapTexture(t, *materialMap, entries)
                                   : pigments.patternedTexture(t, entries, values);
    if (node < 0) return false;
    // The texture's transformations move its textures with the pattern.
    for (const Entry& e : t.entries)
        if (!e.positional() && e.key != kMapEntry && isTransformEntry(e))
            for (Appearance& l : looks) moveLook(l, e);
    ColorMean mean;
    for (const Appearance& l : looks) mean.add(l.pigment);
    const InteriorLook interior = a.interior;
    const bool interiorSet = a.interiorSet;
    a = plainLook(tiles ? looks.back() : looks[0]);  // the first texture written (tiles: see above)
    a.interior = interior;
    a.interiorSet = interiorSet;
    a.pigment = mean.mean();
    a.pigmentNode = node;
    a.pigmentToObject = Transform{};
    a.pigmentUV = false;
    a.patternNode = node;
    a.patternToObject = Transform{};
    a.patternUV = false;
    a.parts = partsOf(looks);
    if (a.parts <= kMaxParts) a.choices = std::move(looks);
    else notes.note("texture pattern", patternAt->loc, "(more than 4096 textures in one: the textures' pigments follow the pattern, lit with one finish)");
    return true;
}

// The part of a look that a texture's own pigment, normal or finish changes: the look, and the top
// layer of a layered one (a modifier after a layered texture's identifier changes its top layer:
// measured).
template <class F>
void onTop(Appearance& a, F&& change) {
    change(a);
    if (!a.layers.empty()) change(a.layers.back());
}

}  // namespace

void applyTexture(const Item& t, Appearance& a, NotRendered& notes, PigmentCompiler* pigments,
                  const Appearance* layerBase) {
    a.set = true;
    if (pigments && applyPatternedTexture(t, a, notes, *pigments, layerBase)) {
        if (hasEntry(t, Kw::uv_mapping)) mapLookByUV(a);
        return;
    }
    bool layered = false;  // a texture item applied already: the next is a layer over it
    for (const Entry& e : t.entries) {
        if (e.positional()) {
            for (const Value& v : e.args) {
                if (v.type != VType::Item || v.item().kind != Kw::texture) continue;
                if (layered) applyLayer(v.item(), a, notes, pigments, layerBase);
                else applyTexture(v.item(), a, notes, pigments, layerBase);
                layered = true;
            }
            continue;
        }
        if (e.key == kMapEntry) continue;
        if (isTransformEntry(e)) {  // moves the texture's pigment and normal (set before it)
            moveLook(a, e);
            continue;
        }
        switch (e.kw()) {
            case Kw::pigment:
                onTop(a, [&](Appearance& l) { setPigment(e, l, notes, pigments); });
                break;
            case Kw::finish: onTop(a, [&](Appearance& l) { applyFinish(e.args[0].item(), l.finish, notes); }); break;
            case Kw::normal: onTop(a, [&](Appearance& l) { setNormal(e, l, notes, pigments); }); break;
            case Kw::texture_map: notes.note("texture_map", e.loc, "(drawn with its first texture)");
                for (const Entry& me : e.args[0].item().entries)
                    if (me.key == kMapEntry && me.args.size() > 1 && me.args[1].type == VType::Item) {
                        applyTexture(me.args[1].item(), a, notes, pigments, layerBase);
                        break;
                    }
                break;
            case Kw::material_map: notes.note("material_map", e.loc); break;
            case Kw::tiles: notes.note("tiles", e.loc, "(not two textures: drawn with the first)"); break;
            default:
                if (isPatternKeyword(e.kw())) notes.note("texture pattern", e.loc);
                break;
        }
    }
    if (hasEntry(t, Kw::uv_mapping)) mapLookByUV(a);
}

bool applyAppearanceEntry(const Entry& e, Appearance& a, const Appearance& fallback, NotRendered& notes,
                          PigmentCompiler* pigments) {
    if (e.positional() || e.key == kMapEntry) return false;
    const Kw k = e.kw();
    if (k != Kw::texture && k != Kw::pigment && k != Kw::finish && k != Kw::normal && k != Kw::interior &&
        k != Kw::material && k != Kw::interior_texture)
        return false;
    if (k == Kw::interior) {
        applyInterior(e.args[0].item(), a.interior, notes, pigments);
        a.interior.block = reinterpret_cast<uintptr_t>(&e.args[0].item());  // the block's identity while the scene is built
        a.interiorSet = true;
        return true;
    }
    if (k == Kw::interior_texture) {  // the inner side's texture (POV-Ray 3.7 reference, "Interior Texture")
        Appearance inside = fallback;
        inside.inside.clear();
        applyTexture(e.args[0].item(), inside, notes, pigments, &fallback);
        a.inside.assign(1, std::move(inside));
        return true;
    }
    if (!a.set) {  // the first texture entry starts from the default; an interior and an
                   // interior_texture written before it stay (measured: interior_texture then
                   // texture keeps the inner side's texture)
        const InteriorLook keep = a.interior;
        const bool keepSet = a.interiorSet;
        auto keepInside = std::move(a.inside);
        a = fallback;
        a.interior = keep;
        a.interiorSet = keepSet;
        if (!keepInside.empty()) a.inside = std::move(keepInside);
        a.set = true;
    }
    switch (k) {
        case Kw::texture:  // over what is set (textures written in a row arrive as one layered texture)
            applyTexture(e.args[0].item(), a, notes, pigments, &fallback);
            break;
        case Kw::pigment: onTop(a, [&](Appearance& l) { setPigment(e, l, notes, pigments); }); break;
        case Kw::finish: onTop(a, [&](Appearance& l) { applyFinish(e.args[0].item(), l.finish, notes); }); break;
        case Kw::normal: onTop(a, [&](Appearance& l) { setNormal(e, l, notes, pigments); }); break;
        case Kw::material:
            for (const Entry& me : e.args[0].item().entries) {
                if (me.positional()) {
                    for (const Value& v : me.args)
                        if (v.type == VType::Item && v.item().kind == Kw::material) {
                            Entry inner = e;
                            inner.args = {v};
                            applyAppearanceEntry(inner, a, fallback, notes, pigments);
                        }
                    continue;
                }
                applyAppearanceEntry(me, a, fallback, notes, pigments);
            }
            break;
        default: break;
    }
    return true;
}

}  // namespace rays::pov

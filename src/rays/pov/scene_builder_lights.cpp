// SceneBuilder's lights and atmosphere: light_source (point, spot, cylinder, area, parallel,
// fading, looks_like) → Light, and fog → PovFog.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/error.h"
#include "rays/pov/grammar.h"
#include "rays/pov/photon_settings.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/scene_builder_parts.h"

namespace rays::pov {

using sdl::VType;

namespace {

// The object of a looks_like block (nullptr when it holds none).
const Item* lookedLikeObject(const Entry& e) {
    if (e.args.empty() || e.args[0].type != VType::Item) return nullptr;
    for (const Entry& inner : e.args[0].item().entries)
        for (const Value& v : inner.args)
            if (v.type == VType::Item && isObjectKind(v.item().kind)) return &v.item();
    return nullptr;
}

}  // namespace

// ---- lights ----------------------------------------------------------------------------------

void SceneBuilder::addLight(const Item& item, const Transform& toWorld) {
    std::vector<const Value*> p = positionals(item);
    // `light_source { Declared modifiers }`: the declared light with these modifiers after its own.
    if (!p.empty() && p[0]->type == VType::Item && p[0]->item().kind == Kw::light_source) {
        Item merged = p[0]->item();
        for (const Entry& e : item.entries)
            if (!e.positional()) merged.entries.push_back(e);
        return addLight(merged, toWorld);
    }
    Light l;
    Vec3 pos = p.empty() ? Vec3{} : toVec3(*p[0]);
    l.color = p.size() > 1 ? toColor(*p[1]).rgb : Vec3{1, 1, 1};
    Transform m;
    Vec3 pointAt{0, 0, 1};
    bool parallel = false, pointAtSet = false;
    double radius = -1, falloff = -1;  // the light type's default unless set
    bool radiusSet = false, falloffSet = false;
    const Item* looksLike = nullptr;
    const Item* projector = nullptr;
    for (const Entry& e : item.entries) {
        if (e.positional()) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, m);
            continue;
        }
        switch (e.kw()) {
            case Kw::spotlight: l.spot = Light::Spot::Cone; break;
            case Kw::cylinder: l.spot = Light::Spot::Cylinder; break;
            case Kw::parallel: parallel = true; break;
            case Kw::point_at:
                pointAt = toVec3(e.args[0]);
                pointAtSet = true;
                break;
            case Kw::radius: radius = toFloat(e.args[0]), radiusSet = true; break;
            case Kw::falloff: falloff = toFloat(e.args[0]), falloffSet = true; break;
            case Kw::tightness: l.tightness = std::max(0.0, toFloat(e.args[0])); break;
            case Kw::shadowless: l.shadowless = true; break;
            case Kw::media_interaction: l.mediaInteraction = isOn(e); break;
            case Kw::media_attenuation: l.mediaAttenuation = isOn(e); break;
            case Kw::photons: readLightPhotons(e.args[0].item(), l); break;
            case Kw::area_light:
                if (e.args.size() == 4) {
                    l.area = true;
                    l.axis1 = toVec3(e.args[0]);
                    l.axis2 = toVec3(e.args[1]);
                    l.n1 = clampedInt(toFloat(e.args[2]), 1, 1024);
                    l.n2 = clampedInt(toFloat(e.args[3]), 1, 1024);
                }
                break;
            case Kw::jitter: l.jitter = isOn(e); break;
            case Kw::adaptive: l.adaptive = clampedInt(toFloat(e.args[0]), -1, 1000); break;
            case Kw::circular: l.circular = isOn(e); break;
            case Kw::orient: l.orient = isOn(e); break;
            case Kw::area_illumination: l.areaIllumination = isOn(e); break;
            case Kw::fade_distance: l.fadeDistance = std::max(0.0, toFloat(e.args[0])); break;
            case Kw::fade_power: l.fadePower = toFloat(e.args[0]); break;
            case Kw::looks_like: looksLike = lookedLikeObject(e); break;
            case Kw::projected_through: projector = lookedLikeObject(e); break;
            default: break;
        }
    }
    const Transform world = toWorld * m;
    l.position = world.point(pos);
    l.axis1 = world.vector(l.axis1);
    l.axis2 = world.vector(l.axis2);
    auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(l.position) || !finite(l.axis1) || !finite(l.axis2))
        throw Error(notes_.where(item.loc) + ": error: the light's transformation overflows (its position is no longer finite)");
    if (l.spot != Light::Spot::None) {
        // The manual's defaults: spotlights radius 30 and falloff 45 degrees (cosines kept);
        // cylindrical lights 0.75 and 1, measured to be distances from the axis.
        const Vec3 d = world.point(pointAtSet ? pointAt : Vec3{}) - l.position;
        if (length(d) == 0) {
            l.spot = Light::Spot::None;
        } else if (l.spot == Light::Spot::Cone) {
            // A negative angle acts as its size (measured: radius -90 lights the whole half-space,
            // falloff -80 as 80; radiosity/cornell.pov's lights are written so).
            auto cosDeg = [](double deg) { return std::cos(std::clamp(std::fabs(deg), 0.0, 180.0) * std::numbers::pi / 180); };
            l.spotRadius = cosDeg(radiusSet ? radius : 30);
            l.spotFalloff = cosDeg(falloffSet ? falloff : 45);
            l.direction = normalize(d);
        } else {
            l.spotRadius = radiusSet && radius >= 0 ? radius : 0.75;
            l.spotFalloff = falloffSet && falloff >= 0 ? falloff : 1;
            // Cylindrical lights shine and cast shadows along their axis (measured).
            parallel = true;
            pointAt = pointAtSet ? pointAt : Vec3{};
        }
    }
    if (parallel) {
        const Vec3 d = world.point(pointAt) - l.position;
        if (length(d) > 0) {
            l.parallel = true;
            l.area = false;
            l.pointAt = world.point(pointAt);
            l.direction = normalize(d);
        } else if (l.spot == Light::Spot::Cylinder) {
            l.spot = Light::Spot::None;
        }
    }
    if (l.area && (length(cross(l.axis1, l.axis2)) == 0)) l.area = false;
    l.lightGroup = lightGroup_;
    if (lightGroup_ >= 0) l.mediaInteraction = false;
    scene_.lights.push_back(l);
    // projected_through (POV-Ray 3.7 reference, "Projected Through": the light is cast only
    // through the object): the object, moved by the light's transformations, is built aside in
    // Scene::projectors; it is neither drawn nor casts shadows itself.
    if (projector) {
        const size_t before = scene_.objects.size();
        addObject(*projector, world, nullptr, 0);
        Light& added = scene_.lights.back();
        added.projectorBegin = int(scene_.projectors.size());
        for (size_t i = before; i < scene_.objects.size(); ++i) scene_.projectors.push_back(std::move(scene_.objects[i]));
        scene_.objects.erase(scene_.objects.begin() + std::ptrdiff_t(before), scene_.objects.end());
        added.projectorCount = int(scene_.projectors.size()) - added.projectorBegin;
    }
    // looks_like: the object, moved to the light's place, is seen but casts no shadow (the manual).
    if (looksLike) {
        const bool saved = noShadow_;
        noShadow_ = true;
        addObject(*looksLike, world * Transform::translate(pos), nullptr, 0);
        noShadow_ = saved;
    }
}

// ---- atmosphere -----------------------------------------------------------------------------

// POV-Ray 3.7 reference, "Fog": fog_type 1 (constant) and 2 (ground fog along up), distance and
// the colour with filter and transmit; transformations turn up; turbulence with turb_depth,
// octaves, omega and lambda (render/pov_lighting.cpp). A fog identifier's items come first.
// distance 0 turns the fog off (the manual).
void SceneBuilder::addFog(const Item& item) {
    PovFog f;
    Transform m;
    std::function<void(const Item&)> read = [&](const Item& it) {
        for (const Entry& e : it.entries) {
            if (e.positional()) {
                for (const Value& v : e.args) {
                    if (v.type == VType::Item && v.item().kind == Kw::fog) {
                        read(v.item());
                    } else {
                        const Rgbft c = toColor(v);
                        f.color = c.rgb;
                        f.filter = c.filter;
                        f.transmit = c.transmit;
                    }
                }
                continue;
            }
            if (isTransformEntry(e)) {
                applyTransform(e, m);
                continue;
            }
            switch (e.kw()) {
                case Kw::fog_type: f.ground = toFloat(e.args[0]) == 2; break;
                case Kw::distance: f.distance = toFloat(e.args[0]); break;
                case Kw::fog_offset: f.offset = toFloat(e.args[0]); break;
                case Kw::fog_alt: f.alt = toFloat(e.args[0]); break;
                case Kw::up: f.up = toVec3(e.args[0]); break;
                case Kw::turbulence: f.turbulence.amount = toVec3(e.args[0]); break;
                case Kw::turb_depth: f.turbDepth = toFloat(e.args[0]); break;
                case Kw::octaves: f.turbulence.octaves = int(std::clamp(toFloat(e.args[0]), 1.0, 10.0)); break;
                case Kw::omega: f.turbulence.omega = toFloat(e.args[0]); break;
                case Kw::lambda: f.turbulence.lambda = toFloat(e.args[0]); break;
                default: break;
            }
        }
    };
    read(item);
    f.up = m.vector(f.up);
    if (f.distance <= 0 || length(f.up) == 0) return;
    f.up = normalize(f.up);
    scene_.pov.fogs.push_back(f);
}

// POV-Ray 3.7 reference, "Rainbow": direction, angle, width, distance, colour map, jitter, up,
// arc_angle, falloff_angle (render/pov_rainbow.h). A rainbow identifier's items come first.
void SceneBuilder::addRainbow(const Item& item) {
    PovRainbow r;
    std::function<void(const Item&)> read = [&](const Item& it) {
        for (const Entry& e : it.entries) {
            if (e.positional()) {
                for (const Value& v : e.args)
                    if (v.type == VType::Item && v.item().kind == Kw::rainbow) read(v.item());
                continue;
            }
            switch (e.kw()) {
                case Kw::direction: r.direction = toVec3(e.args[0]); break;
                case Kw::angle: r.angle = toFloat(e.args[0]); break;
                case Kw::width: r.width = toFloat(e.args[0]); break;
                case Kw::distance: r.distance = toFloat(e.args[0]); break;
                case Kw::jitter: r.jitter = toFloat(e.args[0]); break;
                case Kw::up: r.up = toVec3(e.args[0]); break;
                case Kw::arc_angle: r.arcAngle = toFloat(e.args[0]); break;
                case Kw::falloff_angle: r.falloffAngle = toFloat(e.args[0]); break;
                case Kw::color_map: case Kw::colour_map:
                    r.map.clear();
                    for (const Entry& me : e.args[0].item().entries) {
                        if (me.key != kMapEntry || me.args.size() < 2) continue;
                        const double at = me.args[0].type == VType::Undefined ? 0 : toFloat(me.args[0]);
                        const Rgbft c = toColor(me.args[1]);
                        r.map.push_back({at, {c.rgb, c.filter, c.transmit}, -1});
                    }
                    break;
                default: break;
            }
        }
    };
    read(item);
    if (length(r.direction) == 0 || r.map.empty() || r.distance <= 0) return;
    r.direction = normalize(r.direction);
    scene_.pov.rainbows.push_back(std::move(r));
}

}  // namespace rays::pov

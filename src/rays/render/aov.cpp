#include "rays/render/aov.h"

#include <cmath>
#include <limits>

#include "rays/error.h"
#include "rays/image/parallel.h"
#include "rays/render/pov_pigment.h"
#include "rays/render/renderer.h"
#include "rays/render/texturing.h"
#include "rays/render/tracer.h"

namespace rays {
namespace {

constexpr AovBit kBits[] = {kAovDepth, kAovNormal, kAovAlbedo, kAovObjectId, kAovMaterialId, kAovCoverage, kAovEdgeType};

double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// The surface colour at the hit before lighting: the pigment (POV-Ray pattern, image map) or the
// material colour, in the EXR colour's units.
Vec3 albedoAt(const Scene& scene, const Hit& h, const Ray& ray) {
    const Vec3 P = ray.at(h.t);
    const Object& o = shadedObject(scene.objects, h);
    Vec3 C = o.material.color;
    const bool pov = scene.pov.enabled;
    if (pov && o.material.pov >= 0 && size_t(o.material.pov) < scene.povSurfaces.size()) {
        const PovSurface& s = scene.povSurfaces[size_t(o.material.pov)];
        // slope and aoi read the normal facing the viewer, as the render's pigment does.
        const Vec3 facing = dot(ray.dir, h.normal) < 0 ? h.normal : -h.normal;
        if (s.pigment >= 0) C = povPigmentAt(scene, s, P, facing, nullptr, ray.dir).color;
    }
    if (o.material.pigmentMap >= 0) {
        Vec3 N = h.normal;
        applyMaps(scene, o, P, SurfaceUV{h.hasUV, h.u, h.v, h.dpdu}, C, N);
    }
    return pov ? povLinearColor(C, scene.pov.assumedGamma) : C;
}

}  // namespace

unsigned parseAovList(const std::string& list) {
    unsigned bits = 0;
    size_t start = 0;
    while (start <= list.size()) {
        size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        std::string name = list.substr(start, end - start);
        for (char& c : name)
            if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        start = end + 1;
        if (name.empty() || name == "none") continue;
        if (name == "all") {
            bits |= kAovAll;
            continue;
        }
        unsigned bit = 0;
        for (AovBit b : kBits)
            if (name == aovName(b)) bit = b;
        if (name == "z") bit = kAovDepth;
        if (name == "n") bit = kAovNormal;
        if (bit == 0)
            throw Error("rays: error: unknown AOV '" + name +
                        "' (use depth, normal, albedo, objectid, materialid, coverage, edgetype or all)");
        bits |= bit;
    }
    return bits;
}

const char* aovName(AovBit bit) {
    switch (bit) {
        case kAovDepth: return "depth";
        case kAovNormal: return "normal";
        case kAovAlbedo: return "albedo";
        case kAovObjectId: return "objectid";
        case kAovMaterialId: return "materialid";
        case kAovCoverage: return "coverage";
        case kAovEdgeType: return "edgetype";
    }
    return "?";
}

Vec3 povLinearColor(Vec3 c, double assumedGamma) {
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const double v = std::max(c[i], 0.0);
        out[i] = assumedGamma > 0 ? (assumedGamma == 1 ? v : std::pow(v, assumedGamma)) : srgbDecode(v);
    }
    return out;
}

AovBuffers computeAovs(const Scene& scene, const Bvh& bvh, const RenderSettings& s, unsigned kinds) {
    AovBuffers a;
    a.width = s.width;
    a.height = s.height;
    const size_t n = size_t(s.width) * size_t(s.height);
    if (kinds & kAovDepth) a.depth.assign(n, std::numeric_limits<float>::infinity());
    if (kinds & kAovNormal) a.normal.assign(n, Vec3{});
    if (kinds & kAovAlbedo) a.albedo.assign(n, Vec3{});
    if (kinds & kAovObjectId) a.objectId.assign(n, -1.0f);
    if (kinds & kAovMaterialId) a.materialId.assign(n, -1.0f);
    if (!(kinds & (kAovDepth | kAovNormal | kAovAlbedo | kAovObjectId | kAovMaterialId))) return a;
    const ViewSetup view = resolveView(scene, s);
    const Tracer tracer(scene, bvh, s);
    parallelFor(s.height, s.threads, [&](int y) {
        for (int x = 0; x < s.width; ++x) {
            // The renderer's pixel (x, y from the top) is camera pixel (x, height − 1 − y).
            const Ray ray = cameraRayAt(view, x + 0.5, s.height - 1 - y + 0.5, s.width, s.height);
            if (CameraRays::missed(ray)) continue;
            const Hit h = tracer.firstHit(ray);
            if (!h.valid()) continue;
            const size_t i = size_t(y) * size_t(s.width) + size_t(x);
            const Object& o = shadedObject(scene.objects, h);
            if (!a.depth.empty()) a.depth[i] = float(h.t * length(ray.dir));
            if (!a.normal.empty()) a.normal[i] = normalize(h.normal);
            if (!a.albedo.empty()) a.albedo[i] = albedoAt(scene, h, ray);
            if (!a.objectId.empty()) a.objectId[i] = float(h.object);
            if (!a.materialId.empty()) a.materialId[i] = float(scene.pov.enabled ? o.material.pov : h.object);
        }
    });
    return a;
}

}  // namespace rays

#include "rays/render/texturing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/math/sampling.h"

namespace rays {

void mapCoordinates(int mapType, Vec3 p, double& u, double& v) {
    switch (mapType) {
        case 1: {
            const double r = length(p);
            u = std::atan2(p.z, p.x) / (2 * std::numbers::pi);
            v = r > 0 ? 0.5 + std::asin(std::clamp(p.y / r, -1.0, 1.0)) / std::numbers::pi : 0.5;
            break;
        }
        case 2:
            u = std::atan2(p.z, p.x) / (2 * std::numbers::pi);
            v = p.y;
            break;
        default:
            u = p.x;
            v = p.y;
    }
    if (u < 0 && mapType != 0) u += 1.0;
}

void mapDerivatives(int mapType, Vec3 p, Vec3& dPdu, Vec3& dPdv) {
    switch (mapType) {
        case 1:
        case 2: {
            dPdu = Vec3{-p.z, 0, p.x};  // around the y axis, toward +z from +x
            if (mapType == 2) {
                dPdv = Vec3{0, 1, 0};
            } else {
                const Vec3 radial = length(p) > 0 ? normalize(p) : Vec3{0, 1, 0};
                dPdv = cross(dPdu, radial);  // along the meridian, toward +y
                if (dPdv.y < 0) dPdv = -dPdv;
            }
            break;
        }
        default:
            dPdu = Vec3{1, 0, 0};
            dPdv = Vec3{0, 1, 0};
    }
}

void tangentFrame(Vec3 N, Vec3 dPdu, Vec3 dPdv, Vec3& T, Vec3& B) {
    Vec3 t = dPdu - dot(dPdu, N) * N;
    if (length(t) < 1e-9) {
        Vec3 b;
        orthonormalBasis(N, t, b);
    }
    T = normalize(t);
    B = cross(N, T);
    if (dot(B, dPdv) < 0) B = -B;
}

Vec3 decodeNormal(Vec3 texel) {
    Vec3 n;
    for (int c = 0; c < 3; ++c) n[c] = std::clamp((std::round(texel[c] * 255.0) - 128.0) / 127.0, -1.0, 1.0);
    return n;
}

void applyMaps(const Scene& scene, const Object& o, Vec3 P, const SurfaceUV& uv, Vec3& color, Vec3& N) {
    const Material& m = o.material;
    const Vec3 pObj = o.toObject.point(P);
    auto toTexture = [&](int xf) {
        return xf < 0 ? pObj : scene.textureTransforms[size_t(xf)].toTexture.point(pObj);
    };
    // Texture coordinates of a map: the mesh's own (uv mapping) or projected from texture space.
    auto coords = [&](int mapType, int xf, double& u, double& v) {
        if (mapType == 3) {
            u = uv.u;
            v = uv.v;
            if (xf >= 0) {  // a transform in the block moves the uv plane
                const Vec3 q = scene.textureTransforms[size_t(xf)].toTexture.point(Vec3{u, v, 0});
                u = q.x;
                v = q.y;
            }
        } else {
            mapCoordinates(mapType, toTexture(xf), u, v);
        }
    };
    if (m.pigmentMap >= 0) {
        double u, v;
        coords(m.mapType, m.pigmentTransform, u, v);
        const bool outside = u < 0 || u >= 1 || v < 0 || v >= 1;
        if (!(m.mapOnce && outside)) color = scene.textures[size_t(m.pigmentMap)].sample(u, v, m.mapBilinear);
    }
    const int map = m.normalMap >= 0 ? m.normalMap : m.bumpMap;
    if (map < 0) return;
    const Texture& tex = scene.textures[size_t(map)];
    const Vec3 p = toTexture(m.normalTransform);
    double u, v;
    coords(m.normalMapType, m.normalTransform, u, v);
    Vec3 du, dv;
    Transform toWorld = o.toObject.inverse();
    if (m.normalMapType == 3) {
        du = uv.dpdu;  // object space; the bitangent follows from N
        dv = cross(o.toObject.transposedVector(N), du);
    } else {
        mapDerivatives(m.normalMapType, p, du, dv);
        if (m.normalTransform >= 0) toWorld = toWorld * scene.textureTransforms[size_t(m.normalTransform)].toObject;
    }
    Vec3 T, B;
    tangentFrame(N, toWorld.vector(du), toWorld.vector(dv), T, B);
    if (m.normalMap >= 0) {
        const Vec3 n = decodeNormal(tex.sample(u, v, true));
        if (n.x == 0 && n.y == 0) return;  // flat texel: the geometric normal exactly
        N = normalize(m.normalStrength * (n.x * T + n.y * B) + n.z * N);
    } else {
        // Height slope per 1/32 of the image (heights are grey levels 0..1), by central
        // differences one texel apart.
        auto h = [&](double uu, double vv) { const Vec3 c = tex.sample(uu, vv, true); return (c.x + c.y + c.z) / 3; };
        const double eu = 1.0 / tex.width, ev = 1.0 / tex.height;
        const double gu = (h(u + eu, v) - h(u - eu, v)) / (2 * eu) / 32.0;
        const double gv = (h(u, v + ev) - h(u, v - ev)) / (2 * ev) / 32.0;
        if (gu == 0 && gv == 0) return;
        N = normalize(N - m.bumpSize * (gu * T + gv * B));
    }
}

}  // namespace rays

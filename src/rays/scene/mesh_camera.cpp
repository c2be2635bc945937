#include "rays/scene/mesh_camera.h"

#include <algorithm>

namespace rays {

MeshCamera::FaceRef MeshCamera::faceAt(int k, uint64_t ix, uint64_t iy, int width) const {
    const size_t meshes = meshCount();
    auto inMesh = [&](size_t m, uint64_t index) {
        const size_t begin = m == 0 ? 0 : meshEnd[m - 1];
        return index < meshEnd[m] - begin ? FaceRef{m, size_t(index)} : FaceRef{};
    };
    switch (distribution) {
        case Distribution::PerMesh:
            return size_t(k) < meshes ? inMesh(size_t(k), iy * uint64_t(width) + ix) : FaceRef{};
        case Distribution::Summed: {
            const uint64_t index = iy * uint64_t(width) + ix;
            if (meshes == 0 || index >= meshEnd.back()) return {};
            const size_t m = size_t(std::upper_bound(meshEnd.begin(), meshEnd.end(), size_t(index)) - meshEnd.begin());
            return inMesh(m, index - (m == 0 ? 0 : meshEnd[m - 1]));
        }
        case Distribution::Strips: {
            if (meshes == 0) return {};
            const uint64_t strip = std::max<uint64_t>(uint64_t(width) / meshes, 1);
            return inMesh(std::min<size_t>(size_t(ix / strip), meshes - 1), iy * strip + ix);
        }
        case Distribution::Uv: break;
    }
    return {};
}

bool MeshCamera::ray(int k, double px, double py, int width, int height, Ray& out) const {
    const double x = std::clamp(px, 0.0, double(width - 1));
    const double y = std::clamp(double(height) - py - 1.0, 0.0, double(height - 1));
    if (distribution != Distribution::Uv) {
        const FaceRef f = faceAt(k, uint64_t(x), uint64_t(y), width);
        if (f.mesh >= placements.size()) return false;
        const MeshCameraPlacement& at = placements[f.mesh];
        const MeshCameraFace& face = faces[at.first + f.index];
        out = rayFrom(at.toWorld.point(face.centroid), normalize(at.toObject.transposedVector(face.normal)));
        return true;
    }
    double w[3];
    const int64_t f = uvGrid.find((x - 0.5) / width, 1.0 - (y + 0.5) / height, w);
    if (f < 0) return false;
    const MeshCameraUvFace& face = uvFaces[size_t(f)];
    const Vec3 p = w[0] * face.p[0] + w[1] * face.p[1] + w[2] * face.p[2];
    Vec3 n = face.normal;
    if (smooth) {
        const Vec3 s = w[0] * face.n[0] + w[1] * face.n[1] + w[2] * face.n[2];
        if (length(s) > 0) n = normalize(s);
    }
    out = rayFrom(p, n);
    return true;
}

size_t MeshCamera::memoryBytes() const {
    return faces.capacity() * sizeof(MeshCameraFace) + placements.capacity() * sizeof(MeshCameraPlacement) +
           uvFaces.capacity() * sizeof(MeshCameraUvFace) +
           meshEnd.capacity() * sizeof(size_t) + uvGrid.memoryBytes();
}

}  // namespace rays

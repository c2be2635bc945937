// POV-Ray 3.7's mesh_camera: each pixel's rays start on faces of meshes and follow the faces'
// normals (POV-Ray 3.7's documentation of the camera, in its changelog's "Mesh Camera"; what it
// leaves open measured from POV-Ray 3.7.0.10 renders: docs/povray-language.md, "Mesh camera").
//
// Pixels map to faces by POV-Ray's pixel coordinates x = the sample's distance from the left
// edge and y = its distance from the top less one pixel, each clamped into [0, size − 1]
// (measured: the top two rows show the first row of faces, the bottom row of faces is never
// shown, and distribution 3's uv is (x − ½)/W, 1 − (y + ½)/H). Distributions 0–2 take the face
// numbered W·int(y) + int(x):
//   0  ray k of a pixel from mesh k (rays_per_pixel rays, at most one per mesh);
//   1  the meshes' faces counted as one list (POV-Ray 3.7.0.10 shoots only the pixel's own face
//      whatever rays_per_pixel says: measured);
//   2  the image split into as many strips of W / meshes pixels as there are meshes, mesh m
//      taking the face numbered strip width · int(y) + int(x), x counted from the image's left
//      edge (measured);
//   3  the first face whose uv triangle holds the pixel's uv, the ray starting at that point.
// A ray starts at the face's centroid (0–2) or uv point (3), moved `offset` along the face's
// normal, and follows the normal (interpolated from the corners' normals with smooth), reversed
// when the camera's direction points to −z. A ray with no face is not shot: it does not count in
// the pixel's average, and a pixel with none is black.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rays/geometry/ray.h"
#include "rays/math/transform.h"
#include "rays/math/vec3.h"
#include "rays/scene/uv_face_grid.h"

namespace rays {

/// A face of distributions 0–2 in its mesh's own space: where its ray starts and its normal
/// (c − a) × (b − a), not unit, both before the mesh's transformation.
struct MeshCameraFace {
    Vec3 centroid;
    Vec3 normal;
};

/// One mesh of distributions 0–2: its faces, a stretch of MeshCamera::faces that every copy of one
/// declared mesh shares (100 translated copies of a 19,200-face mesh keep one set of faces), and
/// the copy's transformation (toObject: its inverse, which turns normals).
struct MeshCameraPlacement {
    size_t first = 0, count = 0;
    Transform toWorld, toObject;
};

/// A face of distribution 3 in world space: corners, and the corners' unit normals (the face's
/// normal at each corner when the mesh has none). Its uvs are in MeshCamera::uvGrid.
struct MeshCameraUvFace {
    Vec3 p[3];
    Vec3 n[3];
    Vec3 normal;  ///< the face's unit normal
};

struct MeshCamera {
    enum class Distribution : uint8_t { PerMesh = 0, Summed = 1, Strips = 2, Uv = 3 };

    int raysPerPixel = 1;
    Distribution distribution = Distribution::PerMesh;
    double maxDistance = kInfinity;  ///< camera rays meet nothing farther (max_distance)
    bool smooth = false;             ///< distribution 3: normals interpolated over the face
    double offset = 0;               ///< the ray's origin moved this far along the normal
    bool reversed = false;           ///< rays against the normal

    std::vector<MeshCameraFace> faces;            ///< distributions 0–2: each distinct mesh's faces
    std::vector<MeshCameraPlacement> placements;  ///< distributions 0–2: the meshes, in order
    std::vector<MeshCameraUvFace> uvFaces;        ///< distribution 3: every mesh's faces in world space, mesh after mesh
    std::vector<size_t> meshEnd;                  ///< one past each mesh's last face, the meshes' faces counted as one list
    UvFaceGrid uvGrid;                      ///< distribution 3: the faces' uvs

    size_t meshCount() const { return meshEnd.size(); }
    /// Rays each pixel sample takes (rays_per_pixel for distribution 0, else 1).
    int raysShot() const { return distribution == Distribution::PerMesh ? raysPerPixel : 1; }

    /// Ray k (< raysShot()) of the sample at (px, py) in pixel units, py counted up from the
    /// bottom row; false when that ray has no face (it is not shot).
    bool ray(int k, double px, double py, int width, int height, Ray& out) const;

    size_t memoryBytes() const;

private:
    struct FaceRef {
        size_t mesh = SIZE_MAX, index = 0;  ///< mesh SIZE_MAX: no face
    };
    /// Distributions 0–2: the face of ray k at POV-Ray's integer pixel (ix, iy): its mesh and its
    /// number within the mesh.
    FaceRef faceAt(int k, uint64_t ix, uint64_t iy, int width) const;
    Ray rayFrom(Vec3 origin, Vec3 normal) const {
        return Ray{origin + offset * normal, reversed ? -normal : normal};
    }
};

}  // namespace rays

// SceneBuilder's mesh_camera: the block's numbers, flags and meshes → MeshCamera (scene/mesh_camera.h).
// POV-Ray 3.7's changelog, "Mesh Camera": mesh_camera { rays_per_pixel distribution_type
// [max_distance] mesh { M [TRANSFORMATIONS] } ... [smooth] }. Its errors are POV-Ray 3.7.0.10's
// (measured), each at the mesh_camera keyword.
#include <string>

#include "rays/error.h"
#include "rays/pov/build_mesh.h"
#include "rays/pov/grammar.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/scene_builder_parts.h"

namespace rays::pov {

using sdl::VType;

namespace {

constexpr double kPovEpsilon = 1e-10;  // POV-Ray's EPSILON: max_distance above it limits the rays

Vec3 vertex(const std::vector<float>& v, uint32_t i) {
    return Vec3(v[3 * size_t(i)], v[3 * size_t(i) + 1], v[3 * size_t(i) + 2]);
}

}  // namespace

std::shared_ptr<MeshCamera> SceneBuilder::meshCamera(const Item& block, const sdl::Loc& at) {
    auto fail = [&](const std::string& what) { throw Error(notes_.where(at) + ": error: " + what); };
    const std::vector<const Value*> numbers = positionals(block);
    if (numbers.size() < 2) fail("mesh_camera needs its rays per pixel and distribution type");
    if (numbers.size() > 3) fail("mesh_camera takes at most three numbers (rays per pixel, distribution type, max distance)");
    auto mc = std::make_shared<MeshCamera>();
    // Both are read as integers (measured: 1.7 rays per pixel are 1, distribution 0.6 is 0).
    const double rays = toFloat(*numbers[0]), distribution = toFloat(*numbers[1]);
    if (!(rays >= 1)) fail("mesh_camera: rays per pixel may not be 0");
    if (!(distribution >= 0 && distribution < 4)) fail("mesh_camera: unrecognized distribution method (0 to 3)");
    mc->raysPerPixel = clampedInt(rays, 1, 1 << 20);
    mc->distribution = MeshCamera::Distribution(int(distribution));
    if (numbers.size() > 2 && toFloat(*numbers[2]) > kPovEpsilon) mc->maxDistance = toFloat(*numbers[2]);
    std::vector<double> uvs;  // distribution 3: six per face
    std::vector<CameraMeshShape> shapes;
    for (const Entry& e : block.entries) {
        if (e.positional() || e.key == kMapEntry) continue;
        if (e.kw() == Kw::smooth) mc->smooth = true;
        if ((e.kw() == Kw::mesh || e.kw() == Kw::mesh2) && !e.args.empty() && e.args[0].type == VType::Item)
            addCameraMesh(*mc, uvs, shapes, e.args[0].item());
    }
    const bool uv = mc->distribution == MeshCamera::Distribution::Uv;
    if (uv) mc->uvGrid = UvFaceGrid(std::move(uvs));
    if (mc->meshCount() == 0) fail("mesh_camera needs a mesh or mesh2");
    if (mc->distribution == MeshCamera::Distribution::PerMesh && size_t(mc->raysPerPixel) > mc->meshCount())
        fail("mesh_camera: rays per pixel must be <= number of meshes for distribution method #0");
    if ((uv || mc->distribution == MeshCamera::Distribution::Strips) && mc->raysPerPixel != 1)
        fail("mesh_camera: rays per pixel must be 1 for distribution method #2 or #3");
    if (mc->smooth && !uv) fail("mesh_camera: smooth can only be used with distribution method #3");
    return mc;
}

// One mesh of a mesh_camera. A face's normal is POV-Ray's: (c − a) × (b − a) for corners a, b, c
// (measured: the face <0,1,0>, <1,-1,0>, <-1,-1,0> looks to +z), turned into world space as a
// normal (measured: `scale <1,1,-1>` on that face looks to −z, `scale <-1,1,1>` to +z).
// Distributions 0–2 keep the faces in the mesh's own space, once for all copies of one declared
// mesh (their entries are the same), and a placement per copy; distribution 3 keeps every mesh's
// faces in world space for its uv look-up.
void SceneBuilder::addCameraMesh(MeshCamera& mc, std::vector<double>& uvs, std::vector<CameraMeshShape>& shapes,
                                 const Item& item) {
    std::vector<const Entry*> entries;
    Item m;
    m.kind = unrollObject(item, entries, 0);
    m.loc = item.loc;
    Transform toWorld;
    std::vector<const Entry*> shape;
    for (const Entry* e : entries) {
        if (isTransformEntry(*e))
            applyTransform(*e, toWorld);
        else
            shape.push_back(e);
    }
    if (!toWorld.isUsable())
        throw Error(notes_.where(item.loc) + ": error: the camera mesh's transformation overflows or is singular");
    const Transform toObject = toWorld.inverse();
    const bool uv = mc.distribution == MeshCamera::Distribution::Uv;
    if (!uv)
        for (const CameraMeshShape& known : shapes)
            if (known.entries == shape) {
                mc.placements.push_back(MeshCameraPlacement{known.first, known.count, toWorld, toObject});
                mc.meshEnd.push_back((mc.meshEnd.empty() ? 0 : mc.meshEnd.back()) + known.count);
                return;
            }
    for (const Entry* e : shape) m.entries.push_back(*e);
    std::string problem;
    const std::unique_ptr<Mesh> mesh = meshFromItem(m, problem);
    if (!mesh) throw Error(notes_.where(item.loc) + ": error: " + problem);
    countObjects(mesh->triangleCount(), item.loc);
    const size_t first = mc.faces.size();
    for (size_t t = 0; t < mesh->triangleCount(); ++t) {
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = vertex(mesh->positions, mesh->indices[3 * t + size_t(k)]);
        const Vec3 faceNormal = cross(p[2] - p[0], p[1] - p[0]);
        if (!uv) {
            if (length(faceNormal) > 0)  // no area: no face (as a mesh's empty triangles)
                mc.faces.push_back(MeshCameraFace{(p[0] + p[1] + p[2]) / 3.0, faceNormal});
            continue;
        }
        const Vec3 n = toObject.transposedVector(faceNormal);
        if (!(length(n) > 0)) continue;
        const Vec3 normal = normalize(n);
        for (Vec3& q : p) q = toWorld.point(q);
        MeshCameraUvFace f{{p[0], p[1], p[2]}, {normal, normal, normal}, normal};
        if (mesh->hasNormals())
            for (int k = 0; k < 3; ++k) {
                const Vec3 vn = toObject.transposedVector(vertex(mesh->normals, mesh->normalIndices[3 * t + size_t(k)]));
                if (length(vn) > 0) f.n[k] = normalize(vn);
            }
        mc.uvFaces.push_back(f);
        for (int k = 0; k < 3; ++k) {  // a mesh without uvs gives faces that are never found
            const size_t i = mesh->hasUVs() ? mesh->uvIndices[3 * t + size_t(k)] : 0;
            uvs.push_back(mesh->hasUVs() ? mesh->uvs[2 * i] : 0.0);
            uvs.push_back(mesh->hasUVs() ? mesh->uvs[2 * i + 1] : 0.0);
        }
    }
    if (uv) {
        mc.meshEnd.push_back(mc.uvFaces.size());
        return;
    }
    const size_t count = mc.faces.size() - first;
    mc.placements.push_back(MeshCameraPlacement{first, count, toWorld, toObject});
    mc.meshEnd.push_back((mc.meshEnd.empty() ? 0 : mc.meshEnd.back()) + count);
    shapes.push_back(CameraMeshShape{std::move(shape), first, count});
}

}  // namespace rays::pov

#include "rays/render/course_commands.h"

#include <cstdio>
#include <string>

#include "rays/image/image.h"
#include "rays/render/pov_output.h"
#include "rays/render/tracer.h"
#include "rays/scene/mesh.h"
#include "rays/scene/object_transform.h"

namespace rays {
namespace {

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

std::string vec(Vec3 v) { return "{" + num(v.x) + " " + num(v.y) + " " + num(v.z) + "}"; }

std::string bytes(Vec3 c) {
    return "(" + std::to_string(toByte(c.x)) + ", " + std::to_string(toByte(c.y)) + ", " +
           std::to_string(toByte(c.z)) + ")";
}

// A pixel's colour as the rendered image has it: POV-Ray scenes are encoded on output
// (sRGB of c^assumed_gamma, pov_output.h), course scenes are written as traced.
Vec3 imageColor(const Scene& scene, Vec3 c) {
    return scene.pov.enabled ? povOutputColor(c, scene.pov.assumedGamma) : c;
}

// The lighting model the pixel was shaded with: POV-Ray scenes are lit as POV-Ray 3.7 lights them
// (docs/povray-lighting.md) whatever the shading option says.
const char* lightingName(const Scene& scene, const RenderSettings& s) {
    return scene.pov.enabled ? "POV-Ray 3.7" : shadingName(s.shading);
}

Ray pixelRay(const Scene& scene, const RenderSettings& s, int x, int y) {
    return scene.cameras.at(size_t(s.cameraIndex)).rayThrough(x + 0.5, y + 0.5, s.width, s.height);
}

void pixelLine(std::ostream& out, int x, int y, const Ray& r) {
    out << "Pixel: [" << x << ", " << y << "] Ray: " << vec(r.origin) << " -> " << vec(r.dir) << "\n";
}

void printMaterial(std::ostream& out, const Material& m) {
    out << "- Material:\n";
    out << "  - Ambient: " << num(m.ambient) << "\n";
    out << "  - Diffuse: " << num(m.diffuse) << "\n";
    if (m.hasSpecular) out << "  - Specular: " << num(m.specular) << "\n";
    if (m.hasRoughness) out << "  - Roughness: " << num(m.roughness) << "\n";
    if (m.hasReflection) out << "  - Reflection: " << num(m.reflection) << "\n";
    if (m.hasRefraction) out << "  - Refraction: " << num(m.refraction) << "\n";
    if (m.hasIor) out << "  - IOR: " << num(m.ior) << "\n";
    if (m.hasMetallic) out << "  - Metallic: " << num(m.metallic) << "\n";
}

void printObject(std::ostream& out, const Object& o) {
    out << "- Type: " << shapeName(o.type) << "\n";
    switch (o.type) {
        case ShapeType::Sphere:
            out << "- Center: " << vec(o.p0) << "\n- Radius: " << num(o.r0) << "\n";
            break;
        case ShapeType::Plane:
            out << "- Normal: " << vec(o.p0) << "\n- Distance: " << num(o.r0) << "\n";
            break;
        case ShapeType::Triangle:
            out << "- Vertex 0: " << vec(o.p0) << "\n- Vertex 1: " << vec(o.p1) << "\n- Vertex 2: " << vec(o.p2)
                << "\n";
            break;
        case ShapeType::Box:
            out << "- Min: " << vec(o.p0) << "\n- Max: " << vec(o.p1) << "\n";
            break;
        case ShapeType::Mesh:
            out << "- Triangles: " << o.mesh->triangleCount() << "\n";
            break;
        case ShapeType::Csg: case ShapeType::Text:
            break;
        case ShapeType::Cone:
            out << "- Base: " << vec(o.p0) << "\n- Base Radius: " << num(o.r0) << "\n- Cap: " << vec(o.p1)
                << "\n- Cap Radius: " << num(o.r1) << "\n";
            break;
        default: break;  // the POV-Ray shapes (scene/shapes) print their type only
    }
    if (o.transformed) {  // the shape above is in object space; M maps it into the world
        const Transform m = objectToWorld(o);
        out << "- Transform (object to world):\n";
        out << "  - X axis: " << vec(m.vector({1, 0, 0})) << "\n";
        out << "  - Y axis: " << vec(m.vector({0, 1, 0})) << "\n";
        out << "  - Z axis: " << vec(m.vector({0, 0, 1})) << "\n";
        out << "  - Translation: " << vec(m.point({0, 0, 0})) << "\n";
    }
    out << "- Color: " << vec(o.material.color) << "\n";
    if (o.material.filter > 0) out << "- Filter: " << num(o.material.filter) << "\n";
    printMaterial(out, o.material);
}

const char* kindName(TraceRecord::Kind k) {
    switch (k) {
        case TraceRecord::Kind::Primary: return "Primary";
        case TraceRecord::Kind::Reflection: return "Reflection";
        case TraceRecord::Kind::Refraction: return "Refraction";
    }
    return "?";
}

// Labels are right-aligned in 17 columns, as in the course output.
void field(std::ostream& out, const char* label, const std::string& value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%17s", label);
    out << buf << " " << value << "\n";
}

}  // namespace

void printSceneInfo(std::ostream& out, const Scene& scene) {
    const Camera& c = scene.cameras.front();
    out << "Camera:\n";
    out << "- Location: " << vec(c.location) << "\n";
    out << "- Up: " << vec(c.up) << "\n";
    out << "- Right: " << vec(c.right) << "\n";
    out << "- Look at: " << vec(c.lookAt) << "\n";
    out << "\n---\n\n" << scene.lights.size() << " light(s)\n";
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        out << "\nLight[" << i << "]:\n";
        out << "- Location: " << vec(scene.lights[i].position) << "\n";
        out << "- Color: " << vec(scene.lights[i].color) << "\n";
    }
    out << "\n---\n\n" << scene.objects.size() << " object(s)\n";
    // Objects are numbered from 1, as printrays' "Hit Object: (ID #N ...)" numbers them (the
    // course's sceneinfo numbers from 0; its text comparison accepts integers ±1).
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        out << "\nObject[" << i + 1 << "]:\n";
        printObject(out, scene.objects[i]);
    }
}

void printPixelRay(std::ostream& out, const Scene& scene, const RenderSettings& s, int x, int y) {
    pixelLine(out, x, y, pixelRay(scene, s, x, y));
}

void printFirstHit(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& s, int x, int y) {
    const Ray r = pixelRay(scene, s, x, y);
    pixelLine(out, x, y, r);
    const Hit h = Tracer(scene, bvh, s).firstHit(r);
    if (!h.valid()) {
        out << "No Hit\n";
        return;
    }
    const Object& o = shadedObject(scene.objects, h);
    out << "T = " << num(h.t) << "\n";
    out << "Object Type: " << shapeName(o.type) << "\n";
    out << "Color: " << num(o.material.color.x) << " " << num(o.material.color.y) << " " << num(o.material.color.z)
        << "\n";
}

void printPixelColor(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& s, int x, int y) {
    const Ray r = pixelRay(scene, s, x, y);
    pixelLine(out, x, y, r);
    const Tracer tracer(scene, bvh, s);
    const Hit h = tracer.firstHit(r);
    if (!h.valid()) {
        out << "No Hit\n";
        return;
    }
    TraceContext ctx;
    const Vec3 c = tracer.tracePrimary(r, ctx);
    out << "T = " << num(h.t) << "\n";
    out << "Object Type: " << shapeName(scene.objects[size_t(h.object)].type) << "\n";
    out << "BRDF: " << lightingName(scene, s) << "\n";
    out << "Color: " << bytes(imageColor(scene, c)) << "\n";
}

void printRays(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& settings, int x, int y) {
    RenderSettings s = settings;
    s.maxDepth = kPrintRaysDepth;
    const Ray r = pixelRay(scene, s, x, y);
    std::vector<TraceRecord> log;
    TraceContext ctx;
    const Vec3 c = Tracer(scene, bvh, s).tracePrimary(r, ctx, &log);
    out << "Pixel: [" << x << ", " << y << "] Color: " << bytes(imageColor(scene, c)) << "\n";
    for (size_t i = 0; i < log.size(); ++i) {
        const TraceRecord& rec = log[i];
        out << "----\n";
        field(out, "Iteration type:", kindName(rec.kind));
        field(out, "Ray:", vec(rec.ray.origin) + " -> " + vec(rec.ray.dir));
        if (!rec.hit) {
            out << "  No intersection.\n";
        } else {
            const Object& o = scene.objects[size_t(rec.object)];
            if (o.transformed)
                field(out, "Transformed Ray:", vec(rec.objectRay.origin) + " -> " + vec(rec.objectRay.dir));
            field(out, "Hit Object:", "(ID #" + std::to_string(rec.object + 1) + " - " + std::string(shapeName(o.type)) + ")");
            field(out, "Intersection:", vec(rec.point) + " at T = " + num(rec.t));
            field(out, "Normal:", vec(rec.normal));
            field(out, "Final Color:", vec(rec.color));
            field(out, "Ambient:", vec(rec.ambient));
            field(out, "Diffuse:", vec(rec.diffuse));
            field(out, "Specular:", vec(rec.specular));
            field(out, "Reflection:", vec(rec.reflection));
            field(out, "Refraction:", vec(rec.refraction));
            field(out, "Contributions:", num(rec.wLocal) + " Local, " + num(rec.wReflection) + " Reflection, " +
                                             num(rec.wTransmission) + " Transmission");
        }
        if (rec.kind == TraceRecord::Kind::Refraction)
            field(out, "Extra Info:", rec.intoObject ? "into-object" : "into-air");
        // A blank line after every ray without children (the log is depth first).
        if (i + 1 == log.size() || log[i + 1].depth <= rec.depth) out << "\n";
    }
    out << "\n" << std::string(80, '-') << "\n\n";
}

}  // namespace rays

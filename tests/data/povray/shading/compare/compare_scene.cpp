// The scene of compare_scene.pov built in C++ (Rays cannot read POV-Ray files yet) and rendered by
// Rays' POV-Ray path; writes a binary PPM to stdout. Usage: compare_scene [WIDTH [FLAGS]]; FLAGS
// (default 15) switches the glass sphere's diffuse (1), phong (2), reflection (4) and fade (8), and
// 16 makes the first light a 5×5 area light. Built and run by compare.sh.
#include <cstdio>
#include <cstdlib>

#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/renderer.h"

using namespace rays;

namespace {

Object shape(ShapeType t, Vec3 p0, Vec3 p1, double r0) {
    Object o;
    o.type = t;
    o.p0 = p0;
    o.p1 = p1;
    o.r0 = r0;
    prepareObject(o, Transform{});
    return o;
}

void add(Scene& s, Object o, Vec3 C, double filter, const PovSurface& p) {
    o.material.color = C;
    o.material.filter = filter;
    o.material.pov = int(s.povSurfaces.size());
    s.povSurfaces.push_back(p);
    s.objects.push_back(o);
}

}  // namespace

int main(int argc, char** argv) {
    const int W = argc > 1 ? std::atoi(argv[1]) : 160, H = W * 3 / 4;
    const int flags = argc > 2 ? std::atoi(argv[2]) : 15;
    Scene s;
    s.pov.enabled = true;
    s.pov.background = {0.2, 0.3, 0.5};
    Camera c;
    c.location = {0, 1.2, -5};
    c.lookAt = {0, 1.2, 0};
    c.right = {4.0 / 3, 0, 0};
    c.up = {0, 1, 0};
    s.cameras.push_back(c);
    Light a;
    a.position = {-3, 5, -4};
    a.color = Vec3(1.2);
    if (flags & 16) {
        a.area = true;
        a.axis1 = {2, 0, 0};
        a.axis2 = {0, 0, 2};
        a.n1 = a.n2 = 5;
    }
    s.lights.push_back(a);
    Light b;
    b.parallel = true;
    b.position = {3, 4, -2};
    b.direction = normalize(b.pointAt - b.position);
    b.color = {0.3, 0.25, 0.2};
    s.lights.push_back(b);
    {
        PovSurface p;
        p.finish.ambient = Vec3(0.1);
        p.finish.diffuse = 0.7;
        add(s, shape(ShapeType::Plane, {0, 1, 0}, {}, 0), {0.8, 0.7, 0.6}, 0, p);
    }
    {
        PovSurface p;
        p.finish.ambient = Vec3(0);
        p.finish.diffuse = (flags & 1) ? 0.1 : 0;
        p.finish.phong = (flags & 2) ? 1 : 0;
        p.finish.phongSize = 80;
        if (flags & 4) {
            p.finish.reflectionMin = Vec3(0.05);
            p.finish.reflectionMax = Vec3(1);
            p.finish.reflectionFresnel = true;
            p.finish.conserveEnergy = true;
        }
        p.interior.ior = 1.5;
        p.interior.fadeDistance = (flags & 8) ? 2 : 0;
        p.interior.fadePower = 1001;
        p.interior.fadeColor = {0.5, 0.8, 0.6};
        add(s, shape(ShapeType::Sphere, {-0.6, 1, 0}, {}, 1), {0.9, 1, 0.9}, 0.9, p);
    }
    {
        PovSurface p;
        p.finish.ambient = Vec3(0.1);
        p.finish.diffuse = 0.6;
        p.finish.specular = 0.6;
        p.finish.roughness = 0.02;
        p.finish.metallic = 1;
        p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.2);
        p.finish.reflectionMetallic = 1;
        add(s, shape(ShapeType::Sphere, {1.5, 0.7, 2}, {}, 0.7), {0.9, 0.2, 0.1}, 0, p);
    }
    {
        PovSurface p;
        p.finish.ambient = Vec3(0.2);
        p.finish.diffuse = 0.5;
        p.finish.phong = 0.5;
        p.transmit = 0.6;
        add(s, shape(ShapeType::Box, {1.2, 0, -1.5}, {2.2, 0.8, -1.4}, 0), {0.2, 0.4, 1}, 0, p);
    }
    {
        PovSurface p;
        p.finish.ambient = Vec3(0.1);
        p.finish.diffuse = 0.6;
        p.finish.diffuseBack = 0.3;
        p.finish.brilliance = 2;
        p.finish.phong = 0.4;
        p.finish.phongSize = 20;
        add(s, shape(ShapeType::Sphere, {-2.2, 0.5, 1.5}, {}, 0.5), {0.3, 0.9, 0.3}, 0, p);
    }
    RenderSettings rs;
    rs.width = W;
    rs.height = H;
    rs.threads = 1;
    const Bvh bvh(s.objects);
    TraceStats stats;
    const Image8 img = toImage8(render(s, bvh, rs, stats));
    std::printf("P6\n%d %d\n255\n", W, H);
    std::fwrite(img.pixels.data(), 1, img.pixels.size(), stdout);
}

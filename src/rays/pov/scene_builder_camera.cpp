// SceneBuilder's camera: POV-Ray 3.7's camera items and projection types → Camera.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/error.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/scene_builder_parts.h"

namespace rays::pov {

using sdl::VType;

// ---- camera ----------------------------------------------------------------------------------
// POV-Ray 3.7 reference, "Placing the Camera": items apply in order, but angle sets the
// direction's length from the final right vector's, after them; look_at turns direction, right
// and up (right = sky × direction, keeping the handedness of the vectors before it), after the
// other items from #version 3.5 on; transformations move the location and turn the vectors after
// every other item, wherever they stand (measured with povray 3.7: `rotate`, `translate` or a
// shearing `matrix` before `location` or `look_at` give the same image as after).
// The camera's `normal { }`: a normal root in world space (camera rays are tilted by it as
// surface normals are; the camera's own transformations do not move it).
namespace {

// POV-Ray's adaptive focal blur (reference, "Focal Blur": sampling stops once the estimated colour
// is, with the given confidence, near the real colour, within the variance tolerance). Our reading:
// stop when z²·s²/n ≤ variance in every channel, z the two-sided normal quantile of the confidence
// (erf(z/√2) = confidence, solved by bisection). A confidence outside [0, 1) takes the default 0.9,
// as POV-Ray does with a warning. The minimum, when blur_samples gives none, is 16 samples
// (measured on camera/focalblur.pov against POV-Ray: SSIM 0.944 with 4, 0.965 with 8, 0.986 with 16,
// 0.976 taking every sample; fewer let edge pixels stop on samples that happen to agree).
void setAdaptiveBlur(Camera& c, double confidence, double variance) {
    if (c.aperture <= 0) return;
    if (!(confidence >= 0 && confidence < 1)) confidence = 0.9;
    double lo = 0, hi = 10;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erf(mid / std::numbers::sqrt2) < confidence ? lo : hi) = mid;
    }
    c.blurZ2 = std::max(1e-12, lo * lo);
    c.blurVariance = std::max(0.0, variance);
    if (c.blurMinSamples <= 0) c.blurMinSamples = 16;
    c.blurMinSamples = std::min(c.blurMinSamples, c.blurSamples);
}

}  // namespace

int SceneBuilder::cameraNormal(const Entry& e) {
    if (!pigments_.compilesNormals()) return -1;
    const int node = pigments_.compileNormal(e.args[0].item());
    if (node < 0) return -1;
    scene_.normals.roots.push_back(pattern::NormalRoot{Transform{}, Transform{}, node});
    return int(scene_.normals.roots.size()) - 1;
}

void SceneBuilder::addCamera(const Item& cam) {
    Vec3 loc{0, 0, 0}, dir{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
    Vec3 lookAt{0, 0, 1};  // POV-Ray's default look_at point (measured: orthographic's window size)
    Camera c;
    bool rightOrUpSet = false, angleSet = false;
    double angles[2] = {-1, -1};  // the angle values given (degrees; −1: none)
    double confidence = 0.9, variance = 1.0 / 128;  // focal blur's adaptive stop (reference defaults)
    std::vector<const Entry*> entries;
    std::function<void(const Item&)> collect = [&](const Item& it) {
        for (const Entry& e : it.entries) {
            if (e.positional() && !e.args.empty() && e.args[0].type == VType::Item && e.args[0].item().kind == Kw::camera)
                collect(e.args[0].item());
            else
                entries.push_back(&e);
        }
    };
    collect(cam);
    Transform moved;  // the camera's transformations, in file order
    const Entry* lastTransform = nullptr;
    const Entry* meshEntry = nullptr;  // mesh_camera and its block
    // look_at turns direction, right and up towards lookAt from loc, keeping their lengths.
    auto aim = [&](const Entry& e) {
        const double handed = dot(cross(up, dir), right);
        const double dl = length(dir), ul = length(up), rl = length(right);
        if (length(lookAt - loc) == 0) throw Error(notes_.where(e.loc) + ": error: look_at is the camera location");
        const Vec3 d = normalize(lookAt - loc);
        Vec3 r = cross(sky, d);
        if (length(r) < 1e-12 * length(sky)) {
            // Looking along the sky vector: POV-Ray keeps the right vector as written
            // (made perpendicular), mirrored below as any right vector is (measured with POV-Ray
            // 3.7 looking straight down: `right x` and `up z` show +z up and −x to the right,
            // `right -x*4/3` −z up and +x to the right).
            r = right - dot(right, d) * d;
            if (length(r) == 0) r = std::fabs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
        }
        r = normalize(r);
        dir = d * dl;
        up = normalize(cross(d, r)) * ul;
        right = r * (handed <= 0 ? -rl : rl);  // up × direction along right: left-handed; else (0 too) mirrored (measured)
    };
    // From #version 3.5 on, look_at is applied after every other item, with the final location,
    // sky and vectors (measured with POV-Ray 3.7: `direction`, `location`, `right` or `sky` written
    // after look_at give the image of the same items written before it); before 3.5 the items
    // apply in order.
    const bool lookAtLast = version_ >= 3.5;
    const Entry* lookAtEntry = nullptr;
    for (const Entry* ep : entries) {
        const Entry& e = *ep;
        if (e.positional()) continue;
        if (isTransformEntry(e)) {  // applied after every other item (measured: see above)
            applyTransform(e, moved);
            lastTransform = &e;
            continue;
        }
        switch (e.kw()) {
            case Kw::perspective: c.projection = Projection::Perspective; break;
            case Kw::orthographic: c.projection = Projection::Orthographic; break;
            case Kw::fisheye: c.projection = Projection::Fisheye; break;
            case Kw::ultra_wide_angle: c.projection = Projection::UltraWideAngle; break;
            case Kw::omnimax: c.projection = Projection::Omnimax; break;
            case Kw::panoramic: c.projection = Projection::Panoramic; break;
            case Kw::spherical: c.projection = Projection::Spherical; break;
            case Kw::cylinder: {
                const int type = clampedInt(toFloat(e.args[0]), 0, 5);
                if (type < 1 || type > 4) throw Error(notes_.where(e.loc) + ": error: cylinder camera type must be 1 to 4");
                c.projection = Projection(int(Projection::Cylinder1) + type - 1);
                break;
            }
            case Kw::mesh_camera:
                c.projection = Projection::Mesh;
                if (!e.args.empty() && e.args[0].type == VType::Item) meshEntry = &e;
                break;
            case Kw::location: loc = toVec3(e.args[0]); break;
            case Kw::direction: dir = toVec3(e.args[0]); break;
            case Kw::up: up = toVec3(e.args[0]); rightOrUpSet = true; break;
            case Kw::right: right = toVec3(e.args[0]); rightOrUpSet = true; break;
            case Kw::sky: sky = toVec3(e.args[0]); break;
            case Kw::angle: {
                angleSet = true;
                for (size_t i = 0; i < 2; ++i) angles[i] = i < e.args.size() ? toFloat(e.args[i]) : -1;
                break;
            }
            case Kw::look_at:
                lookAt = toVec3(e.args[0]);
                lookAtEntry = &e;
                if (!lookAtLast) aim(e);
                break;
            case Kw::focal_point: c.focalPoint = toVec3(e.args[0]); break;
            // The lens radius is a quarter of `aperture` (the reference calls its values arbitrary):
            // measured with POV-Ray 3.7 on the blurred edge of a wall behind the focal plane, the
            // circle of confusion is aperture/2 · |d − f| / d wide at any scale, zoom and image size.
            case Kw::aperture: c.aperture = 0.25 * toFloat(e.args[0]); break;
            case Kw::blur_samples:
                c.blurSamples = clampedInt(toFloat(e.args.back()), 0, 65536);
                if (e.args.size() > 1) c.blurMinSamples = clampedInt(toFloat(e.args[0]), 1, 65536);
                break;
            case Kw::confidence: confidence = toFloat(e.args[0]); break;
            case Kw::variance: variance = toFloat(e.args[0]); break;
            case Kw::normal: c.normal = cameraNormal(e); break;
            case Kw::bokeh: notes_.note("bokeh", e.loc); break;
            default: break;
        }
    }
    if (lookAtLast && lookAtEntry) aim(*lookAtEntry);
    // The angle sets the direction's length from the final right vector, wherever it is written
    // (measured with POV-Ray 3.7: `angle 35` before or after `right x*4/3`, before or after
    // `direction z*5`, or with `right x*2 up y*1.5`, gives the same image).
    if (angleSet && c.projection == Projection::Perspective && angles[0] > 0 && angles[0] < 180 && length(dir) > 0)
        dir = normalize(dir) * (0.5 * length(right) / std::tan(angles[0] * std::numbers::pi / 360.0));
    if (lastTransform) {
        loc = moved.point(loc);
        lookAt = moved.point(lookAt);
        dir = moved.vector(dir);
        up = moved.vector(up);
        right = moved.vector(right);
        auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        if (!finite(loc) || !finite(lookAt) || !finite(dir) || !finite(up) || !finite(right))
            throw Error(notes_.where(lastTransform->loc) +
                        ": error: the camera's transformation overflows (its vectors are no longer finite)");
    }
    double dl = length(dir);
    if (c.projection == Projection::Mesh && meshEntry) {
        // Only the z of location and direction count (POV-Ray 3.7's changelog, "Mesh Camera"):
        // how far along the face normal the rays start, and whether they go against it. Both are
        // taken after the camera's transformations (measured: `scale -1` or `rotate 180*y`
        // reverses the rays, `translate 20*z` starts them 20 units out); a zero direction is fine.
        std::shared_ptr<MeshCamera> mc = meshCamera(meshEntry->args[0].item(), meshEntry->loc);
        mc->offset = loc.z;
        mc->reversed = dir.z < -1e-10;
        c.mesh = std::move(mc);
        if (dl == 0) dl = 1;
    }
    if (dl == 0) throw Error(notes_.where(cam.loc) + ": error: the camera's direction is zero");
    c.location = loc;
    c.lookAt = loc + dir;
    c.right = right / dl;
    c.up = up / dl;
    if (c.projection != Projection::Perspective && c.projection != Projection::Mesh) finishProjection(c, dir, right, up, lookAt, rightOrUpSet, angleSet, angles);
    if (c.aperture > 0 && c.blurSamples == 0) c.blurSamples = 16;
    setAdaptiveBlur(c, confidence, variance);
    // A later camera replaces the one before (POV-Ray 3.7 reference, "Camera": the last one is
    // used; screen.inc's macros write a camera at each change).
    scene_.cameras.assign(1, c);
}

// The vectors and angles of the non-perspective projections, as measured from POV-Ray 3.7 renders.
// Orthographic: the window is right × up as written; with no right and up given, or with angle,
// it is the view of a perspective camera with the same vectors at the look_at point (whose default
// is <0,0,1>): right·dist/|direction|, or 2·dist·tan(angle/2) wide keeping up's aspect. The angle
// projections default to 90° (spherical: 360° × 180°; its vertical angle to half the horizontal).
void SceneBuilder::finishProjection(Camera& c, Vec3 dir, Vec3 right, Vec3 up, Vec3 lookAt, bool rightOrUpSet,
                                    bool angleSet, const double angles[2]) {
    constexpr double kDeg = std::numbers::pi / 180.0;
    if (c.projection == Projection::Orthographic) {
        if (angleSet || !rightOrUpSet) {
            double dist = length(lookAt - c.location);
            if (dist == 0) dist = 1;
            const double a = angles[0];
            if (a > 0 && a < 180) {
                const double w = 2 * dist * std::tan(0.5 * a * kDeg);
                up = normalize(up) * (w * length(up) / length(right));
                right = normalize(right) * w;
            } else {
                right = right * (dist / length(dir));
                up = up * (dist / length(dir));
            }
        }
        c.right = right;
        c.up = up;
        return;
    }
    c.right = right;
    c.up = up;
    const bool spherical = c.projection == Projection::Spherical;
    c.angleH = (angles[0] > 0 ? angles[0] : spherical ? 360 : 90) * kDeg;
    c.angleV = angles[1] > 0 ? angles[1] * kDeg : (angles[0] > 0 ? 0.5 * c.angleH : 180 * kDeg);
}

}  // namespace rays::pov

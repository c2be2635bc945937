// Pinhole camera in the course convention (right handed; right/up used exactly as written), and
// POV-Ray's other projections (orthographic, fisheye, ultra_wide_angle, panoramic, cylinder 1-4,
// spherical) as measured from POV-Ray 3.7 renders (docs/povray-language.md, "Camera"), and its
// mesh_camera (scene/mesh_camera.h).
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>

#include "rays/geometry/ray.h"
#include "rays/math/vec3.h"
#include "rays/scene/mesh_camera.h"

namespace rays {

/// How pixels map to rays. Perspective is the pinhole (course and POV-Ray); the others are
/// POV-Ray's camera types.
enum class Projection : uint8_t {
    Perspective, Orthographic, Fisheye, UltraWideAngle, Omnimax, Panoramic, Cylinder1, Cylinder2, Cylinder3,
    Cylinder4, Spherical, Mesh
};

struct Camera {
    Vec3 location{0, 0, 0};
    /// Perspective: image-plane vertical extent at unit distance (not normalised). Orthographic:
    /// the view window's height vector. Other projections: POV-Ray's up vector as written.
    Vec3 up{0, 1, 0};
    /// Like up, horizontally; |right|/|up| is the aspect ratio.
    Vec3 right{1.33333, 0, 0};
    Vec3 lookAt{0, 0, -1};
    double aperture = 0;      ///< lens radius (world units); 0 = pinhole
    Vec3 focalPoint{0, 0, 0}; ///< in perfect focus; the focal distance is measured along the view direction
    int blurSamples = 0;      ///< samples per pixel when aperture > 0 (0: renderer default)
    /// POV-Ray's adaptive focal blur (blur_samples MIN, MAX with confidence and variance): after
    /// blurMinSamples samples a pixel stops once z²·s²/n ≤ blurVariance in every channel (s² the
    /// samples' variance, z the normal quantile of the confidence). blurZ2 = 0: every sample is taken.
    int blurMinSamples = 0;
    double blurZ2 = 0;
    double blurVariance = 0;
    Projection projection = Projection::Perspective;
    double angleH = 0, angleV = 0;  ///< viewing angles (radians) of the angle-based projections
    std::shared_ptr<const MeshCamera> mesh;  ///< Projection::Mesh: the faces rays start from
    int normal = -1;  ///< POV-Ray's camera `normal`: a Scene::normals root tilting each camera ray (-1: none)

    /// Distance from location to the focal plane (along the view direction).
    double focalDistance() const { return dot(focalPoint - location, forward()); }

    /// Unit view direction l = normalize(look_at − location).
    Vec3 forward() const { return normalize(lookAt - location); }

    /// Ray through the centre of sub-pixel position (px, py) in pixel units, py counted up from the
    /// bottom row: u = px/W − ½, v = py/H − ½.
    Ray rayThrough(double px, double py, int width, int height) const;
};

/// A camera ready to generate many rays: the view direction is computed once (rayThrough of a
/// Camera computes it per ray). Rays are bit-identical to Camera::rayThrough's.
struct CameraRays {
    Vec3 location, right, up, forward;
    Projection projection = Projection::Perspective;
    Vec3 direction;            ///< look_at − location as given (panoramic's ellipsoid axis)
    Vec3 rightUnit, upUnit;    ///< normalised right and up (angle-based projections)
    double angleH = 0, angleV = 0, aspect = 1;  ///< aspect = |right| / |up|
    const MeshCamera* mesh = nullptr;           ///< Projection::Mesh (held by the Camera)

    explicit CameraRays(const Camera& c)
        : location(c.location), right(c.right), up(c.up), forward(c.forward()), projection(c.projection),
          direction(c.lookAt - c.location), angleH(c.angleH), angleV(c.angleV), mesh(c.mesh.get()) {
        if (projection == Projection::Perspective || projection == Projection::Mesh) return;
        rightUnit = normalize(right);
        upUnit = normalize(up);
        aspect = length(right) / length(up);
    }

    /// Ray through image-plane coordinates (u, v) in [−½, ½]², v up, for the sub-pixel position
    /// (px, py): u = px/W − ½, v = py/H − ½; perspective: direction = normalize(u·right + v·up +
    /// forward). A point outside the projection (fisheye's circle) gives a zero direction (missed()).
    Ray rayThrough(double px, double py, int width, int height) const {
        const double u = px / width - 0.5, v = py / height - 0.5;
        if (projection == Projection::Perspective) return Ray{location, normalize(u * right + v * up + forward)};
        if (projection == Projection::Mesh) return meshRay(0, px, py, width, height);
        return projected(u, v);
    }

    /// A mesh camera's ray k (< MeshCamera::raysShot()) of the sample at (px, py); a ray with no
    /// face gives a zero direction (missed()).
    Ray meshRay(int k, double px, double py, int width, int height) const {
        Ray r{location, Vec3{}};
        if (mesh && !mesh->ray(k, px, py, width, height, r)) r = Ray{location, Vec3{}};
        return r;
    }

    /// True for the ray of a point outside the projection (POV-Ray leaves those pixels black).
    static bool missed(const Ray& r) { return r.dir == Vec3{}; }

private:
    // POV-Ray's projections, measured from POV-Ray 3.7 renders of a direction-coloured sphere
    // (tests/pov_camera_test.cpp holds the measurements).
    Ray projected(double u, double v) const {
        switch (projection) {
            case Projection::Perspective: case Projection::Mesh: break;
            case Projection::Orthographic: return Ray{location + u * right + v * up, forward};
            case Projection::Fisheye: {
                // Polar: the distance from the centre (1 at the top edge) is angle/2 off the axis.
                const double x = 2 * u * aspect, y = 2 * v, r = std::sqrt(x * x + y * y);
                if (r > 1) return Ray{location, Vec3{}};
                if (r == 0) return Ray{location, forward};
                const double phi = r * 0.5 * angleH;
                return Ray{location, normalize(std::cos(phi) * forward + (std::sin(phi) / r) * (x * rightUnit + y * upUnit))};
            }
            case Projection::Omnimax: return omnimax(u, v);
            case Projection::UltraWideAngle: {
                const double ax = u * angleH, ay = v * angleH / aspect;
                return Ray{location, normalize(std::sin(ax) * rightUnit + std::sin(ay) * upUnit +
                                               std::cos(ax) * std::cos(ay) * forward)};
            }
            case Projection::Panoramic: {
                const double ax = u * kPi, ay = v * kPi;
                return Ray{location, normalize(std::cos(ay) * (std::sin(ax) * right + std::cos(ax) * direction) +
                                               std::sin(ay) * up)};
            }
            case Projection::Cylinder1: {
                const double ax = u * angleH;
                return Ray{location, normalize(std::sin(ax) * rightUnit + std::cos(ax) * forward + v * up)};
            }
            case Projection::Cylinder2: {
                const double ay = v * angleH;
                return Ray{location, normalize(std::sin(ay) * upUnit + std::cos(ay) * forward + u * right)};
            }
            case Projection::Cylinder3: {
                const double ax = u * angleH;
                return Ray{location + v * up, normalize(std::sin(ax) * rightUnit + std::cos(ax) * forward)};
            }
            case Projection::Cylinder4: {
                const double ay = v * angleH;
                return Ray{location + u * right, normalize(std::sin(ay) * upUnit + std::cos(ay) * forward)};
            }
            case Projection::Spherical: {
                const double ax = u * angleH, ay = v * angleV;
                return Ray{location, normalize(std::cos(ay) * (std::sin(ax) * rightUnit + std::cos(ax) * forward) +
                                               std::sin(ay) * upUnit)};
            }
        }
        return Ray{location, forward};
    }
    // Omnimax (measured): a fisheye of 180° whose angle off the axis grows with the distance r from
    // its centre as the odd quintic below (fitted to 50 measured angles, within 1e-4 rad). Images
    // wider than high (|right| > |up|) show the dome's frame: the top edge at the zenith, the bottom
    // 45° below the horizon (kFrame = 1 + r at 45°), the width |right|/|up| times the height;
    // others a circle of radius 1 across the width. Black outside r = 1 and below the dome's rim
    // (the great circle through the sides tilted 45° up: directions with d·(F + Û) < 0).
    Ray omnimax(double u, double v) const {
        constexpr double kFrame = 1.5583;
        const bool frame = aspect > 1;
        const double x = frame ? kFrame * aspect * u : 2 * u;
        const double y = frame ? kFrame * v + 1 - 0.5 * kFrame : 2 * v / aspect;
        const double r = std::sqrt(x * x + y * y);
        if (r > 1) return Ray{location, Vec3{}};
        if (r == 0) return Ray{location, forward};
        const double r2 = r * r, phi = r * (1.41131714 + r2 * (-0.09455797 + r2 * 0.25687244));
        const double c = std::cos(phi), s = std::sin(phi) / r;
        if (c + s * y < 0) return Ray{location, Vec3{}};
        return Ray{location, normalize(c * forward + s * (x * rightUnit + y * upUnit))};
    }
    static constexpr double kPi = 3.14159265358979323846;
};

inline Ray Camera::rayThrough(double px, double py, int width, int height) const {
    return CameraRays(*this).rayThrough(px, py, width, height);
}

}  // namespace rays

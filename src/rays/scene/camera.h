// Pinhole camera in the course convention (right handed; right/up used exactly as written).
#pragma once
#include "rays/geometry/ray.h"
#include "rays/math/vec3.h"

namespace rays {

struct Camera {
    Vec3 location{0, 0, 0};
    Vec3 up{0, 1, 0};         ///< image-plane vertical extent (not normalised)
    Vec3 right{1.33333, 0, 0};///< image-plane horizontal extent; |right|/|up| is the aspect ratio
    Vec3 lookAt{0, 0, -1};
    double aperture = 0;      ///< lens radius (world units); 0 = pinhole
    Vec3 focalPoint{0, 0, 0}; ///< in perfect focus; the focal distance is measured along the view direction
    int blurSamples = 0;      ///< samples per pixel when aperture > 0 (0: renderer default)

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

    explicit CameraRays(const Camera& c) : location(c.location), right(c.right), up(c.up), forward(c.forward()) {}

    /// Ray through image-plane coordinates (u, v) in [−½, ½]², v up, for the sub-pixel position
    /// (px, py): u = px/W − ½, v = py/H − ½; direction = normalize(u·right + v·up + forward).
    Ray rayThrough(double px, double py, int width, int height) const {
        const double u = px / width - 0.5, v = py / height - 0.5;
        return Ray{location, normalize(u * right + v * up + forward)};
    }
};

inline Ray Camera::rayThrough(double px, double py, int width, int height) const {
    return CameraRays(*this).rayThrough(px, py, width, height);
}

}  // namespace rays

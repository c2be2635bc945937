// POV-Ray's isosurface (reference 3.4.5.1.6): the surface where a user function f(x, y, z) equals
// Object::r1 (the threshold), inside where f is below it, cut by a container (a box Object::p0 to
// p1, or a sphere of centre p0 and radius r0) whose faces are drawn where the function is inside,
// unless Object::open. data->function is the compiled function (rays/fn); data->values holds
// {accuracy, max_gradient, 1 for a sphere container else 0}; data->bounds the container's box.
#pragma once
#include <memory>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// Values of an isosurface as written (the reference's defaults).
struct IsosurfaceSpec {
    std::shared_ptr<const fn::Program> function;  ///< f(x, y, z): 3 or more parameters, further ones 0
    bool sphere = false;           ///< contained_by sphere (else box)
    Vec3 lo{-1, -1, -1}, hi{1, 1, 1};  ///< the box's corners
    Vec3 centre;                   ///< the sphere's centre
    double radius = 1;             ///< the sphere's radius
    double threshold = 0;
    double accuracy = 0.001;
    double maxGradient = 1.1;
    bool open = false;
};

/// Fills o's shape fields and data from spec; false when the container is empty.
bool makeIsosurface(const IsosurfaceSpec& spec, Object& o, ShapeData& data);
/// f − threshold at object-space point p (negative inside).
double isosurfaceValue(const Object& o, Vec3 p);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward unit normal.
bool hitIsosurface(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is inside the container and the function below the threshold.
bool insideIsosurface(const Object& o, Vec3 p);

}  // namespace rays

// POV-Ray's julia_fractal (reference 3.4.5.1.7 "Julia Fractal"): the 3-D slice of a 4-D Julia set
// of h ← f(h) + p in the quaternions (f = sqr or cube) or the hypercomplex numbers (f = sqr, cube,
// exp, reciprocal, sin, ..., ln, pwr(X, Y)). A point (x, y, z) is h(0) = (x, y, z, t) with t from
// the slice: n·h = d for the slice's unit normal n (its 4th component must not be 0, as POV-Ray
// requires). Inside when none of h(1) ... h(max_iteration − 1) leaves the escape sphere. As
// measured with POV-Ray 3.7.0.10's trace(): the escape radius is 1 + |p| for quaternions and 4
// for hypercomplex numbers; hypercomplex `cube` iterates as `sqr`; max_iteration 1 draws nothing;
// the normal is the gradient of |h(max_iteration)| (one iteration past the test).
// data->values: p (4), the slice's normal n (4) and d, max_iteration, the march step
// 1/precision, the escape radius squared, the algebra (0 quaternion, 1 hypercomplex), the function
// (JuliaFunction) and pwr's X and Y; data->bounds the escape sphere's box.
#pragma once
#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// The iterated function (reference's FUNCTION_TYPE keywords, in this order).
enum class JuliaFunction { Sqr, Cube, Exp, Reciprocal, Sin, Asin, Sinh, Asinh, Cos, Acos, Cosh, Acosh, Tan, Atan,
                           Tanh, Atanh, Ln, Pwr };

/// The julia fractal's parameters (defaults as the reference gives them).
struct JuliaParams {
    double p[4] = {0, 0, 0, 0};
    bool hypercomplex = false;
    JuliaFunction function = JuliaFunction::Sqr;
    int maxIteration = 20;
    double precision = 20;
    double slice[4] = {0, 0, 0, 1};
    double distance = 0;
    double pwr[2] = {0, 0};
};

/// Fills data from the parameters; false when there is nothing to draw (max_iteration below 2, a
/// quaternion function other than sqr and cube, a precision not above 0). The slice's normal
/// must have a non-zero 4th component (the caller reports it).
bool makeJuliaFractal(const JuliaParams& params, ShapeData& data);
/// Nearest crossing of the fractal's surface by the object-space ray with t in (tMin, tMax),
/// found by steps of 1/precision from tMin (or the escape sphere) and bisection: t and the outward normal.
bool hitJuliaFractal(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is inside.
bool insideJuliaFractal(const Object& o, Vec3 p);

}  // namespace rays

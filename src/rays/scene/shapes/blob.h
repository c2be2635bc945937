// POV-Ray's blob (reference 3.4.5.1.1): the surface where the sum of the components' fields
// equals the threshold (Object::r0); inside where it is greater. A component of strength s and
// radius R adds s·(1 − (d/R)²)² where d < R, d being the distance to a sphere's centre or to a
// cylinder's axis segment (hemispherical ends), measured in the component's own space (its
// transformations make ellipsoids). data->values holds kBlobStride numbers per component (see
// blob.cpp) in the order of data->tree's leaves (a box tree over the components); data->parts the
// component textures' objects; data->bounds the positive components' box.
#pragma once
#include <vector>

#include "rays/math/transform.h"
#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// One blob component as written, in the blob's object space.
struct BlobComponent {
    bool cylinder = false;
    Vec3 a, b;          ///< the centre; a cylinder's ends
    double radius = 0;
    double strength = 0;
    Transform toBlob;   ///< the component's own transformations (component → blob space)
    int part = -1;      ///< its texture's index in ShapeData::parts, or -1 (the blob's)
};

/// The blob's numbers from its components; false when no component can reach the threshold (no
/// positive strength, a zero radius everywhere).
bool makeBlob(const std::vector<BlobComponent>& components, ShapeData& data);
/// The field at object-space point p.
double blobField(const ShapeData& data, Vec3 p);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t, the outward normal (minus the
/// field's gradient) and, when the component adding most field there has its own texture, its part.
bool hitBlob(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside (the field above the threshold).
bool insideBlob(const Object& o, Vec3 p);

}  // namespace rays

// POV-Ray's polynomial surfaces (reference 3.4.5.3.2–3.4.5.3.6: poly, cubic, quartic, quadric,
// polynomial): the points where p(x, y, z) = 0, inside where p < 0. data->order is the degree N
// and data->values the coefficients in POV-Ray's order: the terms x^i y^j z^k with i + j + k ≤ N
// by falling i, then falling j, then falling k (A1 = x^N, A2 = x^(N−1) y, …, the last = 1).
// Unbounded: data->bounds is empty unless set.
#pragma once
#include <memory>
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// A degree-n surface from its coefficients in POV-Ray's order (missing ones 0). Its values are the
/// coefficients, then the plan the ray test walks: the number of groups, then per group of terms
/// x^i y^j with a nonzero coefficient i, j, their count and (k, a) for each term a·x^i y^j z^k,
/// in the coefficients' order.
std::unique_ptr<ShapeData> makePolySurface(int n, const std::vector<double>& coef);
/// Number of coefficients of a degree-n poly: (n + 1)(n + 2)(n + 3) / 6.
int polyTermCount(int n);
/// Index in POV-Ray's order of the term x^i y^j z^k of a degree-n poly.
int polyTermIndex(int n, int i, int j, int k);
/// p at object-space point q.
double evalPolySurface(const ShapeData& d, Vec3 q);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the normal ∇p (outward).
bool hitPolySurface(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point q is strictly inside (p < 0).
bool insidePolySurface(const Object& o, Vec3 q);
/// The object-space box of a quadric's closed inside {p ≤ 0}, which holds its surface too, when
/// the quadric is an ellipsoid or an elliptic cylinder along some axes (the variables that appear
/// in no term are free: those sides are infinite): false for other quadrics and higher orders.
bool quadricInsideBox(const ShapeData& d, Bounds& box);
/// The object-space box of {q in clip : p(q) ≤ 0} for a quadric without cross terms (xy, xz, yz):
/// p is then a sum of one quadratic per axis, so the points of the clip box inside the quadric
/// reach coordinate t on axis i exactly when fᵢ(t) + c plus the least of the other axes' terms
/// over the clip box is ≤ 0; the box holds, per axis, the hull of those t. An empty box when no
/// point of the clip box is inside; false for other quadrics and higher orders.
bool quadricBoxWithin(const ShapeData& d, const Bounds& clip, Bounds& box);
/// For a quadric that quadricInsideBox accepts (a convex inside): narrows [lo, hi] to the ray's
/// stretch within its closed inside (object-space ray); lo ≥ hi when the ray misses it.
void quadricInsideInterval(const ShapeData& d, const Ray& r, double& lo, double& hi);

}  // namespace rays

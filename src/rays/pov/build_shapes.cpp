#include "rays/pov/build_shapes.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "rays/error.h"
#include "rays/scene/shapes/polygon.h"
#include "rays/scene/shapes/poly.h"
#include "rays/scene/shapes/bicubic_patch.h"
#include "rays/scene/shapes/julia_fractal.h"
#include "rays/scene/shapes/lathe.h"
#include "rays/scene/shapes/ovus.h"
#include "rays/scene/shapes/parametric.h"
#include "rays/sdl/function_value.h"
#include "rays/scene/shapes/prism.h"
#include "rays/scene/shapes/sor.h"
#include "rays/scene/shapes/sphere_sweep.h"

namespace rays::pov {

namespace {

// A poly of degree n from its coefficients in POV-Ray's order (poly.h).
std::unique_ptr<ShapeData> polyData(int n, const std::vector<double>& coef) { return makePolySurface(n, coef); }

}  // namespace

void buildBicubicPatch(const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Mesh& mesh,
                       const std::string& where) {
    if (a.size() < 16)
        throw Error(where + ": error: bicubic_patch needs 16 points, found " + std::to_string(a.size()));
    BicubicPatch p;
    for (size_t i = 0; i < 16; ++i) p.points[i] = toVec3(*a[i]);
    for (const Entry* e : terms) {
        if (e->args.empty()) continue;
        const double x = toFloat(e->args[0]);
        switch (e->kw()) {
            case Kw::flatness: p.flatness = x; break;
            case Kw::u_steps: p.uSteps = int(std::clamp(x, 0.0, 10.0)); break;
            case Kw::v_steps: p.vSteps = int(std::clamp(x, 0.0, 10.0)); break;
            case Kw::uv_vectors:
                for (size_t i = 0; i < 4 && i < e->args.size(); ++i) {
                    const Vec3 uv = toVec3(e->args[i]);
                    p.uv[2 * i] = uv.x, p.uv[2 * i + 1] = uv.y;
                }
                break;
            default: break;  // type 0 and 1 draw the same surface; accuracy is type 0's search tolerance
        }
    }
    tessellateBicubicPatch(p, mesh);
}

ShapeBuild buildParametric(const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Mesh& mesh,
                           const std::string& where) {
    ParametricSpec spec;
    int functions = 0;
    for (const Entry* e : terms) {
        if (e->args.empty()) continue;
        if (e->kw() == Kw::function && e->args[0].type == sdl::VType::Function) {
            const sdl::FunctionValue& f = e->args[0].fn();
            if (functions >= 3) continue;
            if (f.kind != sdl::FunctionValue::Kind::Float || !f.table || f.index < 0) return ShapeBuild::NotAShape;
            for (const fn::HostFunction& h : f.table->program(f.index).hosts)
                if (sdl::isPatternStub(h)) return ShapeBuild::NotAShape;  // runs only while parsing
            spec.f[functions++] = f.table->shared(f.index);
        } else if (e->kw() == Kw::contained_by && e->args[0].type == sdl::VType::Item) {
            for (const Entry& c : e->args[0].item().entries) {
                if (c.args.empty() || c.args[0].type != sdl::VType::Item) continue;
                const Item& shape = c.args[0].item();
                const std::vector<const Value*> v = positionals(shape);
                if (v.size() < 2) continue;
                spec.sphere = shape.kind == Kw::sphere;
                if (spec.sphere) spec.centre = toVec3(*v[0]), spec.radius = toFloat(*v[1]);
                else spec.lo = vmin(toVec3(*v[0]), toVec3(*v[1])), spec.hi = vmax(toVec3(*v[0]), toVec3(*v[1]));
            }
        }
    }
    if (functions < 3 || a.size() < 2)
        throw Error(where + ": error: parametric needs three functions and the corners <u1, v1>, <u2, v2>");
    const Vec3 c1 = toVec3(*a[0]), c2 = toVec3(*a[1]);
    spec.u1 = c1.x, spec.v1 = c1.y, spec.u2 = c2.x, spec.v2 = c2.y;
    tessellateParametric(spec, mesh);
    return mesh.indices.empty() ? ShapeBuild::Empty : ShapeBuild::Made;
}

ShapeBuild buildShape(Kw kind, const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Object& o,
                      std::unique_ptr<ShapeData>& data, const std::string& where, ShapeMemo& memo) {
    auto need = [&](size_t n) {
        if (a.size() < n)
            throw Error(where + ": error: " + std::string(sdl::keywordName(kind)) + " needs " + std::to_string(n) +
                        " values, found " + std::to_string(a.size()));
    };
    auto numbers = [&](size_t from) {
        std::vector<double> v;
        for (size_t i = from; i < a.size(); ++i) v.push_back(toFloat(*a[i]));
        return v;
    };
    switch (kind) {
        case Kw::torus:
            need(2);
            o.type = ShapeType::Torus;
            o.r0 = toFloat(*a[0]);
            o.r1 = std::fabs(toFloat(*a[1]));
            return o.r1 > 0 ? ShapeBuild::Made : ShapeBuild::Empty;
        case Kw::superellipsoid: {
            need(1);
            const Vec3 en = toVec3(*a[0]);
            if (!(en.x > 0 && en.y > 0)) return ShapeBuild::Empty;  // the reference wants both above 0
            o.type = ShapeType::Superellipsoid;
            o.r0 = en.x;
            o.r1 = en.y;
            return ShapeBuild::Made;
        }
        case Kw::prism: {
            // The last spline or sweep keyword written counts.
            Kw spline = Kw::linear_spline, sweep = Kw::linear_sweep;
            for (const Entry* e : terms) {
                const Kw k = e->kw();
                if (k == Kw::conic_sweep || k == Kw::linear_sweep) sweep = k;
                else if (k == Kw::linear_spline || k == Kw::quadratic_spline || k == Kw::cubic_spline || k == Kw::bezier_spline)
                    spline = k;
            }
            need(3);
            double y0 = toFloat(*a[0]), y1 = toFloat(*a[1]);
            if (y0 > y1) std::swap(y0, y1);
            const size_t n = size_t(std::max(0.0, toFloat(*a[2])));
            std::vector<Vec3> pts;
            for (size_t i = 3; i < a.size() && pts.size() < n; ++i) {
                const Vec3 p = toVec3(*a[i]);
                pts.push_back(Vec3{p.x, 0, p.y});  // <u, v> → x, z
            }
            o.type = ShapeType::Prism;
            o.r0 = y0;
            o.r1 = y1;
            data = std::make_unique<ShapeData>();
            if (spline == Kw::linear_spline && sweep == Kw::linear_sweep)
                return y1 > y0 && makePrism(pts, y0, y1, *data) ? ShapeBuild::Made : ShapeBuild::Empty;
            const PrismSpline kind = spline == Kw::quadratic_spline ? PrismSpline::Quadratic
                                     : spline == Kw::cubic_spline   ? PrismSpline::Cubic
                                     : spline == Kw::bezier_spline  ? PrismSpline::Bezier
                                                                    : PrismSpline::Linear;
            return makeSplinePrism(pts, kind, sweep == Kw::conic_sweep, y0, y1, *data) ? ShapeBuild::Made
                                                                                         : ShapeBuild::Empty;
        }
        case Kw::lathe: case Kw::sor: {
            // lathe { [SPLINE] N, <x, y>... }, sor { N, <r, h>... }; the last spline keyword written counts.
            LatheSpline spline = LatheSpline::Linear;
            for (const Entry* e : terms) {
                const Kw k = e->kw();
                if (k == Kw::linear_spline) spline = LatheSpline::Linear;
                else if (k == Kw::quadratic_spline) spline = LatheSpline::Quadratic;
                else if (k == Kw::cubic_spline) spline = LatheSpline::Cubic;
                else if (k == Kw::bezier_spline) spline = LatheSpline::Bezier;
            }
            need(1);
            const size_t n = size_t(std::max(0.0, toFloat(*a[0])));
            std::vector<Vec3> pts;
            for (size_t i = 1; i < a.size() && pts.size() < n; ++i) {
                const Vec3 p = toVec3(*a[i]);
                pts.push_back(Vec3{p.x, p.y, 0});
            }
            data = std::make_unique<ShapeData>();
            if (kind == Kw::sor) {
                o.type = ShapeType::Sor;
                return makeSor(pts, *data) ? ShapeBuild::Made : ShapeBuild::Empty;
            }
            o.type = ShapeType::Lathe;
            return makeLathe(pts, spline, o, *data) ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::sphere_sweep: {
            // sphere_sweep { SPLINE N, centre, radius, ... }; the last spline keyword written counts.
            Kw spline = Kw::linear_spline;
            for (const Entry* e : terms)
                if (e->kw() == Kw::linear_spline || e->kw() == Kw::b_spline || e->kw() == Kw::cubic_spline) spline = e->kw();
            need(1);
            const size_t n = size_t(std::max(0.0, toFloat(*a[0])));
            std::vector<Vec3> centres;
            std::vector<double> radii;
            for (size_t i = 1; i + 1 < a.size() && centres.size() < n; i += 2) {
                centres.push_back(toVec3(*a[i]));
                radii.push_back(toFloat(*a[i + 1]));
            }
            o.type = ShapeType::SphereSweep;
            data = std::make_unique<ShapeData>();
            const bool made = spline == Kw::linear_spline ? makeSphereSweep(centres, radii, *data)
                                                          : makeSplineSphereSweep(centres, radii, spline == Kw::b_spline, *data);
            return made ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::julia_fractal: {
            // julia_fractal { <P> [quaternion | hypercomplex] [FUNCTION] [max_iteration N] [precision P]
            // [slice <N>, D] }; the last keyword of each kind written counts.
            need(1);
            JuliaParams q;
            for (int i = 0; i < 4; ++i) q.p[i] = a[0]->type == sdl::VType::Float ? a[0]->c[0] : i < a[0]->dim ? a[0]->c[size_t(i)] : 0.0;
            for (const Entry* e : terms) {
                const Kw k = e->kw();
                const double x = e->args.empty() ? 0.0 : toFloat(e->args[0]);
                if (k == Kw::quaternion || k == Kw::hypercomplex) q.hypercomplex = k == Kw::hypercomplex;
                else if (k == Kw::max_iteration) q.maxIteration = int(std::clamp(x, -1.0, 1e6));
                else if (k == Kw::precision) q.precision = x;
                else if (k == Kw::slice && e->args.size() >= 2) {
                    const Value& n = e->args[0];
                    for (int i = 0; i < 4; ++i) q.slice[i] = n.type == sdl::VType::Float ? n.c[0] : i < n.dim ? n.c[size_t(i)] : 0.0;
                    q.distance = toFloat(e->args[1]);
                    if (q.slice[3] == 0)
                        throw Error(where + ": error: the julia_fractal's slice needs a non-zero 4th (t) component");
                } else if (k == Kw::pwr && e->args.size() >= 2) {
                    q.function = JuliaFunction::Pwr;
                    q.pwr[0] = x;
                    q.pwr[1] = toFloat(e->args[1]);
                } else {
                    static constexpr Kw kFns[] = {Kw::sqr, Kw::cube, Kw::exp, Kw::reciprocal, Kw::sin, Kw::asin, Kw::sinh,
                                                  Kw::asinh, Kw::cos, Kw::acos, Kw::cosh, Kw::acosh, Kw::tan, Kw::atan,
                                                  Kw::tanh, Kw::atanh, Kw::ln};
                    for (size_t f = 0; f < std::size(kFns); ++f)
                        if (k == kFns[f]) q.function = JuliaFunction(int(f));
                }
            }
            if (!q.hypercomplex && q.function != JuliaFunction::Sqr && q.function != JuliaFunction::Cube)
                return ShapeBuild::NotAShape;  // POV-Ray's quaternions have sqr and cube only
            o.type = ShapeType::JuliaFractal;
            std::vector<double> key = {q.p[0], q.p[1], q.p[2], q.p[3], q.slice[0], q.slice[1], q.slice[2], q.slice[3],
                                       q.distance, double(q.maxIteration), q.precision, q.hypercomplex ? 1.0 : 0.0,
                                       double(int(q.function)), q.pwr[0], q.pwr[1]};
            // Keys with a NaN would not order: such a fractal is built on its own.
            const bool keyed = std::all_of(key.begin(), key.end(), [](double k) { return !std::isnan(k); });
            if (keyed) {
                if (const auto seen = memo.julia.find(key); seen != memo.julia.end()) {
                    if (!seen->second) return ShapeBuild::Empty;
                    o.data = seen->second;
                    return ShapeBuild::Made;
                }
            }
            data = std::make_unique<ShapeData>();
            const bool made = makeJuliaFractal(q, *data);
            if (keyed) memo.julia.emplace(std::move(key), made ? data.get() : nullptr);
            return made ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::ovus: {
            // ovus { Bottom_radius, Top_radius }
            need(2);
            o.type = ShapeType::Ovus;
            o.r0 = toFloat(*a[0]);
            o.r1 = toFloat(*a[1]);
            data = std::make_unique<ShapeData>();
            return makeOvus(o, *data) ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::disc: {
            need(3);
            o.type = ShapeType::Disc;
            o.p0 = toVec3(*a[0]);
            const Vec3 n = toVec3(*a[1]);
            if (length(n) == 0) throw Error(where + ": error: the disc's normal is zero");
            o.p1 = normalize(n);
            o.r0 = std::fabs(toFloat(*a[2]));
            o.r1 = a.size() > 3 ? std::fabs(toFloat(*a[3])) : 0.0;
            return o.r0 > o.r1 ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::polygon: {
            need(1);
            const size_t n = size_t(std::max(0.0, toFloat(*a[0])));
            std::vector<Vec3> pts;
            for (size_t i = 1; i < a.size() && pts.size() < n; ++i) pts.push_back(toVec3(*a[i]));
            o.type = ShapeType::Polygon;
            data = std::make_unique<ShapeData>();
            return makePolygon(pts, o, *data) ? ShapeBuild::Made : ShapeBuild::Empty;
        }
        case Kw::quadric: {
            // A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J (reference 3.4.5.3.6) in
            // poly order: x², xy, xz, x, y², yz, y, z², z, 1.
            need(4);
            const Vec3 abc = toVec3(*a[0]), def = toVec3(*a[1]), ghi = toVec3(*a[2]);
            const double j = toFloat(*a[3]);
            o.type = ShapeType::Poly;
            data = polyData(2, {abc.x, def.x, def.y, ghi.x, abc.y, def.z, ghi.y, abc.z, ghi.z, j});
            return ShapeBuild::Made;
        }
        case Kw::cubic: case Kw::quartic: {
            const int n = kind == Kw::cubic ? 3 : 4;
            need(size_t(polyTermCount(n)));
            o.type = ShapeType::Poly;
            data = polyData(n, numbers(0));
            return ShapeBuild::Made;
        }
        case Kw::poly: {
            need(1);
            const int n = int(toFloat(*a[0]));
            if (n < 2 || n > 35) throw Error(where + ": error: a poly's order must be from 2 to 35");
            need(1 + size_t(polyTermCount(n)));
            o.type = ShapeType::Poly;
            data = polyData(n, numbers(1));
            return ShapeBuild::Made;
        }
        case Kw::polynomial: {
            need(1);
            const int n = int(toFloat(*a[0]));
            if (n < 2 || n > 35) throw Error(where + ": error: a polynomial's order must be from 2 to 35");
            std::vector<double> coef(size_t(polyTermCount(n)), 0.0);
            for (const Entry* e : terms) {
                if (e->args.size() < 4) continue;
                const int i = int(toFloat(e->args[0])), j = int(toFloat(e->args[1])), k = int(toFloat(e->args[2]));
                if (i < 0 || j < 0 || k < 0 || i + j + k > n)
                    throw Error(where + ": error: xyz(" + std::to_string(i) + "," + std::to_string(j) + "," +
                                std::to_string(k) + ") is beyond the polynomial's order");
                coef[size_t(polyTermIndex(n, i, j, k))] = toFloat(e->args[3]);  // the last one written wins
            }
            o.type = ShapeType::Poly;
            data = polyData(n, coef);
            return ShapeBuild::Made;
        }
        default: return ShapeBuild::NotAShape;
    }
}

}  // namespace rays::pov

// The patterns' formulas: the manual's where it gives one (boxed, leopard, spherical, ...), and
// otherwise settled by black-box measurements of POV-Ray 3.7.0.10 (`function { pigment { P } }`
// evaluated with #debug at chosen points): radial's angle origin and direction, gradient's
// wrapping, brick's courses and mortar, hexagon's orientation and colour order. Noise patterns
// follow the manual's descriptions on rays' noise and are not point-for-point POV-Ray's.
#include "rays/pattern/pattern.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

#include "rays/fn/compile.h"
#include "rays/fn/machine.h"
#include "rays/pattern/cell_hash.h"
#include "rays/pattern/magnet.h"
#include "rays/pattern/ripples.h"
#include "rays/pattern/tiles.h"
#include "rays/pattern/tiling.h"

namespace rays::pattern {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

double frac(double v) { return v - std::floor(v); }

// a mod b in [0, b).
double wrap(double a, double b) { return a - b * std::floor(a / b); }

// checker: unit cubes alternating (x, y and z floors summed), colour 1 where the sum is even.
// POV-Ray moves the cube faces by a tiny amount (measured: −1e−10 is in the cube above 0, −2e−10
// is not), so that faces lying in a plane such as y = 0 take one colour despite rounding.
int checkerIndex(Vec3 p) {
    constexpr double kShift = 1.5e-10;
    const double s = std::floor(p.x + kShift) + std::floor(p.y + kShift) + std::floor(p.z + kShift);
    return std::fmod(std::fabs(s), 2.0) == 1.0 ? 1 : 0;
}

// hexagon: hexagons of side 1 in the x-z plane, corners on the x-axis; colour 1 round the
// origin, colour 2 next in +z, colour 3 to the sides. Cell centres are a·(1.5, √3/2) + b·(0, √3)
// and the colour is (b − a) mod 3; the nearest centre is one of four candidates.
int hexagonIndex(Vec3 p) {
    constexpr double kS3 = 1.7320508075688772;
    const double a0 = std::floor(p.x / 1.5);
    double best = 1e300;
    int index = 0;
    for (int da = 0; da < 2; ++da) {
        const double a = a0 + da;
        const double b0 = std::floor((p.z - a * kS3 / 2) / kS3);
        for (int db = 0; db < 2; ++db) {
            const double b = b0 + db;
            const double cx = 1.5 * a, cz = a * kS3 / 2 + b * kS3;
            const double d = (p.x - cx) * (p.x - cx) + (p.z - cz) * (p.z - cz);
            if (d < best) {
                best = d;
                index = int(wrap(b - a, 3.0));
            }
        }
    }
    return index;
}

// brick: courses brick_size.y high; odd courses shift the bricks half a length along x, even
// ones half a width along z; mortar fills the last `mortar` of each brick's length, height and
// width. Index 0 is the mortar, 1 the brick.
int brickIndex(Vec3 p, Vec3 size, double mortar) {
    // POV-Ray moves the point by a hair as checker does (measured with its pattern function at
    // the mortar's faces: 1e−10 below x = 7.5 is mortar, 1.2e−10 below is brick; the same in y and
    // z), so that faces lying on a mortar plane, as the sides of a box, take one colour.
    constexpr double kShift = 1.1e-10;
    p = {p.x + kShift, p.y + kShift, p.z + kShift};
    const double course = std::floor(p.y / size.y);
    const bool odd = std::fmod(std::fabs(course), 2.0) == 1.0;
    const double x = wrap(p.x + (odd ? size.x / 2 : 0), size.x);
    const double y = p.y - course * size.y;
    const double z = wrap(p.z + (odd ? 0 : size.z / 2), size.z);
    return (x >= size.x - mortar || y >= size.y - mortar || z >= size.z - mortar) ? 0 : 1;
}

// gradient: the position along the direction, wrapped by fmod when above 1; negative positions
// are left to the wave's wrapping (measured: frequency 2 at x = −0.25 gives 0.5, at 0.75 0.49999).
double gradientValue(Vec3 p, Vec3 dir) {
    const double v = dot(p, dir);
    return v > 1 ? std::fmod(v, 1.0) : v;
}

// 1/f noise sums of the clamped noise (measured with POV-Ray 3.7's pattern functions against its
// bozo at 4,000 scaled points, to 1e-7): granite Σ_{i<6} |clampedNoise(4·2^i·p) − ½| / 2^i,
// wrinkles ½·Σ_{i<10} clampedNoise(2^i·p) / 2^i.
double granite(Vec3 p) {
    double sum = 0, amp = 1;
    p = p * 4.0;
    for (int i = 0; i < 6; ++i, amp *= 0.5, p = p * 2.0) sum += amp * std::fabs(clampedNoise(p) - 0.5);
    return sum;
}
double wrinkles(Vec3 p) {
    double sum = 0, amp = 0.5;
    for (int i = 0; i < 10; ++i, amp *= 0.5, p = p * 2.0) sum += amp * clampedNoise(p);
    return sum;
}

// agate (measured with POV-Ray 3.7's pattern functions: agate_turb 0 gives
// (½ + ½·sin(2π·1.1·z))^0.77 to 5e-6 along z; a small agate_turb t shifts the sine's phase by
// 1.3·t·T, T the marble turbulence with the default octaves, omega and lambda, to 1e-4).
double agate(Vec3 p, double agateTurb) {
    const double phase = 1.1 * p.z + 1.3 * agateTurb * turbulenceScalar(p, 6, 0.5, 2);
    return std::pow(0.5 + 0.5 * std::sin(kTwoPi * phase), 0.77);
}

// wood with turbulence (measured with POV-Ray 3.7's pattern functions at 300 random points, to
// 1e-4, against the displacement gradient x/y patterns show for the same turbulence): x moves by
// sin(2π·amount.x·(x + D.x)) and y by sin(2π·amount.y·(y + D.y)), D the turbulence vector; z and
// amount.z play no part.
double turbulentWood(Vec3 p, const Turbulence& t) {
    const Vec3 d = turbulenceVector(p, t);
    const double x = p.x + std::sin(kTwoPi * t.amount.x * (p.x + d.x));
    const double y = p.y + std::sin(kTwoPi * t.amount.y * (p.y + d.y));
    return std::sqrt(x * x + y * y);
}

// cells (POV-Ray 3.7 reference, "Cells"): one value per unit cube, uniform in [0, 1) (measured with
// POV-Ray's pattern functions: constant within a cube, mean 0.50, spread 0.29 over 400 cubes). The
// values come from a hash of the cube's integer coordinates (splitmix64's finaliser), not POV-Ray's
// table: the look is alike, the values are not point for point.
double cells(Vec3 p) {
    return cellUniform(int64_t(std::floor(p.x)), int64_t(std::floor(p.y)), int64_t(std::floor(p.z)));
}

// mandel and julia (POV-Ray 3.7 reference, "Mandelbrot", "Julia"): z becomes z^exponent + c until
// |z|² > 4 or the iterations run out; mandel starts at z = c = x + iy, julia at z = x + iy with
// its fixed c (both measured with povray 3.7's pattern functions). The value comes from the
// exterior type (escaped: 1 = iterations before escaping / ITERATIONS, measured to count from
// the first new z) or the interior type (0 = 1, 1 = the smallest |z| of the orbit), 2–6 from the
// last z, 7 and 8 the count modulo the factor; other types are multiplied by their factor.
double escapeTime(const PatternParams& m, double zr, double zi, double cr, double ci) {
    double minAbs2 = zr * zr + zi * zi;
    int n = 0;
    for (; n < m.iterations; ++n) {
        double r = zr, i = zi;  // z^exponent by repeated multiplication
        for (int e = 1; e < m.exponent; ++e) {
            const double t = r * zr - i * zi;
            i = r * zi + i * zr;
            r = t;
        }
        zr = r + cr;
        zi = i + ci;
        const double a2 = zr * zr + zi * zi;
        if (a2 > 4) break;
        minAbs2 = std::min(minAbs2, a2);
    }
    return escapeColouring(m, n < m.iterations, n, zr, zi, minAbs2);
}

}  // namespace

double escapeColouring(const PatternParams& m, bool escaped, int n, double zr, double zi, double minAbs2) {
    const int type = escaped ? m.exterior : m.interior;
    const double f = escaped ? m.exteriorFactor : m.interiorFactor;
    switch (type) {
        case 0: return f;
        case 1: return escaped ? double(n) / m.iterations : std::sqrt(minAbs2) * f;
        case 2: return zr * f;
        case 3: return zi * f;
        case 4: return zr * zr * f;
        case 5: return zi * zi * f;
        // Exterior 6 is |z|·factor; interior 6 measured as zr² + factor·zi² (mandel, julia and
        // magnet alike, factors 0.25 to 2, at scattered interior points).
        case 6: return escaped ? std::sqrt(zr * zr + zi * zi) * f : zr * zr + f * zi * zi;
        case 7: return f != 0 ? std::fmod(double(n), f) / f : 0;
        case 8: return f != 0 ? std::fmod(double(n), f + 1) / f : 0;
        default: return 0;
    }
}

namespace {

// spiral1 N (POV-Ray 3.7 reference, "Spiral1"; the formula measured with povray 3.7's pattern
// functions): r + z + N·a, a the angle about z from −y towards +x in turns, in [0, 1). The wave
// wraps it (measured: 2.25 gives 0.24998; with frequency 0.01 the value before any wrap shows).
double spiral1(double arms, Vec3 p) {
    const double turns = std::atan2(p.x, -p.y) / kTwoPi;  // (−0.5, 0.5]
    return std::sqrt(p.x * p.x + p.y * p.y) + p.z + arms * (turns < 0 ? turns + 1 : turns);
}

// spiral2 N (POV-Ray 3.7 reference, "Spiral2"; the formula measured with povray 3.7's pattern
// functions at scattered points, N = −2 … 3): T(r + z + N·a) + T(r), T the triangle
// 1 − |2·frac(u) − 1|, r and a as for spiral1; a value in [0, 2] that the wave wraps.
double spiral2(double arms, Vec3 p) {
    const auto tri = [](double u) { return 1 - std::fabs(2 * frac(u) - 1); };
    const double turns = std::atan2(p.x, -p.y) / kTwoPi;
    const double r = std::sqrt(p.x * p.x + p.y * p.y);
    return tri(r + p.z + arms * (turns < 0 ? turns + 1 : turns)) + tri(r);
}

// A function pattern: the user function at (x, y, z) (further parameters 0), on this thread's
// scratch (grown once per thread and program size, never per evaluation after that). A function
// may call a pattern function whose pattern is a function again: each nesting level has its own
// scratch (a deque: the outer levels' scratches stay where they are while it grows).
double functionValue(const fn::Program& f, Vec3 p) {
    thread_local std::deque<fn::Scratch> scratches;
    thread_local size_t depth = 0;
    if (depth == scratches.size()) scratches.emplace_back();
    fn::Scratch& scratch = scratches[depth];
    if (!scratch.fitsScalar(f)) scratch.fit(f);
    struct Level {
        size_t& d;
        explicit Level(size_t& depth) : d(depth) { ++d; }
        ~Level() { --d; }
    } level(depth);
    double args[fn::kMaxParams] = {p.x, p.y, p.z};
    return fn::eval(f, args, scratch);
}

}  // namespace

int blockIndex(PatternKind kind, const PatternParams& params, Vec3 p) {
    if (params.turbulence.on()) p = turbulent(p, params.turbulence);
    switch (kind) {
        case PatternKind::Checker: return checkerIndex(p);
        case PatternKind::Hexagon: return hexagonIndex(p);
        case PatternKind::Brick: return brickIndex(p, params.brickSize, params.mortar);
        case PatternKind::Square: return squareIndex(p);
        case PatternKind::Triangular: return triangularIndex(p);
        case PatternKind::Cubic: return cubicIndex(p);
        case PatternKind::Object: return params.object ? params.object->index(p) : 0;
        default: return 0;
    }
}

double patternValue(PatternKind kind, const PatternParams& params, Vec3 p, Vec3 N, Vec3 D) {
    const Turbulence& t = params.turbulence;
    // marble, agate and wood use turbulence in their own way instead of moving the point (the
    // manual: old-style turbulence "is handled slightly differently" for them; measured).
    if (kind == PatternKind::Marble) {
        const double turb = t.on() ? t.amount.x * turbulenceScalar(p, t.octaves, t.omega, t.lambda) : 0;
        return p.x + turb;
    }
    if (kind == PatternKind::Agate) return agate(p, params.agateTurb);
    if (kind == PatternKind::Wood && t.on()) return turbulentWood(p, t);
    if (t.on()) p = turbulent(p, t);
    switch (kind) {
        case PatternKind::Gradient: return gradientValue(p, params.vector);
        // The angle about y from +x towards −z, in [0.5, 1.5] before the wave wraps it (measured).
        case PatternKind::Radial: {
            // Measured with POV-Ray 3.7 round the circle: the value runs from 0.25 (towards −z,
            // turning towards −x) to 1.25, so that only the quarter from +x to −z (values above 1)
            // meets the wave's wrap by 1.00001.
            const double v = 1 - std::atan2(p.z, p.x) / kTwoPi;
            return v > 1.25 ? v - 1 : v;
        }
        case PatternKind::Onion: return frac(std::sqrt(dot(p, p)));
        case PatternKind::Spherical: return std::max(0.0, 1 - std::sqrt(dot(p, p)));
        case PatternKind::Cylindrical: return std::max(0.0, 1 - std::sqrt(p.x * p.x + p.z * p.z));
        case PatternKind::Planar: return std::max(0.0, 1 - std::fabs(p.y));
        case PatternKind::Boxed:
            return 1 - std::min(1.0, std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
        case PatternKind::Leopard: {
            const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3;
            return s * s;
        }
        case PatternKind::Bozo: return noiseOfGenerator(p, params.noiseGenerator);
        case PatternKind::Granite: return granite(p);
        case PatternKind::Wood: return std::sqrt(p.x * p.x + p.y * p.y);
        case PatternKind::Wrinkles: return wrinkles(p);
        case PatternKind::Crackle: return crackleValue(p, params.crackle);
        case PatternKind::Ripples: return ripplesValue(p, waveCount(params.waves));
        case PatternKind::Waves: return wavesValue(p, waveCount(params.waves));
        case PatternKind::Dents: return dentsValue(p);
        case PatternKind::Cells: return cells(p);
        case PatternKind::Mandel: return escapeTime(params, p.x, p.y, p.x, p.y);
        case PatternKind::Julia: return escapeTime(params, p.x, p.y, params.juliaR, params.juliaI);
        case PatternKind::Magnet: return magnetValue(params, p.x, p.y);
        case PatternKind::Spiral1: return spiral1(params.arms, p);
        case PatternKind::Spiral2: return spiral2(params.arms, p);
        case PatternKind::Quilted: return quiltedValue(params.quilt, p);
        case PatternKind::Slope: return slopeValue(params.slope, p, N);
        case PatternKind::Aoi: {
            // The angle between the normal facing the viewer (tilted by the surface's normal) and
            // the ray, over π: 1 seen head-on, 0.5 at grazing (measured with POV-Ray 3.7 on an
            // orthographic sphere and on tilted planes seen from both sides: 1 − θ/π for θ the
            // angle to the viewer, within 1e-5; as a pattern function, off surfaces, 0).
            const double nn = dot(N, N), dd = dot(D, D);
            if (nn == 0 || dd == 0) return 0;
            return std::acos(std::clamp(dot(N, D) / std::sqrt(nn * dd), -1.0, 1.0)) / std::numbers::pi;
        }
        case PatternKind::Tiling: return tilingValue(params.tiling, p);
        case PatternKind::Pavement: return pavementValue(params.pavement, p);
        case PatternKind::DensityFile: return params.grid ? params.grid->at(p, params.interpolate) : 0;
        case PatternKind::Function: {
            // Wrapped above 1 like gradient (measured: 1.2 gives 0.2 under triangle_wave 0.4).
            const double v = params.function ? functionValue(*params.function, p) : 0;
            return v > 1 ? std::fmod(v, 1.0) : v;
        }
        default: return 0;
    }
}

}  // namespace rays::pattern

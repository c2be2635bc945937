// Normal perturbation as the manual describes it ("Normals, Accuracy"): a pattern not made for
// normals is sampled at four points of a pyramid (a regular tetrahedron) `accuracy` away from the
// point, giving the gradient of its height (value → wave → slope_map); the normal tilts against
// that gradient. Measured with POV-Ray 3.7 (tests/pov_normal_test.cpp): the tilt is
// kPovBumpScale·amount·gradient, the gradient taken in the pattern's own space (a uniformly scaled
// normal keeps its depth, a scale along one axis steepens it), the full gradient subtracted from
// the unit normal there (a gradient along the normal changes nothing), the wave and slopes included.
// bumps, dents, ripples, waves and wrinkles have their own perturbation in POV-Ray, measured: a
// vector noise added to the normal for bumps, dents and wrinkles (noiseTilt, on Rays' noise, not
// POV-Ray's), the waves' own tilt for ripples and waves (analytic, the tilt independent of the
// frequency). quilted has POV-Ray's own tilt, measured (pattern/quilted.h).
#include "rays/pattern/normal.h"

#include "rays/pattern/bump_map.h"
#include "rays/pattern/ripples.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::pattern {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The tetrahedron's unit directions: one vertex up +y, one in the xy plane towards +x, two at ±z
// (each 1/3 below the centre). The orientation is POV-Ray's, measured: across a step in x its
// normal shows two bands, 0.943·δ wide where only the +x sample has crossed and then 0.471·δ
// where the +y one has too, and across a step in y one band 1.333·δ wide
// (tests/pov_normal_test.cpp). Σ dᵢ dᵢᵀ = 4/3 I, so the gradient of a linear height h is
// 3/(4δ) Σ h(p + δ dᵢ) dᵢ, whatever the orientation.
constexpr double kA = 0.94280904158206337;  // √8 / 3
constexpr double kB = 0.47140452079103168;  // √2 / 3
constexpr double kC = 0.81649658092772603;  // √6 / 3
constexpr Vec3 kPyramid[4] = {{kA, -1.0 / 3, 0}, {-kB, -1.0 / 3, kC}, {-kB, -1.0 / 3, -kC}, {0, 1, 0}};

Vec3 patternPoint(const PigmentTable& patterns, const PigmentNode& pn, Vec3 p) {
    if (pn.warpCount > 0) {
        for (int i = 0; i < pn.warpCount; ++i) p = applyWarp(patterns.warps[size_t(pn.warpBegin + i)], p);
    } else if (pn.transformed) {
        p = pn.toPattern.point(p);
    }
    return p;
}

// The pattern's value at q (pattern space): a block pattern's index, else the value after the wave.
double rawValue(const PigmentTable& patterns, const PigmentNode& pn, Vec3 q) {
    if (isBlockPattern(pn.kind)) return blockIndex(pn.kind, pn.params, q);
    return applyWave(pn.wave, patterns.rawValue(pn, q));
}

// The slope map's cubic (Hermite) curve through the entries' heights with their slopes, the slopes
// per unit of the segment (measured: the manual's triangle map [0 <0,1>] [0.5 <1,1>] ... gives a
// straight ramp, and [0 <0,0>] [1 <1,0>] a smoothstep).
double slopeHeight(const SlopeEntry* s, int count, double v) {
    if (count == 0) return v;
    if (v <= s[0].value) return s[0].height;
    for (int i = 0; i + 1 < count; ++i) {
        const SlopeEntry &a = s[i], &b = s[i + 1];
        if (v > b.value) continue;
        const double d = b.value - a.value;
        if (d <= 0) return b.height;
        const double t = (v - a.value) / d, t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * a.height + (t3 - 2 * t2 + t) * a.slope + (-2 * t3 + 3 * t2) * b.height +
               (t3 - t2) * b.slope;
    }
    return s[count - 1].height;
}

// ripples and waves: not the gradient of their pigments but a tilt along each source's direction,
// (1/n)·Σᵢ sin(2π·fᵢ·|q − cᵢ|)/fᵢ · (q − cᵢ)/|q − cᵢ| over the first n sources, added to the normal
// facing the viewer times the bump size (fᵢ = 1 for ripples). Measured with POV-Ray 3.7: a plane
// facing the camera lit along the view (16-bit, linear) with number_of_waves 1 and 10 and bump sizes
// 1 and 0.5; the fit leaves a residual of 5·10⁻⁶. `frequency` spaces the rings only (POV-Ray's tilt
// does not grow with it, so that huge scales with huge frequencies, as in var_refl.pov, stay calm).
Vec3 wavesTilt(Vec3 q, const Wave& w, bool ripples, int n) {
    Vec3 t;
    for (int i = 0; i < n; ++i) {
        const Vec3 r = q - kWaveCentres[i];
        const double d = length(r);
        if (d == 0) continue;
        const double f = ripples ? 1.0 : kWaveFrequencies[i];
        t += (std::sin(kTwoPi * (d * w.frequency * f + w.phase)) / (f * d)) * r;
    }
    return t / double(n);
}

// bumps, dents and wrinkles: not gradients of heights but a vector noise added to the normal
// (its three components the noise at three far-apart places, each in about [−1, 1]) at q, in
// pattern space, times the bump size: bumps the vector noise itself; dents the vector noise times
// 2.7·noise(q)⁵ (mostly flat, dented where the noise is high: POV-Ray's tilt correlates 0.89 with
// its bozo cubed at the same point, and its mean at each level of bozo, 0.03 at 0.5 to 0.30 at 0.8,
// fits 2.7·n⁵ times the vector noise's mean length); wrinkles ten octaves of its components'
// absolute values, each octave twice the frequency and half the weight, so that the normal leans
// towards +x, +y and +z. Measured with POV-Ray 3.7 on a plane facing the camera, lit along the
// view and from 45° to each side (16-bit linear, the normal recovered per pixel): the tilt's
// spread (bumps 1: 0.327 ± 0.160), its correlation over distance (0.48 at half a unit: the value
// of a noise, where a gradient's falls below zero), dents' small mean tilt with a long tail
// (0.055 ± 0.065) and wrinkles' lean (at amount 1 the normal facing −z turns to (0.51, 0.51, −0.63)).
// docs/povray-patterns.md has Rays' figures beside these.
Vec3 noiseTilt(NormalKind kind, Vec3 q) {
    switch (kind) {
        case NormalKind::Bumps: return vectorNoise(q);
        case NormalKind::Dents: {
            const double n = noise(q), n2 = n * n;
            return vectorNoise(q) * (2.7 * n2 * n2 * n);
        }
        case NormalKind::Wrinkles: {
            Vec3 sum;
            double scale = 1;
            for (int i = 0; i < 10; ++i, scale *= 2) {
                const Vec3 v = vectorNoise(q * scale);
                sum += Vec3{std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)} / scale;
            }
            return sum;
        }
        default: return {};
    }
}

bool isSpecial(NormalKind k) { return k >= NormalKind::Bumps && k != NormalKind::BumpMap; }

}  // namespace

double NormalTable::height(const PigmentTable& patterns, const NormalNode& node, Vec3 p) const {
    const PigmentNode& pn = patterns.nodes[size_t(node.pattern)];
    const Vec3 q = patternPoint(patterns, pn, p);
    return slopeHeight(slopes.data() + node.slopeBegin, node.slopeCount, rawValue(patterns, pn, q));
}

Vec3 NormalTable::perturb(const PigmentTable& patterns, int n, Vec3 p, Vec3 normal, double stretch) const {
    const NormalNode& node = nodes[size_t(n)];
    if (node.pattern < 0) return normal;
    Vec3 np = node.fromPattern.transposedVector(normal);  // the normal in pattern space
    const double len = length(np);
    if (len == 0) return normal;
    np = np / len;
    Vec3 out;
    if (node.kind == NormalKind::BumpMap) {
        const PigmentNode& pn = patterns.nodes[size_t(node.pattern)];
        out = bumpMapNormal(patterns.images[size_t(pn.image)], patternPoint(patterns, pn, p), np, node.amount);
    } else if (node.kind == NormalKind::Pattern || isSpecial(node.kind)) {
        // The gradient in pattern space from four samples `accuracy` apart in pattern space.
        Vec3 g;
        const double delta = node.accuracy > 0 ? node.accuracy : 0.02;
        if (isSpecial(node.kind)) {
            // Sampled about the turbulent point in pattern space: the turbulence moves the bumps
            // but does not roughen them (measured: POV-Ray's bumps tilt as much with turbulence 0.5).
            const PigmentNode& pn = patterns.nodes[size_t(node.pattern)];
            Vec3 q = patternPoint(patterns, pn, p);
            if (pn.params.turbulence.on()) q = turbulent(q, pn.params.turbulence);
            if (node.kind == NormalKind::Quilted) {
                // Not a gradient: POV-Ray tilts the normal along the point's offset from its cube's
                // centre (measured, pattern/quilted.h).
                g = quiltedTilt(pn.params.quilt, q) * (-1 / kPovBumpScale);
            } else if (node.kind == NormalKind::Ripples || node.kind == NormalKind::Waves) {
                const bool ripples = node.kind == NormalKind::Ripples;
                g = wavesTilt(q, pn.wave, ripples, waveCount(pn.params.waves)) * (-1 / kPovBumpScale);
            } else {  // bumps, dents, wrinkles
                g = noiseTilt(node.kind, q) * (-1 / kPovBumpScale);
            }
        } else {
            for (const Vec3& d : kPyramid) g += height(patterns, node, p + node.fromPattern.vector(delta * d)) * d;
            g = g * (3 / (4 * delta));
        }
        // Mapped back, np − k·g tilts as n − k·|A⁻ᵀn|·Aᵀg would in the enclosing space (A: that
        // space → pattern space, |A⁻ᵀn| the normal's stretch), so a uniform scale keeps the
        // depth. no_bump_scale takes the world gradient's tilt, n − k·Aᵀg over every space down
        // from the world: the stretches divided out (measured with POV-Ray 3.7 on a lit plane,
        // gradient x 0.5: scale 0.25 tilts 4 times as much, scale 2 half as much, <0.5, 1, 1>
        // twice as much with or without it, and an object's scale counts as the normal's own).
        const double depth = node.noBumpScale ? 1 / (stretch * len) : 1.0;
        out = np - (kPovBumpScale * node.amount * depth) * g;
    } else {
        const PigmentNode& pn = patterns.nodes[size_t(node.pattern)];
        const Vec3 q = patternPoint(patterns, pn, p);
        const NormalEntry* map = entries.data() + node.mapBegin;
        auto entry = [&](int i) { return map[i].node >= 0 ? perturb(patterns, map[i].node, q, np, stretch * len) : np; };
        if (node.mapCount == 0) {
            out = np;
        } else if (node.kind == NormalKind::Block) {
            const int i = blockIndex(pn.kind, pn.params, q);
            out = entry(std::min(i, node.mapCount - 1));
        } else if (node.kind == NormalKind::Average) {
            for (int i = 0; i < node.mapCount; ++i) out += map[i].value * entry(i);
        } else {
            // The map's two entries about the value, blended (the first wins at a shared value).
            const double v = rawValue(patterns, pn, q);
            int hi = 0;
            while (hi < node.mapCount && map[hi].value <= v) ++hi;
            if (hi == 0) out = entry(0);
            else if (hi == node.mapCount) out = entry(node.mapCount - 1);
            else {
                const int lo = hi - 1;
                const double span = map[hi].value - map[lo].value;
                const double t = span > 0 ? (v - map[lo].value) / span : 0;
                out = t <= 0 ? entry(lo) : (1 - t) * entry(lo) + t * entry(hi);
            }
        }
    }
    const Vec3 back = node.toPattern.transposedVector(out);
    const double bl = length(back);
    return bl > 0 ? back / bl : normal;
}

Vec3 NormalTable::atRoot(const PigmentTable& patterns, int r, Vec3 P, Vec3 N) const {
    const NormalRoot& root = roots[size_t(r)];
    Vec3 n = root.textureToWorld.transposedVector(N);
    const double len = length(n);
    if (len == 0) return N;
    n = perturb(patterns, root.node, root.worldToTexture.point(P), n / len, len);
    const Vec3 w = root.worldToTexture.transposedVector(n);
    const double wl = length(w);
    return wl > 0 ? w / wl : N;
}

}  // namespace rays::pattern
